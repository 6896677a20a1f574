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

#include "tests.h"

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

  auto direction = problem.create_design_vector();
  for (const auto i : direction.locally_owned_elements())
    direction(i) = random(i, 3);
  direction.compress(VectorOperation::insert);

  const double        scale = settings.optimization.design_bound;
  std::vector<double> steps{1e-1, 1e-2, 1e-3, 1e-4};
  std::vector<std::vector<double>> taylor(functionals.size());
  for (const double h : steps)
    {
      x.d = d0;
      x.d.add(h * scale, direction);
      const auto at = problem.evaluate(x);
      for (unsigned int k = 0; k < functionals.size(); ++k)
        taylor[k].push_back(
          std::abs(at[k] - values[k] - h * scale * (gradients[k] * direction)));
    }

  for (unsigned int k = 0; k < functionals.size(); ++k)
    {
      deallog << functionals[k]->name() << " = " << values[k] << ": rates";
      bool pass = true;
      for (unsigned int i = 0; i + 1 < steps.size(); ++i)
        {
          const double rate = std::log10(taylor[k][i] / taylor[k][i + 1]);
          pass &= rate >= 1.9;
          deallog << " " << std::fixed << std::setprecision(1) << rate;
        }
      deallog << std::defaultfloat << std::setprecision(8)
              << (pass ? " (all >= 1.9)" : " (BELOW 1.9)") << std::endl;
    }

  // Warm start from another design, back at d0.
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
