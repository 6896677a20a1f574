#ifndef softopt_path_equilibrium_problem_h
#define softopt_path_equilibrium_problem_h

#include <deal.II/lac/petsc_vector.h>

namespace softopt
{
  using namespace dealii;

  /**
   * What path following sees of a discretized equilibrium problem
   * r_a(a, lambda) = 0 (Eq. res): residuals, the load vector
   * P = dr_a/dlambda, the tangent K = dr_a/da and solves with it.
   * No physics.
   */
  class EquilibriumProblem
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    virtual ~EquilibriumProblem() = default;

    /** A zero vector of unknowns (the state at lambda = 0). */
    virtual Vector
    create_vector() const = 0;

    /**
     * The residual r_a(a, lambda) and the load vector P(a) (Eq. Newt2); with
     * @p with_tangent also the tangent K(a, lambda), kept for factorize().
     * Constrained entries are zero. Throws StepFailure if @p a is not an
     * admissible state (an inverted element).
     */
    virtual void
    assemble(const Vector &a,
             const double  load_factor,
             Vector       &residual,
             Vector       &load,
             const bool    with_tangent) = 0;

    /** Factorizes the tangent of the last assemble(). */
    virtual void
    factorize() = 0;

    /** x = K^{-1} b for the tangent of the last assemble(), as the problem
     * chooses (by default a fresh factorization; a problem may instead
     * iterate on a kept one, to a relative residual well below Newton's
     * reduction per step). For Newton steps. */
    virtual void
    solve_tangent(const Vector &b, Vector &x)
    {
      factorize();
      solve(b, x);
    }

    /** As solve_tangent(), for a Newton step whose previous step's
     * factorization is of a nearby tangent (Newton's quadratic phase): a
     * problem may iterate on that factorization instead of factorizing. */
    virtual void
    solve_nearby_tangent(const Vector &b, Vector &x)
    {
      solve_tangent(b, x);
    }

    /** x = K^{-1} b with the last factorization (constrained entries zero).
     * For a condensed system, K, b and x hold only the retained unknowns. */
    virtual void
    solve(const Vector &b, Vector &x) const = 0;

    /**
     * a <- a + da for an increment da of the retained unknowns that solves
     * K da = -r (with r from the last assemble()); a condensed problem also
     * recovers its condensed unknowns here.
     */
    virtual void
    update(Vector &a, const Vector &da) const = 0;

    /** Zeroes the condensed unknowns of @p v, leaving the retained ones
     * (the unknowns that enter the arclength constraint). */
    virtual void
    zero_condensed(Vector &v) const = 0;

    /** Negative pivots of the last factorization (the sign of det K). */
    virtual unsigned int
    n_negative_pivots() const = 0;
  };
} // namespace softopt

#endif
