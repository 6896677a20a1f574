// The stability eigenvalue (lowest_eigenvalue: the smallest positive one,
// past a fold the negative one nearest zero) vanishes at the limit point of
// the load path. Sphere octants with A/B = 0.9 and
// 0.5, nu = 0.4999, inflated by arclength past their pressure maximum
// (closed form, sphere.h: p_max = 0.1304272 mu and 0.8164237 mu). Near a
// maximum the eigenvalue goes like +-sqrt(p_max - p) on either side, so
// lambda^2 is linear in p: extrapolated to zero from the two rows of largest
// load factor (one on each side of the maximum) it must land on the
// closed-form p_max within 0.2% (the mesh's own error, tests/limit_points)
// and on the maximum the path located within 0.05%. The eigenvalue must be
// positive on every row before the located maximum and negative on every
// row after it (unstable under pressure), and converged (the relative
// error bound LowestEigenvalue::residual below 1e-5, in fewer than the 100
// Lanczos steps allowed). All this for mu of K phi = mu K_0 phi
// (StabilityMetric, what load_path.csv writes), which must be 1 at rest
// (K(0) - K_0 is the bulk term's excess, and the sphere has isochoric
// modes), and the signs also for the plain eigenvalue of K (M = I).

#include <softopt/physics/stability.h>

#include "sphere.h"

using namespace softopt_tests;

void
follow(const double A, const double B, const double h, const double p_over_mu,
       const double volume_limit)
{
  Sphere       sphere(A, B, h, 3., 0.4999, p_over_mu);
  const double ratio = A / B;
  const double exact_max = closed_form_maximum_pressure(ratio);

  const softopt::StabilityMetric metric(*sphere.problem);
  const auto mu = [&](const softopt::HyperelasticProblem::Vector &a, const double load_factor) {
    return softopt::lowest_eigenvalue(*sphere.problem, a, load_factor, 1e-6, 100, &metric.matrix());
  };
  const auto rest = mu(sphere.problem->create_vector(), 0.);

  // (load factor, eigenvalue) of the rows, in path order.
  std::vector<std::pair<double, double>> rows;
  double       worst_residual = rest.residual;
  unsigned int most_steps     = rest.iterations;
  bool         past_maximum   = false;
  unsigned int wrong_signs    = 0;
  unsigned int wrong_plain_signs = 0;
  const auto   result = follow_past_maximum(
    sphere, volume_limit, [&](const auto &point, const auto &a, double) {
      // Rows after the located maximum are on the descending branch.
      past_maximum = past_maximum || point.limit_point;
      if (point.step > 0 && !point.limit_point)
        {
          const auto eigen = mu(a, point.load_factor);
          const auto plain = softopt::lowest_eigenvalue(*sphere.problem, a, point.load_factor);
          worst_residual = std::max({worst_residual, eigen.residual, plain.residual});
          most_steps     = std::max({most_steps, eigen.iterations, plain.iterations});
          if ((eigen.value > 0) == past_maximum)
            ++wrong_signs;
          if ((plain.value > 0) == past_maximum)
            ++wrong_plain_signs;
          rows.emplace_back(point.load_factor, eigen.value);
        }
    });

  // The two rows of largest load factor.
  unsigned int top = 0;
  while (top + 1 < rows.size() && rows[top + 1].first > rows[top].first)
    ++top;
  const auto [p1, s1] = rows[top - 1];
  const auto [p2, s2] = rows[top];
  const double extrapolated =
    (p2 + s2 * s2 * (p2 - p1) / (s1 * s1 - s2 * s2)) * p_over_mu;
  const double located = result.limit_load_factors.empty() ?
                           0. :
                           result.limit_load_factors.front() * p_over_mu;
  const double exact_error   = std::abs(extrapolated - exact_max) / exact_max;
  const double located_error = std::abs(extrapolated - located) / located;
  deallog << "A/B = " << ratio << ", closed-form p_max/mu " << exact_max
          << ", located " << located << std::endl;
  deallog << "  mu at rest " << rest.value
          << (std::abs(rest.value - 1) < 1e-6 ? " (within 1e-6 of 1)" : " (WRONG, not 1)")
          << std::endl;
  deallog << "  mu at the two rows of largest load " << s1 << ", " << s2
          << "; lambda^2 extrapolated to zero at p/mu " << extrapolated << std::endl;
  deallog << "  error against the closed form " << exact_error
          << (exact_error < 2e-3 ? " (< 0.2%)" : " (TOO LARGE, >= 0.2%)")
          << ", against the located maximum " << located_error
          << (located_error < 5e-4 ? " (< 0.05%)" : " (TOO LARGE, >= 0.05%)") << std::endl;
  deallog << "  rows with the wrong sign " << wrong_signs << " (mu), " << wrong_plain_signs
          << " (K's eigenvalue) of " << rows.size()
          << (wrong_signs + wrong_plain_signs == 0 && past_maximum ?
                " (== 0, descending rows present)" :
                " (WRONG)")
          << "; largest eigen residual "
          << (worst_residual < 1e-5 && most_steps < 100 ? "< 1e-5 in < 100 steps" :
                                                          "TOO LARGE, or 100 steps")
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  deallog << std::setprecision(6);
  follow(0.9, 1., 0.1, 0.15, 6.);
  follow(1., 2., 0.5, 1., 12.);
}
