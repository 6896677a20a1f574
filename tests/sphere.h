// The thick-walled sphere octant of the verification tests, and the closed
// form of its inflation (incompressible neo-Hookean):
//   p/mu = [2/lambda_b + 1/(2 lambda_b^4)] - [2/lambda_a + 1/(2 lambda_a^4)],
//   lambda_b^3 = 1 + (lambda_a^3 - 1) (A/B)^3.
#ifndef softopt_tests_sphere_h
#define softopt_tests_sphere_h

#include <softopt/functionals/design_surface.h>
#include <softopt/path/newton_solver.h>
#include <softopt/path/path_following.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include "tests.h"

#include <memory>

namespace softopt_tests
{
  inline double
  closed_form_pressure(const double lambda_a, const double ratio)
  {
    const double lambda_b =
      std::cbrt(1 + (std::pow(lambda_a, 3) - 1) * std::pow(ratio, 3));
    auto f = [](const double s) { return 2 / s + 1 / (2 * std::pow(s, 4)); };
    return f(lambda_b) - f(lambda_a);
  }

  /** lambda_a at p/mu on the ascending branch (bisection). */
  inline double
  closed_form_stretch(const double p_over_mu, const double ratio)
  {
    double low = 1, high = 1;
    while (closed_form_pressure(high, ratio) < p_over_mu)
      high += 0.1;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid = (low + high) / 2;
        (closed_form_pressure(mid, ratio) < p_over_mu ? low : high) = mid;
      }
    return (low + high) / 2;
  }

  /** The sphere octant with inner radius A and outer radius B, meshed at h,
   * pressurized with p_over_mu times its shear modulus at load factor 1. */
  struct Sphere
  {
    Sphere(const double A,
           const double B,
           const double h,
           const double youngs_modulus,
           const double nu,
           const double p_over_mu)
      : triangulation(MPI_COMM_WORLD)
      , material(youngs_modulus, nu)
    {
      geometry.mesh_file            = SOURCE_DIR "/../meshes/sphere_octant.geo";
      geometry.mesh_size            = h;
      geometry.mesh_parameters      = {{"A", A}, {"B", B}};
      geometry.dirichlet_boundaries = {{1, {{true, false, false}}},
                                       {2, {{false, true, false}}},
                                       {3, {{false, false, true}}}};
      geometry.pressure_boundary_ids = {4};
      geometry.create_triangulation(triangulation);
      design  = std::make_unique<softopt::DesignConfiguration>(triangulation,
                                                              geometry);
      problem = std::make_unique<softopt::HyperelasticProblem>(
        triangulation,
        design->get_mapping(),
        geometry,
        material,
        p_over_mu * material.shear_modulus);
      problem->setup_system();
      initial_volume =
        softopt::cavity_volume(*problem, *design, problem->create_vector());
    }

    /** lambda_a = (V/V_0)^(1/3). */
    double
    stretch(const softopt::HyperelasticProblem::Vector &a) const
    {
      return std::cbrt(softopt::cavity_volume(*problem, *design, a) / initial_volume);
    }

    parallel::fullydistributed::Triangulation<3>  triangulation;
    softopt::Geometry                             geometry;
    const softopt::NeoHookeanMixed                material;
    std::unique_ptr<softopt::DesignConfiguration> design;
    std::unique_ptr<softopt::HyperelasticProblem> problem;
    double                                        initial_volume;
  };
} // namespace softopt_tests

#endif
