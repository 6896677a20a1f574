// The warm start's design substeps (DesignProblem::substep_start) on the
// small design problem (inputs/sphere_design.prm, nu = 0.49): with Newton
// held to two iterations, the full step d0 -> d1 at the design bound is
// beyond Newton from d0's states, and the substeps psi_0 + t (psi_1 - psi_0)
// must carry the states to d1 (no path from zero) and land on the states the
// path from zero finds with the usual Newton (relative 1e-8; the sphere has
// one branch).

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "tests.h"

using namespace softopt_tests;

namespace
{
  using Vector = softopt::DesignProblem::Vector;

  /** The states at d1 = s direction after d0 = 0, and d1's path report;
   * Newton held to @p newton_cap iterations for d1 (0: as in the file). */
  std::pair<std::map<double, Vector>, softopt::DesignProblem::PathReport>
  states_at_d1(softopt::Settings &settings, const double s, const unsigned int newton_cap)
  {
    const unsigned int usual = settings.newton.max_iterations;
    softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
    softopt::DesignIterate x         = problem.initial_iterate();
    auto                   direction = problem.create_design_vector();
    for (const auto i : direction.locally_owned_elements())
      direction(i) = random(i, 5);
    direction.compress(VectorOperation::insert);
    problem.evaluate(x);
    x.d = 0;
    x.d.add(s, direction);
    if (newton_cap > 0)
      settings.newton.max_iterations = newton_cap;
    problem.evaluate(x);
    settings.newton.max_iterations = usual;
    return {x.states, problem.path_report()};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings settings(SOURCE_DIR "/inputs/sphere_design.prm");
  const double      s = settings.optimization.design_bound;

  settings.optimization.warm_start = false;
  const auto [cold, cold_report] = states_at_d1(settings, s, 0);

  settings.optimization.warm_start       = true;
  settings.optimization.secant_predictor = false;
  const auto [stepped, stepped_report]   = states_at_d1(settings, s, 2);

  deallog << "from the last design's states: "
          << (stepped_report.warm_start_failure.empty() ? "converged (NOT A TEST)" : "failed")
          << "; design substeps: " << stepped_report.substeps << " ("
          << (stepped_report.warm_started && stepped_report.substeps > 0 ? "warm, > 0" :
                                                                           "NOT USED")
          << ")" << std::endl;
  for (const auto &[load_factor, a] : cold)
    {
      auto difference = stepped.at(load_factor);
      difference -= a;
      const double relative = difference.l2_norm() / a.l2_norm();
      deallog << "lambda " << load_factor
              << ": |a(substeps) - a(path from zero)| / |a| "
              << (relative < 1e-8 ? "below 1e-8" : error(relative)) << std::endl;
    }
}
