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
   *
   * Each converged point also carries what step control and the location
   * of limit points need (doc/theory.md, "Step control"): the angle by
   * which the step turned away from its predictor, the change of the state
   * relative to the linear response, and the sign-carrying load rate
   * d lambda / ds of the path there, which vanishes at a limit point.
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

    /** The arclength of a step along the initial linear response whose
     * displacement change is @p state_change times |u_f^0|. */
    double
    arclength_of_state_change(const double state_change) const;

    /** A converged point. */
    struct Point
    {
      Vector       a;
      double       load_factor = 0;
      unsigned int iterations  = 0;
      double       residual_norm = 0;
      /** The load component of the unit tangent, oriented along the path,
       * in units of the displacement per load factor at rest:
       * (d lambda / ds) / sqrt(1 + |da_f|^2 / |u_f^0|^2) with
       * K da_f = -P here. 1/sqrt(2) at rest, 0 at a limit point, negative
       * where the load falls along the path. */
      double load_rate = 1;
      /** The angle (radians) between the step's predictor and its
       * converged increment: about the curvature of the path times the
       * arclength. */
      double turning_angle = 0;
      /** |Delta u| / |u_f^0| of the step. */
      double state_change = 0;
      /** Negative pivots of the tangent's factorization at the point (at
       * Newton's last iterate; -1: not known). A limit point, where one
       * eigenvalue of the tangent passes zero, changes it by one. */
      int negative_pivots = -1;
    };

    /**
     * The next point at arclength @p alpha from the converged @p current.
     * With a @p previous converged point the predictor is the secant through
     * both (it carries the path through limit points); without, it is the
     * tangent, in the direction of increasing lambda. With @p tangent the
     * predictor is the tangent at @p current also after the first step,
     * oriented along the secant (one factorization more): past a fold
     * sharper than the last step the secant points away from the path,
     * the tangent does not. Throws StepFailure if
     * Newton fails.
     */
    Point
    step(const Point &current,
         const Point *previous,
         const double alpha,
         const bool   tangent = false) const;

    /** The point at arclength @p alpha from @p current, predicted along the
     * chord from @p current to @p towards (a point of the path ahead). */
    Point
    step_towards(const Point &current, const Point &towards, const double alpha) const;

    /** The distance of two states in the arclength metric. */
    double
    distance(const Point &from, const Point &to) const;

  private:
    /** Crisfield's corrector from the predicted point @p next, the
     * increment (Du, Dl) of arclength alpha from @p current; checks that
     * the step does not turn back if @p secant. */
    Point
    correct(const Point &current,
            Point        next,
            Vector       Du,
            double       Dl,
            const double alpha,
            const bool   secant) const;


    EquilibriumProblem &problem;
    const NewtonSolver &newton;
    double              psi_squared;
    /** |u_f^0|^2: the linear response at rest, per unit load factor. */
    double              linear_norm_squared;
    double              initial_load_norm;
  };
} // namespace softopt

#endif
