#ifndef softopt_path_newton_solver_h
#define softopt_path_newton_solver_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/path/equilibrium_problem.h>

namespace softopt
{
  /**
   * Newton's method for r_a(a, lambda) = 0 at a fixed load factor (load
   * control), and the convergence test that arclength shares (subsection
   * "Newton").
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
     * Solves r_a(a, lambda) = 0 starting from @p a. On return the tangent
     * at the converged state is assembled (not yet factorized). Throws
     * StepFailure when the iteration does not converge.
     */
    Result
    solve(EquilibriumProblem &problem,
          EquilibriumProblem::Vector &a,
          const double                load_factor) const;

    /** Is |r| small against the external load |lambda P|? */
    bool
    converged(const double residual_norm, const double load_norm) const;

    /** Relative residual tolerance. */
    double tolerance = 1e-8;

    /** Iterations before a step counts as failed. */
    unsigned int max_iterations = 12;
  };
} // namespace softopt

#endif
