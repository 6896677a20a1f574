// Exact landing on target load factors: arclength on the thick sphere
// (A/B = 0.5) with targets 0.3 and 0.6 (of p = mu) must report exactly those
// load factors, and the states there must equal a pure load-control solve to
// the same load factors (relative 1e-8).

#include "sphere.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  Sphere                 sphere(1., 2., 0.5, 3., 0.4999, 1.);
  softopt::NewtonSolver  newton;
  ConditionalOStream     quiet(std::cout, false);
  const auto             none = [](const auto &, const auto &) { return std::string(); };
  const std::vector<double> targets{0.3, 0.6};

  softopt::PathFollowing::Parameters arclength_parameters;
  arclength_parameters.method            = softopt::PathFollowing::Method::arclength;
  arclength_parameters.initial_increment = 0.07;
  const softopt::PathFollowing arclength(arclength_parameters);
  const auto on_arc = arclength.run(*sphere.problem, newton, targets, none, quiet);

  softopt::PathFollowing load_control;
  const auto on_load = load_control.run(*sphere.problem, newton, targets, none, quiet);

  deallog << "arclength took " << on_arc.last.step << " steps" << std::endl;
  for (unsigned int i = 0; i < targets.size(); ++i)
    {
      auto difference = on_arc.target_states[i];
      difference -= on_load.target_states[i];
      const double relative =
        difference.l2_norm() / on_load.target_states[i].l2_norm();
      deallog << "target " << targets[i] << ": arclength |lambda - target| = "
              << below(on_arc.target_load_factors[i] - targets[i], 1e-14)
              << ", load control |lambda - target| = "
              << below(on_load.target_load_factors[i] - targets[i], 1e-14)
              << ", |a_arclength - a_load| / |a_load| "
              << (relative < 1e-8 ? "< 1e-8" : "= " + error(relative))
              << ", lambda_a = " << sphere.stretch(on_arc.target_states[i])
              << std::endl;
    }
}
