// Arclength through limit points with the default step control: sphere
// octants with A/B = 0.9 (thin) and 0.5 (thick), nu = 0.4999, inflated past
// their pressure maximum up to a cavity volume limit. The closed form
// (sphere.h) has p_max = 0.1304272 mu at lambda_a = 1.4312272 (A/B = 0.9)
// and p_max = 0.8164237 mu at lambda_a = 1.8281473 (A/B = 0.5). With the
// default Loading entries only, the path must locate exactly one limit point
// (the located p_max within 0.2% of the closed form: the mesh's own error,
// doc/verification.md), its largest pressure row within 1%, and at least 10
// rows on the descending branch (pressure falling, cavity growing) before
// the volume limit.

#include "sphere.h"

using namespace softopt_tests;

void
follow(const double A,
       const double B,
       const double h,
       const double p_over_mu,
       const double volume_limit)
{
  Sphere sphere(A, B, h, 3., 0.4999, p_over_mu);
  const double ratio = A / B;

  const double exact_max = closed_form_maximum_pressure(ratio);

  double       max_load = 0, max_stretch = 0, last_load = 0, last_volume = 0;
  unsigned int descending = 0, limit_rows = 0;
  const auto   result = follow_past_maximum(
    sphere, volume_limit, [&](const auto &point, const auto &a, const double volume) {
      if (point.limit_point)
        ++limit_rows;
      else if (point.load_factor > max_load)
        {
          max_load    = point.load_factor;
          max_stretch = sphere.stretch(a);
        }
      if (point.load_factor < last_load && volume > last_volume)
        ++descending;
      last_load   = point.load_factor;
      last_volume = volume;
    });

  const double p_max   = max_load * p_over_mu;
  const double located = result.limit_load_factors.empty() ?
                           0. :
                           result.limit_load_factors.front() * p_over_mu;
  const double row_error     = std::abs(p_max - exact_max) / exact_max;
  const double located_error = std::abs(located - exact_max) / exact_max;
  deallog << "A/B = " << ratio << " (" << sphere.triangulation.n_global_active_cells()
          << " tetrahedra), closed-form p_max/mu " << exact_max << std::endl;
  deallog << "  located limit points " << result.limit_load_factors.size()
          << " (== 1), rows marked " << limit_rows << " (== 1): "
          << (result.limit_load_factors.size() == 1 && limit_rows == 1 ? "ok" : "WRONG")
          << std::endl;
  deallog << "  located p_max/mu " << located << ", error " << located_error
          << (located_error < 2e-3 ? " (< 0.2%)" : " (TOO LARGE, >= 0.2%)") << std::endl;
  deallog << "  largest other row p/mu " << p_max << " at lambda_a " << max_stretch
          << ", error " << row_error
          << (row_error < 0.01 ? " (< 1%)" : " (TOO LARGE, >= 1%)") << std::endl;
  deallog << "  descending rows " << descending
          << (descending >= 10 ? " (>= 10)" : " (TOO FEW, < 10)") << "; "
          << result.last.step << " rows in all, stopped at " << result.stop_reason
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  deallog << std::setprecision(6);
  // The case: 60 kPa at mu = 0.4 MPa, up to 6 times the cavity.
  follow(0.9, 1., 0.1, 0.15, 6.);
  follow(1., 2., 0.5, 1., 12.);
}
