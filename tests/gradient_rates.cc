// Adjoint gradients against finite differences on a small design problem
// (inputs/sphere_design.prm): for an objective with a constant direction, one with
// the inward radial direction, the constraint and the cavity volume, the
// Taylor remainder |J(d + h dd) - J(d) - h grad J . dd| along a seeded random
// direction must fall as h^2 (rate >= 1.9) over three consecutive steps.
// Then the same gradients after a warm start (Newton at the targets from the
// states of another design, the adjoint by iterative refinement on the last
// Newton factorization) must equal those after the path from zero.

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "taylor_test.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_design.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  problem.add_cavity_volume();
  const auto &functionals = problem.functionals();

  softopt::DesignIterate x         = problem.initial_iterate();
  const auto             d0        = x.d;
  const auto             values    = problem.evaluate(x);
  const auto             gradients = problem.gradients(x);

  const double scale = settings.optimization.design_bound;
  taylor_test(problem, x, values, gradients, scale, 3);

  // Warm start from another design (along the direction of the test), back
  // at d0.
  auto direction = problem.create_design_vector();
  for (const auto i : direction.locally_owned_elements())
    direction(i) = random(i, 3);
  direction.compress(VectorOperation::insert);
  x.d = d0;
  x.d.add(0.5 * scale, direction);
  problem.evaluate(x);
  x.d = d0;
  problem.evaluate(x);
  const auto warm = problem.gradients(x);
  deallog << "warm start: " << (problem.path_report().warm_started ? "yes" : "no")
          << std::endl;
  for (unsigned int k = 0; k < functionals.size(); ++k)
    {
      auto difference = warm[k];
      difference -= gradients[k];
      const double relative = difference.l2_norm() / gradients[k].l2_norm();
      deallog << functionals[k]->name()
              << ": |warm - cold gradient| / |cold gradient| "
              << (relative < 1e-7 ? "below 1e-7" : error(relative)) << std::endl;
    }
}
