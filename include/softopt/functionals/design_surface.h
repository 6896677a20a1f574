#ifndef softopt_functionals_design_surface_h
#define softopt_functionals_design_surface_h

#include <softopt/functionals/direction_field.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

namespace softopt
{
  /**
   * The integrals over the design surface dOmega^d, in the design
   * configuration X, that objectives (Eq. g0) and constraints (Eq.
   * constraint) are made of: |dOmega^d| = int dS, int u . v dS and
   * int (u . v)^2 dS, and on request their derivatives in the state a (on
   * the hyperelastic DoFs) and in the positions X (on the design DoFs):
   * through dS and v(X), the terms of Eqs. g0sens-dnhatdshape2.
   */
  struct DesignSurfaceIntegrals
  {
    double area = 0, linear = 0, quadratic = 0;
    PETScWrappers::MPI::Vector d_area_dX, d_linear_dX, d_quadratic_dX;
    PETScWrappers::MPI::Vector d_linear_da, d_quadratic_da;
  };

  DesignSurfaceIntegrals
  integrate_over_design_surface(const HyperelasticProblem        &problem,
                                const DesignConfiguration        &design,
                                const PETScWrappers::MPI::Vector &a,
                                const DirectionField             &v,
                                const bool                        derivatives);

  /**
   * The cavity volume V_c^p = -1/3 int x . n_c da over the pressure boundary
   * (the paper's footnote, divergence theorem; n_c points out of the solid)
   * in mm^3, and on request its derivatives in a and X (which are equal: V
   * depends on x = X + u only).
   */
  double
  cavity_volume(const HyperelasticProblem        &problem,
                const DesignConfiguration        &design,
                const PETScWrappers::MPI::Vector &a,
                PETScWrappers::MPI::Vector       *d_da = nullptr,
                PETScWrappers::MPI::Vector       *d_dX = nullptr);
} // namespace softopt

#endif
