#include <softopt/base/step_failure.h>
#include <softopt/path/newton_solver.h>

#include <cmath>
#include <sstream>

namespace softopt
{
  void
  NewtonSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Residual tolerance",
                      "1e-8",
                      Patterns::Double(1e-15, 1e-1),
                      "Newton stops when the l2 norm of the residual (N) is "
                      "below this fraction of the l2 norm of the external "
                      "load lambda P (N), or when a correction is below "
                      "round-off (its energy |da . r| under 1e-4 times the "
                      "square of this fraction of the load's work lambda P "
                      ". a: near incompressibility the residual stalls in "
                      "the stiff volumetric modes).");
    prm.declare_entry("Maximum iterations",
                      "12",
                      Patterns::Integer(1, 200),
                      "Newton iterations after which a load step counts as "
                      "failed and is cut back.");
    prm.leave_subsection();
  }



  void
  NewtonSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    tolerance      = prm.get_double("Residual tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
  }



  NewtonSolver::Monitor::Monitor(const NewtonSolver &newton)
    : newton(newton)
  {}



  bool
  NewtonSolver::Monitor::converged(const unsigned int iteration,
                                   const double       norm,
                                   const double       load_norm)
  {
    if (!std::isfinite(norm))
      throw StepFailure("the residual is not finite");
    if (norm <= newton.tolerance * load_norm || norm == 0.)
      return true;
    if (iteration == 1)
      first_update_norm = norm;
    std::ostringstream reason;
    if (iteration >= newton.max_iterations)
      reason << "Newton did not converge in " << newton.max_iterations
             << " iterations (|r| = " << norm << " N, |lambda P| = "
             << load_norm << " N)";
    else if (iteration >= 3 && norm > previous_norm && norm > first_update_norm)
      reason << "Newton diverges (|r| = " << norm << " N after " << iteration
             << " iterations)";
    if (!reason.str().empty())
      throw StepFailure(reason.str());
    previous_norm = norm;
    return false;
  }



  bool
  NewtonSolver::Monitor::negligible(const unsigned int iteration,
                                    const double       residual_norm,
                                    const double       load_norm,
                                    const double       correction_energy,
                                    const double       work) const
  {
    // r^T K^-1 r weighs the residual by the compliance: a residual left in
    // the stiff volumetric modes (kappa / mu = 2 (1 + nu) / (3 (1 - 2 nu)),
    // 1.7e8 at nu = 0.49999999) moves nothing. At a residual of
    // tolerance |lambda P| in the soft modes the ratio is about 1e-2
    // tolerance^2 (the sphere at nu = 0.4999: 6e-19 for 1e-8); round-off
    // stalls |r| near 4e-8 |lambda P| at nu = 0.49999999 with the ratio at
    // 4e-24. Only after a first update: iteration 0 follows a load change;
    // and only with |r| near the tolerance: on an unstable branch K is
    // indefinite and r^T K^-1 r can cancel.
    return iteration > 0 && work > 0 &&
           residual_norm <= 1e3 * newton.tolerance * load_norm &&
           correction_energy <= 1e-4 * newton.tolerance * newton.tolerance * work;
  }



  NewtonSolver::Result
  NewtonSolver::solve(EquilibriumProblem         &problem,
                      EquilibriumProblem::Vector &a,
                      const double                load_factor) const
  {
    EquilibriumProblem::Vector residual, load, increment;
    Monitor                    monitor(*this);
    for (unsigned int iteration = 0;; ++iteration)
      {
        problem.assemble(a, load_factor, residual, load, true);
        const double norm      = residual.l2_norm();
        const double load_norm = std::abs(load_factor) * load.l2_norm();
        if (monitor.converged(iteration, norm, load_norm))
          return {iteration, norm};
        residual *= -1.;
        // In Newton's quadratic phase the last step's factorization is of
        // a nearby tangent.
        if (iteration > 0 && norm <= quadratic_phase * load_norm)
          problem.solve_nearby_tangent(residual, increment);
        else
          problem.solve_tangent(residual, increment);
        // At the round-off floor the increment is noise: keep a, whose
        // tangent is the one assembled.
        if (monitor.negligible(iteration,
                               norm,
                               load_norm,
                               std::abs(increment * residual),
                               std::abs(load_factor * (load * a))))
          return {iteration, norm};
        problem.update(a, increment);
      }
  }
} // namespace softopt
