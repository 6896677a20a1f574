#ifndef softopt_path_arclength_h
#define softopt_path_arclength_h

#include <softopt/path/equilibrium_problem.h>
#include <softopt/path/newton_solver.h>

namespace softopt
{
  /**
   * Crisfield's spherical arclength method (Eq. arclength; Crisfield 1997):
   * each step finds (a, lambda) on the equilibrium path at the distance
   *   Delta u . Delta u + psi^2 Delta lambda^2 = alpha^2
   * from the last converged point, where u are the retained (condensed)
   * unknowns. The load factor is scaled by psi = w |u_f^0|, with
   * u_f^0 = -K^{-1} P the displacement per unit load factor of the linear
   * response at the start: both terms then have the units and the mesh
   * dependence of a displacement norm, and w (default 1) weighs them.
   *
   * Per iteration the two solves K da_r = -r and K da_f = -P share one
   * factorization; Crisfield's quadratic gives dlambda, and of its two
   * roots the one whose new increment makes the smaller angle with the
   * current one is taken.
   */
  class Arclength
  {
  public:
    using Vector = EquilibriumProblem::Vector;

    /** Sets the scaling from the linear response at the state (a, lambda)
     * (one assembly and factorization). */
    Arclength(EquilibriumProblem &problem,
              const NewtonSolver &newton,
              const Vector       &a,
              const double        load_factor,
              const double        load_factor_weight);

    /** The arclength of a step that changes lambda by @p load_increment
     * along the initial linear response. */
    double
    arclength_of(const double load_increment) const;

    /** A converged point. */
    struct Point
    {
      Vector       a;
      double       load_factor = 0;
      unsigned int iterations  = 0;
      double       residual_norm = 0;
    };

    /**
     * The next point at arclength @p alpha from the converged @p current.
     * With a @p previous converged point the predictor is the secant through
     * both (it carries the path through limit points); without, it is the
     * tangent, in the direction of increasing lambda. Throws StepFailure if
     * Newton fails or the constraint has no real root.
     */
    Point
    step(const Point &current, const Point *previous, const double alpha) const;

  private:
    EquilibriumProblem &problem;
    const NewtonSolver &newton;
    double              psi_squared;
    double              initial_load_norm;
  };
} // namespace softopt

#endif
