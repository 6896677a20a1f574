#include <softopt/base/step_failure.h>
#include <softopt/path/arclength.h>

#include <cmath>

namespace softopt
{
  Arclength::Arclength(EquilibriumProblem &problem,
                       const NewtonSolver &newton,
                       const Vector       &a,
                       const double        load_factor,
                       const double        load_factor_weight)
    : problem(problem)
    , newton(newton)
  {
    Vector r, P, u_f;
    problem.assemble(a, load_factor, r, P, true);
    problem.factorize();
    P *= -1.;
    problem.solve(P, u_f);
    psi_squared       = std::pow(load_factor_weight, 2) * (u_f * u_f);
    initial_load_norm = P.l2_norm();
  }



  double
  Arclength::arclength_of(const double load_increment) const
  {
    // Along the linear response Delta u = Delta lambda u_f^0, so
    // alpha^2 = Delta lambda^2 (|u_f^0|^2 + psi^2) = Delta lambda^2 psi^2 (1 + 1/w^2);
    // with w = 1 this is sqrt(2) psi Delta lambda.
    return std::abs(load_increment) * std::sqrt(2. * psi_squared);
  }



  Arclength::Point
  Arclength::step(const Point &current, const Point *previous, const double alpha) const
  {
    Vector r, P, du_r, du_f;
    Point  next{current.a, current.load_factor, 0, 0};

    // Predictor: (Delta u, Delta lambda) at distance alpha.
    Vector Du;
    double Dl = 0;
    if (previous != nullptr)
      {
        Vector Da = current.a;
        Da -= previous->a;
        Du = Da;
        problem.zero_condensed(Du);
        Dl = current.load_factor - previous->load_factor;
        const double s = alpha / std::sqrt(Du * Du + psi_squared * Dl * Dl);
        next.a.add(s, Da);
        Du *= s;
        Dl *= s;
      }
    else
      {
        problem.assemble(current.a, current.load_factor, r, P, true);
        problem.factorize();
        P *= -1.;
        problem.solve(P, du_f);
        Dl = alpha / std::sqrt(du_f * du_f + psi_squared);
        Du = du_f;
        Du *= Dl;
        problem.update(next.a, Du);
      }
    next.load_factor = current.load_factor + Dl;
    // The predictor's increment: a converged step must go on along it.
    const Vector Du_0 = Du;
    const double Dl_0 = Dl;

    NewtonSolver::Monitor monitor(newton);
    for (unsigned int iteration = 0;; ++iteration)
      {
        problem.assemble(next.a, next.load_factor, r, P, true);
        const double norm = r.l2_norm();
        // The load scale never falls below a millionth of the initial one,
        // so that a path through lambda = 0 stays measurable.
        const double load_norm =
          std::max(std::abs(next.load_factor) * P.l2_norm(),
                   1e-6 * initial_load_norm);
        if (monitor.converged(iteration, norm, load_norm))
          {
            // Near a sharp fold the corrector can converge to a point behind
            // the current one; the path would then trace itself backwards.
            if (previous != nullptr && Du * Du_0 + psi_squared * Dl * Dl_0 <= 0)
              throw StepFailure("the step turned back along the path");
            next.iterations    = iteration;
            next.residual_norm = norm;
            return next;
          }

        problem.factorize();
        r *= -1.;
        P *= -1.;
        problem.solve(r, du_r);
        problem.solve(P, du_f);

        // |Du + du_r + dl du_f|^2 + psi^2 (Dl + dl)^2 = alpha^2
        Vector v = Du;
        v += du_r;
        const double a1 = du_f * du_f + psi_squared;
        const double a2 = 2. * (du_f * v + psi_squared * Dl);
        const double a3 = v * v + psi_squared * Dl * Dl - alpha * alpha;
        const double discriminant = a2 * a2 - 4. * a1 * a3;
        if (discriminant < 0)
          throw StepFailure("the arclength constraint has no real root");
        const double root[2] = {(-a2 + std::sqrt(discriminant)) / (2. * a1),
                                (-a2 - std::sqrt(discriminant)) / (2. * a1)};
        // Crisfield: the root whose new increment is closest in angle to
        // the current increment.
        const auto cosine = [&](const double dl) {
          return (v * Du) + dl * (du_f * Du) + psi_squared * (Dl + dl) * Dl;
        };
        const double dl = cosine(root[0]) >= cosine(root[1]) ? root[0] : root[1];

        Vector du = du_r;
        du.add(dl, du_f);
        problem.update(next.a, du);
        Du += du;
        Dl += dl;
        next.load_factor = current.load_factor + Dl;
      }
  }
} // namespace softopt
