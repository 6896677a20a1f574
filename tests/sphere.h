// The thick-walled sphere octant of the verification tests, and the closed
// form of its inflation (incompressible neo-Hookean):
//   p/mu = [2/lambda_b + 1/(2 lambda_b^4)] - [2/lambda_a + 1/(2 lambda_a^4)],
//   lambda_b^3 = 1 + (lambda_a^3 - 1) (A/B)^3,
// and for any incompressible W(I1^), with the equibiaxial stretch lambda at
// radius r (I1^ = 2 lambda^2 + lambda^-4),
//   p = int_{lambda_b}^{lambda_a} 4 W'(I1^) (lambda^3 + 1) / lambda^5 dlambda,
// which is the neo-Hookean form for W' = mu/2.
#ifndef softopt_tests_sphere_h
#define softopt_tests_sphere_h

#include <softopt/functionals/design_surface.h>
#include <softopt/path/newton_solver.h>
#include <softopt/path/path_following.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include "tests.h"

#include <functional>
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

  /** p for an incompressible W(I1^) with W' = dW_dI1 (composite Gauss,
   * 20 intervals of 4 points: round-off for these smooth integrands). */
  inline double
  closed_form_pressure(const double                          lambda_a,
                       const double                          ratio,
                       const std::function<double(double)> &dW_dI1)
  {
    const double lambda_b =
      std::cbrt(1 + (std::pow(lambda_a, 3) - 1) * std::pow(ratio, 3));
    const double x[4] = {-0.8611363115940526, -0.3399810435848563,
                         0.3399810435848563,  0.8611363115940526};
    const double w[4] = {0.3478548451374538, 0.6521451548625461,
                         0.6521451548625461, 0.3478548451374538};
    const unsigned int n = 20;
    const double       h = (lambda_a - lambda_b) / n;
    double             p = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int q = 0; q < 4; ++q)
        {
          const double s = lambda_b + h * (i + 0.5 + 0.5 * x[q]);
          p += 0.5 * h * w[q] * 4 * dW_dI1(2 * s * s + std::pow(s, -4)) *
               (s * s * s + 1) / std::pow(s, 5);
        }
    return p;
  }

  /** lambda_a at pressure p (bisection on the ascending branch). */
  inline double
  closed_form_stretch(const double                         p,
                      const std::function<double(double)> &pressure)
  {
    double low = 1, high = 1;
    while (pressure(high) < p)
      high += 0.1;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid = (low + high) / 2;
        (pressure(mid) < p ? low : high) = mid;
      }
    return (low + high) / 2;
  }

  /** lambda_a at p/mu on the ascending branch (neo-Hookean). */
  inline double
  closed_form_stretch(const double p_over_mu, const double ratio)
  {
    return closed_form_stretch(p_over_mu, [ratio](const double lambda_a) {
      return closed_form_pressure(lambda_a, ratio);
    });
  }

  /** The neo-Hookean sphere's pressure maximum p_max/mu (golden-section
   * search on p(lambda_a)). */
  inline double
  closed_form_maximum_pressure(const double ratio)
  {
    double lo = 1.01, hi = 3.;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
        if (closed_form_pressure(m1, ratio) < closed_form_pressure(m2, ratio))
          lo = m1;
        else
          hi = m2;
      }
    return closed_form_pressure((lo + hi) / 2, ratio);
  }

  /** The sphere octant with inner radius A and outer radius B, meshed at h,
   * pressurized with p_over_mu times its shear modulus at load factor 1. */
  struct Sphere
  {
    /** Of the neo-Hookean material with E and nu. */
    Sphere(const double A,
           const double B,
           const double h,
           const double youngs_modulus,
           const double nu,
           const double p_over_mu)
      : Sphere(A, B, h, neo_hookean(youngs_modulus, nu), p_over_mu)
    {}

    Sphere(const double                                    A,
           const double                                    B,
           const double                                    h,
           const std::shared_ptr<const softopt::Material> &material,
           const double                                    p_over_mu)
      : triangulation(MPI_COMM_WORLD)
      , material(material)
    {
      geometry.mesh_file            = SOURCE_DIR "/../meshes/sphere_octant.geo";
      geometry.mesh_size            = h;
      geometry.mesh_parameters      = {{"A", A}, {"B", B}};
      geometry.dirichlet_boundaries = {{1, {{true, false, false}}},
                                       {2, {{false, true, false}}},
                                       {3, {{false, false, true}}}};
      geometry.pressure_boundary_ids = {4};
      design = std::make_unique<softopt::DesignConfiguration>(
        triangulation, geometry.create_triangulation(triangulation));
      problem = std::make_unique<softopt::HyperelasticProblem>(
        triangulation,
        design->get_mapping(),
        geometry,
        *material,
        p_over_mu * material->shear_modulus);
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
    std::shared_ptr<const softopt::Material>      material;
    std::unique_ptr<softopt::DesignConfiguration> design;
    std::unique_ptr<softopt::HyperelasticProblem> problem;
    double                                        initial_volume;
  };

  /** Follows @p sphere's load path by arclength with the default Loading
   * entries, past its pressure maximum, until the cavity exceeds
   * @p volume_limit times its initial volume; @p observe(point, a, volume)
   * sees every converged point. */
  inline softopt::PathFollowing::Result
  follow_past_maximum(
    Sphere      &sphere,
    const double volume_limit,
    const std::function<void(const softopt::PathFollowing::PathPoint &,
                             const softopt::HyperelasticProblem::Vector &,
                             double)> &observe)
  {
    softopt::PathFollowing::Parameters parameters;
    parameters.method = softopt::PathFollowing::Method::arclength;
    const softopt::NewtonSolver newton;
    ConditionalOStream          quiet(std::cout, false);
    return softopt::PathFollowing(parameters).run(
      *sphere.problem,
      newton,
      {1.},
      [&](const softopt::PathFollowing::PathPoint &point, const auto &a) {
        const double volume = softopt::cavity_volume(*sphere.problem, *sphere.design, a);
        observe(point, a, volume);
        return volume > volume_limit * sphere.initial_volume ?
                 std::string("the volume limit") :
                 std::string();
      },
      quiet);
  }
} // namespace softopt_tests

#endif
