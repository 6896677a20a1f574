#ifndef softopt_shape_residual_shape_derivative_h
#define softopt_shape_residual_shape_derivative_h

#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

namespace softopt
{
  /**
   * (dr_a/dX)^T mu on the design DoFs: the partial derivative in the
   * positions X of the condensed residual at (a, lambda), follower load
   * included, contracted with an adjoint mu on the hyperelastic DoFs (the
   * term (dr_a/dpsi)^T mu_a of Eq. adj3, with dX/dpsi = I). Element by
   * element with automatic differentiation (CellKernels); the follower load
   * depends on x = X + u only, so its X-derivative is its load stiffness
   * (Eq. shapePressureLoad).
   */
  PETScWrappers::MPI::Vector
  residual_shape_derivative(const HyperelasticProblem        &problem,
                            const DesignConfiguration        &design,
                            const PETScWrappers::MPI::Vector &a,
                            const double                      load_factor,
                            const PETScWrappers::MPI::Vector &mu);
} // namespace softopt

#endif
