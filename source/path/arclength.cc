#include <softopt/base/step_failure.h>
#include <softopt/path/arclength.h>

#include <algorithm>
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
    linear_norm_squared = u_f * u_f;
    psi_squared         = std::pow(load_factor_weight, 2) * linear_norm_squared;
    initial_load_norm   = P.l2_norm();
  }



  double
  Arclength::arclength_of(const double load_increment) const
  {
    // Along the linear response Delta u = Delta lambda u_f^0, so
    // alpha^2 = Delta lambda^2 (|u_f^0|^2 + psi^2).
    return std::abs(load_increment) * std::sqrt(linear_norm_squared + psi_squared);
  }



  double
  Arclength::arclength_of_state_change(const double state_change) const
  {
    return arclength_of(state_change);
  }



  double
  Arclength::distance(const Point &from, const Point &to) const
  {
    Vector Du = to.a;
    Du -= from.a;
    problem.zero_condensed(Du);
    const double Dl = to.load_factor - from.load_factor;
    return std::sqrt(Du * Du + psi_squared * Dl * Dl);
  }



  Arclength::Point
  Arclength::step(const Point &current,
                  const Point *previous,
                  const double alpha,
                  const bool   tangent) const
  {
    if (previous != nullptr && !tangent)
      {
        // Predictor: the secant through the last two converged points.
        Point ahead{current.a, 2 * current.load_factor - previous->load_factor};
        ahead.a.sadd(2., -1., previous->a);
        return step_towards(current, ahead, alpha);
      }

    // Predictor: the tangent K du_f = -P, oriented along the path so far
    // (or towards increasing lambda at its start).
    Vector r, P, du_f;
    problem.assemble(current.a, current.load_factor, r, P, true);
    problem.factorize();
    P *= -1.;
    problem.solve(P, du_f);
    double orientation = 1;
    if (previous != nullptr)
      {
        Vector Da = current.a;
        Da -= previous->a;
        problem.zero_condensed(Da);
        orientation = (du_f * Da + psi_squared * (current.load_factor -
                                                  previous->load_factor)) >= 0 ?
                        1. :
                        -1.;
      }
    const double Dl = orientation * alpha / std::sqrt(du_f * du_f + psi_squared);
    du_f *= Dl;
    Point predicted{current.a, current.load_factor + Dl};
    problem.update(predicted.a, du_f);
    return correct(current, std::move(predicted), du_f, Dl, alpha, previous != nullptr);
  }



  Arclength::Point
  Arclength::step_towards(const Point &current, const Point &towards, const double alpha) const
  {
    Vector Du = towards.a;
    Du -= current.a;
    problem.zero_condensed(Du);
    const double Dl = towards.load_factor - current.load_factor;
    const double s  = alpha / std::sqrt(Du * Du + psi_squared * Dl * Dl);
    Du *= s;
    // The whole state, condensed unknowns too, moves along the chord.
    Point predicted{current.a, current.load_factor + s * Dl};
    predicted.a.sadd(1. - s, s, towards.a);
    return correct(current, std::move(predicted), Du, s * Dl, alpha, true);
  }



  Arclength::Point
  Arclength::correct(const Point &current,
                     Point        next,
                     Vector       Du,
                     double       Dl,
                     const double alpha,
                     const bool   secant) const
  {
    Vector r, P, du_r, du_f;
    // The predictor's increment: a converged step must go on along it.
    const Vector Du_0 = Du;
    const double Dl_0 = Dl;
    bool         have_tangent = false;

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
        const auto converged = [&]() -> Point {
          // Near a sharp fold the corrector can converge to a point behind
          // the current one; the path would then trace itself backwards.
          const double along = Du * Du_0 + psi_squared * Dl * Dl_0;
          if (secant && along <= 0)
            throw StepFailure("the step turned back along the path");
          if (!have_tangent)
            {
              problem.factorize();
              P *= -1.;
              problem.solve(P, du_f);
            }
          next.negative_pivots = int(problem.n_negative_pivots());
          // The tangent (du_f, 1) of the last iterate, oriented along the
          // step (Newton's last update is far below the step).
          const double orientation = (du_f * Du + psi_squared * Dl) >= 0 ? 1. : -1.;
          next.load_rate =
            orientation / std::sqrt(1. + (du_f * du_f) / linear_norm_squared);
          next.turning_angle = std::acos(std::clamp(
            along / std::sqrt((Du * Du + psi_squared * Dl * Dl) *
                              (Du_0 * Du_0 + psi_squared * Dl_0 * Dl_0)),
            -1.,
            1.));
          next.state_change  = Du.l2_norm() / std::sqrt(linear_norm_squared);
          next.iterations    = iteration;
          next.residual_norm = norm;
          return next;
        };
        if (monitor.converged(iteration, norm, load_norm))
          return converged();

        problem.factorize();
        r *= -1.;
        P *= -1.;
        problem.solve(r, du_r);
        problem.solve(P, du_f);
        have_tangent = true;
        // P is -P here: the work lambda P . a and the correction's energy.
        if (monitor.negligible(iteration,
                               norm,
                               load_norm,
                               std::abs(du_r * r),
                               std::abs(next.load_factor * (P * next.a))))
          return converged();

        // |Du + du_r + dl du_f|^2 + psi^2 (Dl + dl)^2 = alpha^2
        Vector v = Du;
        v += du_r;
        const double a1 = du_f * du_f + psi_squared;
        const double a2 = 2. * (du_f * v + psi_squared * Dl);
        const double a3 = v * v + psi_squared * Dl * Dl - alpha * alpha;
        const double discriminant = a2 * a2 - 4. * a1 * a3;
        double       dl           = -a2 / (2. * a1);
        if (discriminant >= 0)
          {
            const double root[2] = {dl + std::sqrt(discriminant) / (2. * a1),
                                    dl - std::sqrt(discriminant) / (2. * a1)};
            // Crisfield: the root whose new increment is closest in angle
            // to the current increment.
            const auto cosine = [&](const double dl) {
              return (v * Du) + dl * (du_f * Du) + psi_squared * (Dl + dl) * Dl;
            };
            dl = cosine(root[0]) >= cosine(root[1]) ? root[0] : root[1];
          }
        // Else the corrected state misses the sphere for every dlambda (a
        // large residual correction near a fold): the real part of the
        // complex roots, the iterate closest to the sphere; the next
        // iterations come back onto it, and a step that never does fails
        // in Newton.

        Vector du = du_r;
        du.add(dl, du_f);
        problem.update(next.a, du);
        Du += du;
        Dl += dl;
        next.load_factor = current.load_factor + Dl;
      }
  }
} // namespace softopt
