// The forward model at the extremes users reach, on the thick sphere
// (A/B = 0.5, 693 tetrahedra):
// - nu from 0.49 to 0.49999999: no locking (round-off stalls the residual at
//   4e-8 |lambda P| at 0.49999999; Newton stops on the correction energy), lambda_a at p = 0.5 mu within 0.5%
//   of the incompressible closed form;
// - a pressure of 1e-6 p_max: the stretch lambda_a - 1 (about 1e-7) still
//   has its discretization accuracy;
// - E scaled by 1e3 and 1e-3 with the pressure: the same path (V/V_0 to 1e-8).

#include "sphere.h"

using namespace softopt_tests;

namespace
{
  /** lambda_a at the target load factors (load control). */
  std::vector<double>
  inflate(const double E, const double nu, const double p_over_mu,
          const std::vector<double> &targets)
  {
    Sphere                 sphere(1., 2., 0.5, E, nu, p_over_mu);
    softopt::PathFollowing path;
    softopt::NewtonSolver  newton;
    ConditionalOStream     quiet(std::cout, false);
    const auto             result = path.run(
      *sphere.problem, newton, targets,
      [](const auto &, const auto &) { return std::string(); }, quiet);
    if (result.failed)
      deallog << "FAILED: " << result.stop_reason << std::endl;
    std::vector<double> stretches(targets.size(), std::nan(""));
    for (const auto &a : result.target_states)
      stretches[&a - &result.target_states[0]] = sphere.stretch(a);
    return stretches;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const double exact = closed_form_stretch(0.5, 0.5);
  for (const double nu : {0.49, 0.499, 0.4999, 0.49999, 0.4999999, 0.49999999})
    {
      const double lambda_a = inflate(3., nu, 0.5, {1.})[0];
      const double error    = std::abs(lambda_a - exact) / exact;
      deallog << "nu = " << nu << ": lambda_a = " << lambda_a
              << ", relative error " << error
              << (error < 5e-3 ? " (within 0.5%)" : " (TOO LARGE)") << std::endl;
    }

  const double p_tiny   = 1e-6 * 0.8164237;
  const double stretch  = inflate(3., 0.4999, p_tiny, {1.})[0] - 1;
  const double expected = closed_form_stretch(p_tiny, 0.5) - 1;
  deallog << "p = 1e-6 p_max: lambda_a - 1 = " << stretch << ", closed form "
          << expected << ", relative error " << std::abs(stretch - expected) / expected
          << std::endl;

  const std::vector<double> reference = inflate(3., 0.4999, 0.5, {0.5, 1.});
  for (const double scale : {1e3, 1e-3})
    {
      const auto   scaled = inflate(3. * scale, 0.4999, 0.5, {0.5, 1.});
      double       worst  = 0;
      for (unsigned int i = 0; i < scaled.size(); ++i)
        worst = std::max(worst, std::abs(std::pow(scaled[i] / reference[i], 3) - 1));
      deallog << "E x " << scale << ": largest relative difference of V/V_0 "
              << (worst < 1e-8 ? "< 1e-8" : error(worst)) << std::endl;
    }
}
