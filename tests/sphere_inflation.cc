// Verification against a closed form: an octant of a thick-walled sphere
// (A = 1, B = 2) of nearly incompressible neo-Hookean material (nu = 0.4999)
// under internal pressure, with lambda_a = (V / V_0)^(1/3) from the cavity
// volume, against the closed form of sphere.h, which gives
// lambda_a = 1.0845562 at p = 0.25 mu and 1.2128882 at 0.5 mu.
// The coarse mesh (693 tetrahedra) must be within 0.2% of the stretch.

#include "sphere.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  Sphere sphere(1., 2., 0.5, 3., 0.4999, 0.5);
  deallog << "tetrahedra: " << sphere.triangulation.n_global_active_cells()
          << std::endl;
  deallog << "V_0 / (pi/6 A^3) = " << sphere.initial_volume / (M_PI / 6.)
          << std::endl;

  softopt::PathFollowing path;
  softopt::NewtonSolver  newton;
  ConditionalOStream     quiet(std::cout, false);
  const auto             result = path.run(
    *sphere.problem, newton, {0.5, 1.},
    [](const softopt::PathFollowing::PathPoint &, const auto &) { return std::string(); },
    quiet);
  for (unsigned int i = 0; i < result.target_states.size(); ++i)
    {
      const double p_over_mu = 0.5 * result.target_load_factors[i];
      const double lambda_a  = sphere.stretch(result.target_states[i]);
      const double exact     = closed_form_stretch(p_over_mu, 0.5);
      const double error     = std::abs(lambda_a - exact) / (exact - 1);
      deallog << "p/mu = " << p_over_mu << ": lambda_a = " << lambda_a
              << ", closed form " << exact << ", error in the stretch "
              << error << (error < 2e-3 ? " (below 0.2%)" : " TOO LARGE")
              << std::endl;
    }
}
