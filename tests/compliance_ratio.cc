// The quantity "compliance ratio" (source/functionals/quantities/
// compliance_ratio.cc) on the thick sphere octant (A/B = 1/2, nu = 0.4999)
// pressurized to 0.7 of its pressure maximum (inputs/sphere_compliance.prm):
// - against the closed form of sphere.h, Q = (l_a^3(p) - l_a^3(p_0)) /
//   ((1 - p_0/p) (l_a^3(p) - 1)), since V / V_0 = l_a^3, as the objective
//   (l_0 = 0.9, l = 1: Q = 1.94 at 0.7 of the maximum) and as a constraint
//   (l_0 = 0.4, l = 0.5: Q = 1.26); on the 693 tetrahedra the error in
//   l_a - 1 is below 0.2 % up to p = 0.5 mu (sphere_inflation; here up to
//   0.57 mu), which makes the volumes' errors similar and largely cancel in
//   the ratio: the bound is 0.5 %;
// - its adjoint gradient through filter, physics and mesh against a Taylor
//   expansion (rates 2).

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "sphere.h"
#include "taylor_test.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_compliance.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  softopt::DesignIterate x      = problem.initial_iterate();
  const auto             values = problem.evaluate(x);

  // p / mu at load factor 1 (the prm file's pressure over mu).
  const double mu        = 3. / (2 * 1.4999);
  const double p_over_mu = 0.5715346 / mu;
  const auto   closed_form = [&](const double l_0, const double l) {
    const double V   = std::pow(closed_form_stretch(l * p_over_mu, 0.5), 3);
    const double V_0 = std::pow(closed_form_stretch(l_0 * p_over_mu, 0.5), 3);
    return (V - V_0) / ((1 - l_0 / l) * (V - 1));
  };
  const double exact[2] = {closed_form(0.9, 1.), closed_form(0.4, 0.5)};
  const double Q[2]     = {values[0], values[1] + 2.}; // f_1 = Q - 2
  for (unsigned int k = 0; k < 2; ++k)
    {
      const double error = std::abs(Q[k] - exact[k]) / exact[k];
      deallog << problem.functionals()[k]->name() << ": Q = " << Q[k]
              << ", closed form " << exact[k] << ", relative error "
              << below(error, 5e-3) << std::endl;
    }

  taylor_test(problem, x, values, problem.gradients(x), settings.optimization.design_bound, 3);
}
