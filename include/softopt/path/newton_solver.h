#ifndef softopt_path_newton_solver_h
#define softopt_path_newton_solver_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/path/equilibrium_problem.h>

namespace softopt
{
  /**
   * Newton's method for r_a(a, lambda) = 0 at a fixed load factor (load
   * control), and the convergence and failure tests that arclength shares
   * (subsection "Newton").
   */
  class NewtonSolver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** What one converged solve took. */
    struct Result
    {
      unsigned int iterations    = 0;
      double       residual_norm = 0;
    };

    /**
     * Watches one sequence of Newton iterations: says when it has converged
     * (|r| <= tolerance |lambda P|, or a correction below round-off: see
     * negligible()), and throws StepFailure when it will not
     * (a NaN, too many iterations, a residual that still grows after the
     * third iteration: the first update of a nearly incompressible body may
     * raise |r| by orders of magnitude, later growth means the step is too
     * large).
     */
    class Monitor
    {
    public:
      explicit Monitor(const NewtonSolver &newton);

      /** Called with the residual of each iterate, from iteration 0. */
      bool
      converged(const unsigned int iteration,
                const double       residual_norm,
                const double       load_norm);

      /**
       * Whether a Newton correction da = K^-1 (-r) is below what the
       * arithmetic resolves: |da . r| <= 1e-4 tolerance^2 |work|, with the
       * work lambda P . a of the load, and |r| <= 1e3 tolerance |lambda P|
       * (never at iteration 0). Near
       * incompressibility (nu >= 0.4999999) round-off holds |r| in the
       * stiff volumetric modes above tolerance |lambda P| while the
       * displacement has converged; the state before the correction is
       * then the converged one.
       */
      bool
      negligible(const unsigned int iteration,
                 const double       residual_norm,
                 const double       load_norm,
                 const double       correction_energy,
                 const double       work) const;

    private:
      const NewtonSolver &newton;
      double              previous_norm     = 0;
      double              first_update_norm = 0;
    };

    /**
     * Solves r_a(a, lambda) = 0 starting from @p a by Newton's method, each
     * step solving with its own tangent: a fresh factorization
     * (EquilibriumProblem::solve_tangent), or, once |r| is below
     * quadratic_phase |lambda P| after a first step, GMRES on the last
     * step's factorization (solve_nearby_tangent; in that phase the
     * tangent has moved little, and a step saves a factorization for a few
     * solves). On return the tangent at the converged state is assembled
     * and the factorization held is of a nearby tangent. Throws StepFailure
     * when the iteration does not converge. (Modified Newton, steps with a
     * kept factorization and no Krylov method, was measured for warm starts
     * and dropped: doc/benchmarks.md.)
     */
    Result
    solve(EquilibriumProblem         &problem,
          EquilibriumProblem::Vector &a,
          const double                load_factor) const;

    /** Relative residual tolerance. */
    double tolerance = 1e-8;

    /** Iterations before a step counts as failed. */
    unsigned int max_iterations = 12;
    /** Below this |r| / |lambda P|, after a first step, Newton counts as
     * in its quadratic phase (EquilibriumProblem::solve_nearby_tangent). */
    static constexpr double quadratic_phase = 1e-2;
  };
} // namespace softopt

#endif
