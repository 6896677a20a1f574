#ifndef softopt_functionals_surface_mean_h
#define softopt_functionals_surface_mean_h

#include <softopt/physics/hyperelastic_problem.h>

#include <functional>

namespace softopt
{
  /**
   * The area average of u . v over the design surface dOmega^d in the design
   * configuration, 1/|dOmega^d| int u . v dS (Eq. g0 without its weight),
   * in mm.
   */
  double
  design_surface_mean(const HyperelasticProblem         &problem,
                      const HyperelasticProblem::Vector &a,
                      const std::function<Tensor<1, 3>(const Point<3> &)> &v);
} // namespace softopt

#endif
