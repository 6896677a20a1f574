#ifndef softopt_app_gradient_check_h
#define softopt_app_gradient_check_h

#include <softopt/app/settings.h>

namespace softopt
{
  /**
   * "softopt check-gradients CASE.prm": checks the adjoint gradient of every
   * objective, constraint and of the cavity volume against finite
   * differences at the initial design, along a seeded random direction and
   * along each gradient, for steps h = 1e-1 ... 1e-7 times the design bound.
   * Writes gradient_check.csv (function,direction,h,fd_remainder,
   * taylor_remainder) and prints the observed rates: the Taylor remainder
   * |J(d + h dd) - J(d) - h grad J . dd| falls as h^2 until round-off if the
   * gradient is right (the plain difference falls as h).
   */
  int
  run_gradient_check(const Settings &settings, const MPI_Comm comm);
} // namespace softopt

#endif
