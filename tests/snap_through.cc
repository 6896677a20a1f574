// Load control past a limit point (issue 19): a thin sphere octant (A/B =
// 0.9, nu = 0.4999) of a Yeoh material whose pressure rises to a maximum,
// falls to a minimum and rises again (W' = C1 + 2 C2 x + 3 C3 x^2, x = I1^ - 3,
// with C2 < 0), inflated under pressure control to a target above the
// maximum. Inflated from rest the sphere snaps through at p_max onto the far
// ascending branch; the state at the target is the one there. Load control
// (the default) cannot pass the maximum: it hands over to arclength, which
// must land on the target on the far branch, at the closed-form stretch of
// sphere.h (the largest root of p(lambda_a) = p_target), within 2% of the
// stretch change; a target below the maximum lies on the near branch. With
// "Load control at a limit point = stop" the path stops below the maximum.

#include "sphere.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  deallog << std::setprecision(6);

  const std::vector<double> C{0.2, -0.01, 0.001};
  const auto                material = yeoh("0.2, -0.01, 0.001", 0.4999);
  const auto                pressure = [&](const double lambda_a) {
    return closed_form_pressure(lambda_a, 0.9, [&](const double I1) {
      const double x = I1 - 3;
      return C[0] + 2 * C[1] * x + 3 * C[2] * x * x;
    });
  };

  // The closed form: the maximum, the minimum after it, and the stretch
  // on either branch at a pressure (bisection between the extrema).
  // The first local maximum and the first local minimum after it.
  double lambda_max = 1, lambda_min = 0;
  for (double l = 1.001; lambda_min == 0; l += 0.001)
    if (lambda_max == 1 && pressure(l + 0.001) < pressure(l))
      lambda_max = l;
    else if (lambda_max > 1 && pressure(l + 0.001) > pressure(l))
      lambda_min = l;
  const auto root = [&](const double p, double low, double high) {
    const bool rising = pressure(high) > pressure(low);
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double mid = (low + high) / 2;
        ((pressure(mid) < p) == rising ? low : high) = mid;
      }
    return (low + high) / 2;
  };
  const double p_target = 1.25 * pressure(lambda_max); // load factor 1
  const double G0       = material->shear_modulus;
  deallog << "closed form: p_max/G_0 = " << pressure(lambda_max) / G0
          << " at lambda_a = " << lambda_max << ", p_min/G_0 = "
          << pressure(lambda_min) / G0 << " at lambda_a = " << lambda_min
          << "; target p/G_0 = " << p_target / G0 << std::endl;

  Sphere sphere(0.9, 1., 0.1, material, p_target / G0);
  ConditionalOStream    quiet(std::cout, false);
  softopt::NewtonSolver newton;
  const auto            no_stop = [](const softopt::PathFollowing::PathPoint &,
                          const auto &) { return std::string(); };
  const std::vector<double> targets{0.5, 1.};

  {
    const softopt::PathFollowing path; // load control, the defaults
    const auto result = path.run(*sphere.problem, newton, targets, no_stop, quiet);
    deallog << "load control: " << result.stop_reason << "; arclength from load factor "
            << result.arclength_from << " (closed-form maximum at "
            << pressure(lambda_max) / p_target << ")" << std::endl;
    for (unsigned int i = 0; i < result.target_states.size(); ++i)
      {
        const double p        = p_target * result.target_load_factors[i];
        const double lambda_a = sphere.stretch(result.target_states[i]);
        const double exact    = p < pressure(lambda_max) ?
                                  root(p, 1., lambda_max) :
                                  root(p, lambda_min, 4.);
        const double error = std::abs(lambda_a - exact) / (exact - 1);
        deallog << "  load factor " << result.target_load_factors[i]
                << ": lambda_a = " << lambda_a << ", closed form " << exact
                << (p < pressure(lambda_max) ? " (near branch)" : " (far branch)")
                << ", error " << error << (error < 0.02 ? " (< 0.02)" : " (TOO LARGE)")
                << std::endl;
      }
  }
  {
    softopt::PathFollowing::Parameters parameters;
    parameters.arclength_past_limit_points = false;
    parameters.minimum_increment           = 1e-3;
    const softopt::PathFollowing path(parameters);
    const auto result = path.run(*sphere.problem, newton, targets, no_stop, quiet);
    deallog << "load control, stop at a limit point: failed " << result.failed
            << " above load factor " << result.last.load_factor
            << (result.last.load_factor < pressure(lambda_max) / p_target ?
                  " (below the maximum)" :
                  " (ABOVE THE MAXIMUM)")
            << std::endl;
  }
}
