// The check of the warm-started states against those from rest
// (DesignProblem::check_branch, Optimization / Path from rest interval) on a
// design with two equilibria at its target (inputs/thin_sphere_branches.prm):
// the thin sphere octant at 0.11 mu, below its pressure maximum 0.1304 mu.
// Its states are set to a state of the descending branch that arclength
// reaches past the maximum, from which the warm start's Newton converges to
// that branch's equilibrium at the target, a state that inflating the
// sphere from rest does not reach. The check must
// find another branch and go on from the states from rest, which are those
// of the path from zero.

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "sphere.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/thin_sphere_branches.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  auto                  &physics = problem.hyperelastic_problem();

  // From rest: the path from zero (no states yet).
  softopt::DesignIterate    x         = problem.initial_iterate();
  const std::vector<double> from_rest = problem.evaluate(x);
  const auto                a_rest    = x.states.at(1.);

  // A state on the descending branch: arclength past the maximum (load
  // factor 1.186) until the load factor falls below 1 again.
  softopt::PathFollowing::Parameters path_parameters;
  path_parameters.method            = softopt::PathFollowing::Method::arclength;
  path_parameters.initial_increment = 0.1;
  path_parameters.maximum_increment = 0.1;
  path_parameters.maximum_steps     = 80;
  ConditionalOStream quiet(std::cout, false);
  auto               guess = physics.create_vector();
  double             last = 0, at = 0;
  const softopt::PathFollowing path(path_parameters);
  path.run(
    physics,
    settings.newton,
    {10.},
    [&](const softopt::PathFollowing::PathPoint &point, const auto &a) {
      const bool past = point.load_factor < last && point.load_factor < 1.;
      last            = point.load_factor;
      if (!past)
        return std::string();
      guess = a;
      at    = point.load_factor;
      return std::string("on the descending branch");
    },
    quiet);
  deallog << "arclength: the descending branch below load factor 1 "
          << (at > 0.8 && at < 1. ? "reached" : "NOT reached") << std::endl;
  x.states = {{1., guess}};

  std::vector<double> values = problem.evaluate(x); // warm: from the guess
  deallog << "warm start: " << (problem.path_report().warm_started ? "yes" : "no")
          << problem.path_report().warm_start_failure
          << ", cavity volume / that from rest "
          << (values[0] > 1.5 * from_rest[0] ? "above 1.5" : "NOT above 1.5")
          << std::endl;

  const auto check = problem.check_branch(x, values, 1e-3);
  deallog << "check from rest: difference " << (check.difference > 0.5 ? "above 0.5" : "NOT above 0.5")
          << ", another branch: " << (check.switched ? "yes" : "no") << std::endl;
  auto difference = x.states.at(1.);
  difference -= a_rest;
  deallog << "the run goes on from the states from rest: |a - a_rest| / |a_rest| "
          << below(difference.l2_norm() / a_rest.l2_norm(), 1e-6)
          << ", |V - V_rest| / V_rest " << below(std::abs(values[0] - from_rest[0]) / from_rest[0], 1e-8)
          << std::endl;

  // Back on the physical branch, the next check finds the same branch.
  const auto again = problem.check_branch(x, values, 1e-3);
  deallog << "checked again: another branch: " << (again.switched ? "yes" : "no")
          << ", difference " << below(again.difference, 1e-3) << std::endl;

  // The constraint f = V - Tolerance is active (Tolerance is V at the
  // target to 7 digits): values 1e-8 V off those from rest, at the
  // solvers' accuracy, are the same branch. Relative to f itself they
  // would differ by about 0.1 and count as a switch.
  std::vector<double> near = values;
  near[1] += 1e-8 * values[0];
  const auto active = problem.check_branch(x, near, 1e-3);
  deallog << "active constraint: |f| / V " << below(std::abs(values[1]) / values[0], 1e-6)
          << ", values 1e-8 V off: another branch: " << (active.switched ? "yes" : "no")
          << ", difference " << below(active.difference, 1e-6) << std::endl;
}
