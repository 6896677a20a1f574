// The warm start's secant predictor (SecantPredictor) on the small design
// problem (inputs/sphere_design.prm, nu = 0.49): after designs d0 and
// d1 = d0 + s dd, the design d2 = d0 + 2 s dd starts Newton at every target
// from a_1 + alpha (a_1 - a_0), with alpha near 1 (the filter is nonlinear,
// so X is not exactly linear in d). The states it converges to must equal
// those of the path from zero and of the warm start from a_1 (relative
// 1e-8), with fewer Newton iterations than from a_1.

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "tests.h"

using namespace softopt_tests;

namespace
{
  using Vector = softopt::DesignProblem::Vector;

  /** The states at d2 after d0 and d1, and d2's path report. */
  std::pair<std::map<double, Vector>, softopt::DesignProblem::PathReport>
  states_at_d2(softopt::Settings &settings, const double s)
  {
    softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
    softopt::DesignIterate x         = problem.initial_iterate();
    auto                   direction = problem.create_design_vector();
    for (const auto i : direction.locally_owned_elements())
      direction(i) = random(i, 5);
    direction.compress(VectorOperation::insert);
    for (const double step : {0., 1., 2.})
      {
        x.d = 0;
        x.d.add(step * s, direction);
        problem.evaluate(x);
      }
    return {x.states, problem.path_report()};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings settings(SOURCE_DIR "/inputs/sphere_design.prm");
  const double      s = 0.3 * settings.optimization.design_bound;

  const auto [secant, secant_report] = states_at_d2(settings, s);
  settings.optimization.secant_predictor = false;
  const auto [last, last_report] = states_at_d2(settings, s);
  settings.optimization.warm_start = false;
  const auto [cold, cold_report] = states_at_d2(settings, s);

  deallog << "secant start: " << (secant_report.warm_started ? "warm" : "cold")
          << ", alpha " << std::fixed << std::setprecision(2)
          << secant_report.secant_alpha << std::defaultfloat
          << std::setprecision(8) << std::endl;
  deallog << "from the last design's states: "
          << (last_report.warm_started ? "warm" : "cold") << std::endl;
  deallog << "Newton iterations over both targets: secant "
          << secant_report.newton_iterations << ", last design's states "
          << last_report.newton_iterations << " ("
          << (secant_report.newton_iterations < last_report.newton_iterations ?
                "fewer" :
                "NOT FEWER")
          << ")" << std::endl;
  for (const auto &[load_factor, a] : cold)
    for (const auto &[name, other] :
         {std::pair{"secant", &secant}, std::pair{"last design's", &last}})
      {
        auto difference = other->at(load_factor);
        difference -= a;
        const double relative = difference.l2_norm() / a.l2_norm();
        deallog << "lambda " << load_factor << ": |a(" << name
                << " start) - a(path from zero)| / |a| "
                << (relative < 1e-8 ? "below 1e-8" : error(relative))
                << std::endl;
      }
}
