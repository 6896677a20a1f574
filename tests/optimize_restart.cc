// Checkpoint and restart: a design loop on the sphere octant
// (inputs/sphere_design.prm, 8 iterations, a mesh update every 3) run
// without interruption, and the same loop stopped after 7 iterations and
// restarted from its last checkpoint (at iteration 6, written before the
// mesh update of that iteration, which the restart makes again), write the
// same history.csv, Newton iterations included (the warm start's secant is
// in the checkpoint). So does the loop stopped after 5 and restarted at 4,
// an iteration the uninterrupted run does not check from rest: the restart
// does not check it either (its from_rest columns stay empty). The loop
// must improve the objective. The same with a new mesh at every mesh
// update ("Remesh below quality" = 1): the restart reads the mesh of
// iteration 6 that the checkpoint names.

#include <softopt/io/output_directory.h>
#include <softopt/app/settings.h>
#include <softopt/optimization/checkpoint.h>
#include <softopt/optimization/shape_optimizer.h>

#include "tests.h"

#include <limits>

#include <fstream>

using namespace softopt_tests;

namespace
{
  /** Runs the loop with at most @p iterations into @p directory. */
  void
  optimize(const std::string &directory,
           const unsigned int iterations,
           const bool         restart,
           const double       remesh_quality)
  {
    softopt::Settings settings(SOURCE_DIR "/inputs/sphere_design.prm");
    settings.optimization.remesh_quality      = remesh_quality;
    settings.output_directory                 = directory;
    settings.output.print_timings             = false;
    settings.optimization.maximum_iterations  = iterations;
    settings.optimization.mesh_update_interval = 3;
    settings.optimization.checkpoint_interval  = 2;
    settings.optimization.output_interval      = 0;
    settings.optimization.move_limit           = 0.1;
    // As softopt optimize --restart: on the checkpoint's mesh.
    softopt::DesignProblem problem(settings,
                                   MPI_COMM_WORLD,
                                   restart ? softopt::Checkpoint::mesh_file(directory) : "");
    const softopt::OutputDirectory out(settings.output_directory, MPI_COMM_WORLD);
    softopt::ShapeOptimizer optimizer(settings.optimization, settings.output, problem, out);
    std::cout.setstate(std::ios::failbit); // the per-iteration lines
    optimizer.run(restart);
    std::cout.clear();
  }

  /** history.csv without the columns that are timings. */
  std::vector<std::vector<std::string>>
  read_history(const std::string &file)
  {
    std::vector<std::vector<std::string>> rows = read_csv(file);
    const std::vector<std::string>        header = rows.at(0);
    for (auto &fields : rows)
      {
        std::vector<std::string> kept;
        for (unsigned int i = 0; i < fields.size(); ++i)
          if (header[i] != "wall_time_s")
            kept.push_back(fields[i]);
        fields = kept;
      }
    return rows;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  for (const double remesh_quality : {0., 1.})
    {
      const std::string suffix = remesh_quality > 0 ? "_remeshed" : "";
      optimize("uninterrupted" + suffix, 8, false, remesh_quality);
      // Stopped after 7 (restart at the mesh update of 6), and without a
      // new mesh also after 5 (restart at 4, no check from rest there).
      std::vector<unsigned int> stops{7};
      if (remesh_quality == 0)
        stops.push_back(5);
      for (const unsigned int stop : stops)
        {
          const std::string directory =
            "interrupted_at_" + std::to_string(stop) + suffix;
          optimize(directory, stop, false, remesh_quality);
          optimize(directory, 8, true, remesh_quality);
        }
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        continue;
      deallog << (remesh_quality > 0 ? "A new mesh at every mesh update:" :
                                       "Mesh updates:")
              << std::endl;
      const auto a = read_history("uninterrupted" + suffix + "/history.csv");
      for (const unsigned int stop : stops)
        {
          const auto b =
            read_history("interrupted_at_" + std::to_string(stop) + suffix + "/history.csv");
          deallog << "stopped after " << stop << ", restarted: rows " << a.size() - 1
                  << " and " << b.size() - 1 << std::endl;
          double largest = 0;
          for (unsigned int r = 1; r < std::min(a.size(), b.size()); ++r)
            for (unsigned int c = 1; c < a[r].size(); ++c)
              {
                if (a[r][c].empty() || b[r][c].empty()) // not checked from rest
                  {
                    if (a[r][c] != b[r][c])
                      largest = std::numeric_limits<double>::infinity();
                    continue;
                  }
                const double x = std::stod(a[r][c]), y = std::stod(b[r][c]);
                largest = std::max(largest, std::abs(x - y) / std::max(1e-3, std::abs(x)));
              }
          deallog << "largest relative difference between the histories "
                  << (largest < 1e-8 ? "below 1e-8" : error(largest)) << std::endl;
        }
      for (unsigned int r = 1; r < a.size(); ++r)
        deallog << a[r][0] << ": " << a[0][1] << " " << a[r][1] << "  " << a[0][2]
                << " " << a[r][2] << "  " << a[0][3] << " " << a[r][3] << std::endl;
    }
}
