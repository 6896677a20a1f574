// Verification against a closed form: an octant of a thick-walled sphere
// (A = 1, B = 2) of nearly incompressible neo-Hookean material (nu = 0.4999)
// under internal pressure, with lambda_a = (V / V_0)^(1/3) from the cavity
// volume, against
//   p/mu = [2/lambda_b + 1/(2 lambda_b^4)] - [2/lambda_a + 1/(2 lambda_a^4)],
//   lambda_b^3 = 1 + (lambda_a^3 - 1) (A/B)^3,
// which gives lambda_a = 1.0845562 at p = 0.25 mu, 1.2128882 at 0.5 mu.
// The coarse mesh (693 tetrahedra) must be within 0.2% of the stretch.

#include <deal.II/base/conditional_ostream.h>

#include <softopt/path/newton_solver.h>
#include <softopt/path/path_following.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include "tests.h"

using namespace softopt_tests;

namespace
{
  double
  closed_form_pressure(const double lambda_a, const double ratio)
  {
    const double lambda_b =
      std::cbrt(1 + (std::pow(lambda_a, 3) - 1) * std::pow(ratio, 3));
    auto f = [](const double s) { return 2 / s + 1 / (2 * std::pow(s, 4)); };
    return f(lambda_b) - f(lambda_a);
  }

  double
  closed_form_stretch(const double p_over_mu, const double ratio)
  {
    double low = 1, high = 1.5;
    for (unsigned int i = 0; i < 100; ++i)
      {
        const double mid = (low + high) / 2;
        (closed_form_pressure(mid, ratio) < p_over_mu ? low : high) = mid;
      }
    return (low + high) / 2;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  parallel::fullydistributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  softopt::Geometry                            geometry;
  geometry.mesh_file            = SOURCE_DIR "/../meshes/sphere_octant.geo";
  geometry.mesh_size            = 0.5;
  geometry.dirichlet_boundaries = {{1, {{true, false, false}}},
                                   {2, {{false, true, false}}},
                                   {3, {{false, false, true}}}};
  geometry.pressure_boundary_ids = {4};
  geometry.create_triangulation(triangulation);
  deallog << "tetrahedra: " << triangulation.n_global_active_cells() << std::endl;

  const double                        nu = 0.4999, E = 3.;
  const softopt::NeoHookeanMixed      material(E, nu);
  const double                        mu = material.shear_modulus;
  const softopt::DesignConfiguration  design(triangulation, geometry);
  softopt::HyperelasticProblem        problem(
    triangulation, design.get_mapping(), geometry, material, 0.5 * mu);
  problem.setup_system();
  const double V_0 = problem.cavity_volume(problem.create_vector());
  deallog << "V_0 / (pi/6 A^3) = " << V_0 / (M_PI / 6.) << std::endl;

  softopt::PathFollowing path;
  softopt::NewtonSolver  newton;
  ConditionalOStream     quiet(std::cout, false);
  const auto             result = path.run(
    problem, newton, {0.5, 1.},
    [](const softopt::PathFollowing::PathPoint &, const auto &) { return std::string(); },
    quiet);
  for (unsigned int i = 0; i < result.target_states.size(); ++i)
    {
      const double p_over_mu = 0.5 * result.target_load_factors[i];
      const double lambda_a =
        std::cbrt(problem.cavity_volume(result.target_states[i]) / V_0);
      const double exact = closed_form_stretch(p_over_mu, 0.5);
      const double error = std::abs(lambda_a - exact) / (exact - 1);
      deallog << "p/mu = " << p_over_mu << ": lambda_a = " << lambda_a
              << ", closed form " << exact << ", error in the stretch "
              << error << (error < 2e-3 ? " (below 0.2%)" : " TOO LARGE")
              << std::endl;
    }
}
