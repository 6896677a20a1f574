// Arclength through limit points: sphere octants with A/B = 0.9 (thin) and
// 0.5 (thick), nu = 0.4999, inflated past their pressure maximum. The closed
// form (sphere.h) has p_max = 0.1304272 mu at lambda_a = 1.4312272 (A/B = 0.9)
// and p_max = 0.8164237 mu at lambda_a = 1.8281473 (A/B = 0.5). The largest
// computed pressure must be within 1% of p_max, and the path must go on down
// the descending branch (pressure falling, cavity growing) for 10 steps.

#include "sphere.h"

using namespace softopt_tests;

void
follow(const double A, const double B, const double h, const double p_over_mu)
{
  Sphere sphere(A, B, h, 3., 0.4999, p_over_mu);
  const double ratio = A / B;

  // The closed-form maximum: golden-section search on p(lambda_a).
  double lo = 1.01, hi = 3.;
  for (unsigned int i = 0; i < 200; ++i)
    {
      const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
      (closed_form_pressure(m1, ratio) < closed_form_pressure(m2, ratio) ? lo : hi) =
        (closed_form_pressure(m1, ratio) < closed_form_pressure(m2, ratio) ? m1 : m2);
    }
  const double exact_max = closed_form_pressure((lo + hi) / 2, ratio);

  softopt::PathFollowing::Parameters path_parameters;
  path_parameters.method              = softopt::PathFollowing::Method::arclength;
  path_parameters.initial_increment   = 0.1;
  path_parameters.maximum_increment   = 0.2;
  path_parameters.maximum_steps       = 60;
  softopt::NewtonSolver newton;
  ConditionalOStream    quiet(std::cout, false);

  double       max_load = 0, max_stretch = 0, last_load = 0, last_volume = 0;
  unsigned int descending = 0;
  const softopt::PathFollowing path(path_parameters);
  const auto   result     = path.run(
    *sphere.problem, newton, {1.},
    [&](const softopt::PathFollowing::PathPoint &point, const auto &a) {
      const double volume = softopt::cavity_volume(*sphere.problem, *sphere.design, a);
      if (point.load_factor > max_load)
        {
          max_load    = point.load_factor;
          max_stretch = sphere.stretch(a);
        }
      if (point.load_factor < last_load && volume > last_volume)
        ++descending;
      last_load   = point.load_factor;
      last_volume = volume;
      return descending >= 10 ? std::string("ten descending steps") : std::string();
    },
    quiet);

  const double p_max = max_load * p_over_mu;
  deallog << "A/B = " << ratio << " (" << sphere.triangulation.n_global_active_cells()
          << " tetrahedra): p_max/mu = " << p_max << " at lambda_a = " << max_stretch
          << "; closed form " << exact_max << ", error "
          << std::abs(p_max - exact_max) / exact_max
          << (std::abs(p_max - exact_max) < 0.01 * exact_max ? " (within 1%)" :
                                                               " (TOO LARGE)")
          << std::endl;
  deallog << "  stopped after " << result.last.step << " steps: " << result.stop_reason
          << "; descending steps " << descending << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  deallog << std::setprecision(6);
  follow(0.9, 1., 0.1, 0.2);
  follow(1., 2., 0.5, 1.);
}
