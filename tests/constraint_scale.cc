// A constraint whose scale is far below 1 is held: the sphere octant's
// design loop (inputs/sphere_design.prm) with its constraint, the mean
// (u . e_y)^2 at half load, tightened to Tolerance = 3e-5 mm^2, which the
// initial sphere violates by 76 % (Q = 5.29e-5). MMA sees each constraint
// as f / Tolerance (ShapeOptimizer::mma_step), so its elastic variable
// costs c = 1000 per tolerance exceeded. Passed unscaled, as before, the
// violation of 2.3e-5 cost 0.02 and MMA crept at a thousandth of the move
// limit: f_1 / Tolerance was still 0.64 after 12 iterations and max g had
// fallen by 2 %. Scaled, the design is feasible within a few iterations
// and stays on the constraint while the objective falls.

#include <softopt/app/settings.h>
#include <softopt/io/output_directory.h>
#include <softopt/optimization/shape_optimizer.h>

#include "tests.h"

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const double tolerance = 3e-5;
  {
    std::ifstream      in(SOURCE_DIR "/inputs/sphere_design.prm");
    std::ostringstream text;
    text << in.rdbuf();
    std::string prm = text.str();
    const auto  replace = [&](const std::string &from, const std::string &to) {
      const auto at = prm.find(from);
      AssertThrow(at != std::string::npos, ExcMessage("no \"" + from + "\""));
      prm.replace(at, from.size(), to);
    };
    replace("../../meshes/", SOURCE_DIR "/../meshes/");
    replace("set Tolerance = 1e-4", "set Tolerance = 3e-5");
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream("case.prm") << prm;
    MPI_Barrier(MPI_COMM_WORLD);
  }
  softopt::Settings settings("case.prm");
  settings.output_directory                   = "results";
  settings.output.print_timings               = false;
  settings.optimization.maximum_iterations    = 12;
  settings.optimization.move_limit            = 0.1;
  settings.optimization.checkpoint_interval   = 0;
  settings.optimization.output_interval       = 0;
  {
    softopt::DesignProblem          problem(settings, MPI_COMM_WORLD, "");
    const softopt::OutputDirectory  out(settings.output_directory, MPI_COMM_WORLD);
    softopt::ShapeOptimizer         optimizer(settings.optimization, settings.output, problem, out);
    std::cout.setstate(std::ios::failbit); // the per-iteration lines
    optimizer.run(false);
    std::cout.clear();
  }
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;

  const auto rows = read_csv("results/history.csv");
  const auto column = [&](const std::string &name) {
    const auto at = std::find(rows[0].begin(), rows[0].end(), name);
    AssertThrow(at != rows[0].end(), ExcMessage("no column " + name));
    return at - rows[0].begin();
  };
  const auto g_1 = column("g_1"), g_2 = column("g_2"), f_1 = column("f_1");
  const auto value = [&](const unsigned int r, const long c) { return std::stod(rows[r][c]); };
  const auto max_g = [&](const unsigned int r) { return std::max(value(r, g_1), value(r, g_2)); };
  const unsigned int last = rows.size() - 1;

  deallog << "iterations: " << last << std::endl;
  deallog << "f_1 / Tolerance at iteration 0: " << value(1, f_1) / tolerance
          << " (the initial design violates it)" << std::endl;
  unsigned int feasible = 0;
  for (unsigned int r = 1; r <= last && feasible == 0; ++r)
    if (value(r, f_1) / tolerance < 1e-3)
      feasible = r - 1;
  deallog << "first iteration with f_1 / Tolerance < 1e-3: " << feasible
          << (feasible > 0 && feasible <= 6 ? " (<= 6)" : " (NOT <= 6)") << std::endl;
  double worst = 0;
  for (unsigned int r = feasible + 1; feasible > 0 && r <= last; ++r)
    worst = std::max(worst, value(r, f_1) / tolerance);
  deallog << "largest f_1 / Tolerance after it: " << below(worst, 1e-3) << std::endl;
  const double decrease = 1 - max_g(last) / max_g(1);
  deallog << "max g fell by " << std::lround(100 * decrease) << " %"
          << (decrease > 0.1 ? " (> 10 %)" : " (NOT > 10 %)") << std::endl;
}
