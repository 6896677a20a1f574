#include <deal.II/base/exceptions.h>

#include <softopt/base/step_failure.h>
#include <softopt/path/arclength.h>
#include <softopt/path/path_following.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

namespace softopt
{
  void
  PathFollowing::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Path following",
                      "load control",
                      Patterns::Selection("load control|arclength"),
                      "load control: the load factor rises step by step, "
                      "cheap, but stops at a limit point (a pressure "
                      "maximum). arclength: Crisfield's spherical arclength "
                      "method, which follows the path through limit points "
                      "onto descending branches. The load increments below "
                      "set the arclength through the initial linear response "
                      "(see doc/theory.md).");
    prm.declare_entry("Arclength load factor weight",
                      "1",
                      Patterns::Double(0),
                      "The weight w of the load factor in the arclength "
                      "constraint |Delta u|^2 + (w |u_f| Delta lambda)^2 = "
                      "alpha^2, u_f the initial displacement per unit load "
                      "factor (dimensionless; 0: a cylindrical constraint).");
    prm.declare_entry("Initial load increment",
                      "1",
                      Patterns::Double(1e-12, 1),
                      "The first load factor increment (at most the maximum "
                      "one; halved until Newton "
                      "converges). Without a limit point the equilibrium at a "
                      "target does not depend on the path, so one large "
                      "step is cheapest; smaller maximum increments give "
                      "more rows in load_path.csv.");
    prm.declare_entry("Minimum load increment",
                      "1e-4",
                      Patterns::Double(1e-14, 1),
                      "A step that fails is halved; below this increment the "
                      "run stops and reports the last converged load factor.");
    prm.declare_entry("Maximum load increment",
                      "1",
                      Patterns::Double(1e-12),
                      "The load factor increment never grows beyond this.");
    prm.declare_entry("Arclength maximum turning angle",
                      "10",
                      Patterns::Double(0.01, 60),
                      "Arclength step control (degrees): the angle between a "
                      "step's predictor and its converged increment, about "
                      "the curvature of the path times the arclength, stays "
                      "near this. Steps that turn more than twice as far are "
                      "redone shorter, the next step shrinks or grows by the "
                      "ratio (at most 1.5 times). Smaller: more rows where "
                      "the response bends, as at a pressure maximum.");
    prm.declare_entry("Arclength maximum state change",
                      "0.25",
                      Patterns::Double(1e-6),
                      "Arclength step control (dimensionless): the change "
                      "of the displacement in one step, |Delta u|, stays "
                      "below this multiple of the linear response at rest "
                      "to the full load, |u_f^0|; it also sets the first "
                      "arclength if that is smaller than the initial load "
                      "increment's. Smaller: more rows where the part "
                      "deforms much at little change of the load, as on a "
                      "descending branch.");
    prm.declare_entry("Load control at a limit point",
                      "arclength",
                      Patterns::Selection("arclength|stop"),
                      "What load control does when a step fails three times "
                      "from one converged point past the first, as at a "
                      "pressure maximum. arclength: the rest of the path is "
                      "followed with the arclength method, through the limit "
                      "point; a target above it is reached where the path "
                      "first crosses it, on the branch a part inflated from "
                      "rest snaps to (doc/theory.md). stop: the path stops "
                      "there (after halving down to the minimum increment).");
    prm.declare_entry("Maximum number of steps",
                      "200",
                      Patterns::Integer(1),
                      "The path stops after this many converged steps.");
  }



  void
  PathFollowing::Parameters::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    method = prm.get("Path following") == "arclength" ? Method::arclength :
                                                         Method::load_control;
    load_factor_weight  = prm.get_double("Arclength load factor weight");
    initial_increment    = prm.get_double("Initial load increment");
    minimum_increment    = prm.get_double("Minimum load increment");
    maximum_increment    = prm.get_double("Maximum load increment");
    maximum_steps        = prm.get_integer("Maximum number of steps");
    arclength_past_limit_points =
      prm.get("Load control at a limit point") == "arclength";
    maximum_turning_angle =
      prm.get_double("Arclength maximum turning angle") * M_PI / 180.;
    maximum_state_change = prm.get_double("Arclength maximum state change");

    AssertThrow(minimum_increment <= std::min(initial_increment, maximum_increment),
                ExcMessage(input.where("Loading", "Minimum load increment") +
                           ": must not exceed the initial or the maximum load "
                           "increment."));
  }



  PathFollowing::PathFollowing()
    : PathFollowing(Parameters())
  {}



  PathFollowing::PathFollowing(const Parameters &parameters)
    : parameters(parameters)
  {}



  PathFollowing::Result
  PathFollowing::run(EquilibriumProblem        &problem,
                     const NewtonSolver        &newton,
                     const std::vector<double> &targets_in,
                     const Observer            &observer,
                     const ConditionalOStream  &log) const
  {
    std::vector<double> targets = targets_in;
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    Assert(!targets.empty() && targets.front() > 0, ExcInternalError());

    using Point = Arclength::Point;
    Result                     result;
    Point                      current{problem.create_vector(), 0., 0, 0.};
    Point                      previous = current;
    bool                       has_previous = false;
    std::unique_ptr<Arclength> arclength;
    if (parameters.method == Method::arclength)
      {
        arclength = std::make_unique<Arclength>(
          problem, newton, current.a, 0., parameters.load_factor_weight);
        current.negative_pivots = int(problem.n_negative_pivots());
      }
    // A limit point between two converged points: the load rate changes
    // sign, and so does one eigenvalue of the tangent (its inertia changes).
    // Where the path bends sharply, as where a bulge forms within a small
    // range of the load, the tangent at the new point can point backwards
    // along the chord with the tangent stiffness still positive definite:
    // that is no limit point (doc/theory.md, "Limit points and the
    // tangent's inertia").
    const auto limit_point_between = [&](const Point &from, const Point &to) {
      if ((from.load_rate > 0) == (to.load_rate > 0))
        return false;
      if (from.negative_pivots < 0 || to.negative_pivots < 0 ||
          from.negative_pivots != to.negative_pivots)
        return true;
      log << "    the load rate changed sign between load factors "
          << from.load_factor << " and " << to.load_factor
          << " without a change of the tangent's inertia (" << to.negative_pivots
          << " negative pivots): a sharp bend of the path, no limit point"
          << std::endl;
      return false;
    };
    // The step size: a load increment, or its arclength.
    const auto size_of = [&](const double load_increment) {
      return arclength ? arclength->arclength_of(load_increment) : load_increment;
    };
    double size = size_of(std::min(parameters.initial_increment, parameters.maximum_increment));
    if (arclength)
      size = std::min(size,
                      arclength->arclength_of_state_change(
                        parameters.maximum_state_change));
    unsigned int next_target = 0;
    unsigned int failures    = 0; // of steps from the current point
    unsigned int arclength_failures = 0; // failed or redone arclength steps from it

    for (unsigned int step = 1; result.stop_reason.empty(); ++step)
      {
        if (step > parameters.maximum_steps)
          {
            result.stop_reason = "reached the maximum number of steps (" +
                                 std::to_string(parameters.maximum_steps) + ")";
            break;
          }
        const double target = targets[next_target];

        // Propose the next point; a step that crosses the target is redone
        // with load control from the last converged point, so that it lands
        // on the target exactly.
        Point  next;
        bool   lands   = false;
        double control = 1.5; // how the arclength may change (step_control)
        try
          {
            if (arclength)
              {
                // After a failed or redone step from this point, the
                // tangent predictor: the secant through a long last step
                // can miss a sharp bend by an angle no shorter step
                // reduces.
                next = arclength->step(current,
                                       has_previous ? &previous : nullptr,
                                       size,
                                       arclength_failures > 0);
                control = step_control(next);
                lands   = current.load_factor < target &&
                        next.load_factor >= target;
                // Turned or moved more than twice as far as allowed, or
                // crossed the target past a maximum of the load (landing
                // would start Newton beyond the fold): shorter, unless
                // that falls below the minimum arclength.
                const double shorter =
                  control < 0.5           ? std::max(0.2, 0.9 * control) :
                  lands && next.load_rate <= 0 ? 0.5 :
                                                 1.;
                if (shorter < 1 &&
                    size * shorter >= size_of(parameters.minimum_increment))
                  {
                    size *= shorter;
                    ++arclength_failures;
                    log << "    step " << step << " from load factor "
                        << current.load_factor << " turned "
                        << next.turning_angle * 180 / M_PI
                        << " degrees, changed the state by "
                        << next.state_change
                        << " |u_f^0|: redone shorter" << std::endl;
                    --step;
                    continue;
                  }
                if (lands)
                  {
                    next = load_controlled_step(problem,
                                                newton,
                                                current,
                                                &next,
                                                target);
                    next.load_rate = 1; // crossed upwards, first crossing
                  }
              }
            else
              {
                lands = size >= target - current.load_factor;
                next  = load_controlled_step(
                  problem,
                  newton,
                  current,
                  has_previous ? &previous : nullptr,
                  lands ? target : current.load_factor + size);
              }
          }
        catch (const StepFailure &failure)
          {
            size /= 2;
            if (arclength)
              ++arclength_failures;
            log << "    step " << step << " failed from load factor "
                << current.load_factor << ": " << failure.what()
                << "; halving the step" << std::endl;
            --step;
            // Three failures in a row, or steps that converge ever shorter
            // until below the minimum increment (each success resets the
            // count): load control cannot go on.
            if (!arclength && parameters.arclength_past_limit_points &&
                has_previous &&
                (++failures == 3 || size < parameters.minimum_increment))
              {
                // Load control cannot pass a limit point: arclength, scaled
                // by the linear response at rest as from the start, goes on
                // along the secant through the last two converged points.
                arclength = std::make_unique<Arclength>(problem,
                                                        newton,
                                                        problem.create_vector(),
                                                        0.,
                                                        parameters.load_factor_weight);
                size                  = arclength->arclength_of(size);
                result.arclength_from = current.load_factor;
                log << "    load control cannot go on above load factor "
                    << current.load_factor << " (a limit point?): the path "
                    << "goes on with arclength" << std::endl;
                continue;
              }
            if (size < size_of(parameters.minimum_increment))
              {
                std::ostringstream reason;
                reason << "the load step could not be solved above load "
                       << "factor " << current.load_factor;
                if (parameters.full_load_kPa > 0)
                  reason << " (" << current.load_factor * parameters.full_load_kPa
                         << " kPa)";
                reason << ", the last converged one, even with the minimum "
                       << (arclength ? "arclength" : "load increment")
                       << (arclength || parameters.arclength_past_limit_points ?
                             "" :
                             ". If the pressure has a maximum there (a limit "
                             "point), set \"Load control at a limit point = "
                             "arclength\" or \"Path following = arclength\"")
                       << ". The last attempt: " << failure.what();
                result.stop_reason = reason.str();
                result.failed      = true;
              }
            continue;
          }
        failures           = 0;
        arclength_failures = 0;

        // Grow the step when Newton converges fast, shrink it when not; a
        // step shortened to land on a target does not shrink the next one.
        // An arclength step also adapts to how the path bends.
        double factor = next.iterations <= 3 ? 1.5 : next.iterations >= 7 ? 0.7 : 1.;
        factor = std::min(factor, control);
        size   = std::clamp(size * factor,
                          size_of(parameters.minimum_increment),
                          size_of(parameters.maximum_increment));

        // A maximum of the load before the last target: a part inflated
        // from rest snaps through there, to a state far from this path.
        const bool limit_point = arclength && limit_point_between(current, next);
        if (parameters.stop_at_limit_point && limit_point && current.load_rate > 0)
          {
            std::ostringstream reason;
            reason << "the pressure has a maximum (a limit point) between load "
                   << "factors " << current.load_factor << " and "
                   << next.load_factor;
            if (parameters.full_load_kPa > 0)
              reason << " (" << current.load_factor * parameters.full_load_kPa
                     << " and " << next.load_factor * parameters.full_load_kPa
                     << " kPa)";
            reason << ", below the target load factor " << target
                   << ": inflated from rest, the part snaps through there.";
            result.stop_reason            = reason.str();
            result.failed                 = true;
            result.stopped_at_limit_point = true;
            break;
          }

        // The load rate changed sign between the two points: a limit point
        // lies between them, located and reported before the next point.
        if (limit_point)
          {
            // (Not reported if not one point between them converged.)
            if (const auto limit = locate_limit_point(*arclength, current, next, log))
              {
                result.limit_load_factors.push_back(limit->load_factor);
                PathPoint point{step++, limit->load_factor, limit->iterations,
                                limit->residual_norm, false, true};
                result.stop_reason = observer(point, limit->a);
                if (!result.stop_reason.empty())
                  {
                    result.last = point;
                    break;
                  }
              }
          }

        previous     = std::move(current);
        current      = std::move(next);
        has_previous = true;
        result.last  = {step,
                       current.load_factor,
                       current.iterations,
                       current.residual_norm,
                       lands};
        if (lands)
          {
            result.target_load_factors.push_back(current.load_factor);
            result.target_states.push_back(current.a);
          }
        result.stop_reason = observer(result.last, current.a);
        // A path that turns back to zero load does not reach the target
        // on this branch (an arclength path after a fold, say).
        if (result.stop_reason.empty() && current.load_factor <= 0)
          {
            result.stop_reason = "the path returned to zero load (load factor " +
                                 std::to_string(current.load_factor) +
                                 ") without reaching load factor " +
                                 std::to_string(target);
            result.failed = true;
          }
        if (result.stop_reason.empty() && lands &&
            ++next_target == targets.size())
          result.stop_reason = reached_last_target;
      }
    return result;
  }



  double
  PathFollowing::step_control(const Arclength::Point &next) const
  {
    double control = 1.5;
    if (next.turning_angle > 0)
      control = std::min(control, parameters.maximum_turning_angle / next.turning_angle);
    if (next.state_change > 0)
      control = std::min(control, parameters.maximum_state_change / next.state_change);
    return control;
  }



  std::optional<Arclength::Point>
  PathFollowing::locate_limit_point(const Arclength          &arclength,
                                    const Arclength::Point   &from,
                                    const Arclength::Point   &to,
                                    const ConditionalOStream &log)
  {
    // The load rate is a smooth function of the distance from @p from along
    // the path, of opposite signs at both ends: Illinois' regula falsi
    // brackets its zero. Where the load is extremal its error enters the
    // load factor only quadratically.
    const double chord = arclength.distance(from, to);
    double       lo = 0, hi = chord, g_lo = from.load_rate, g_hi = to.load_rate;
    std::optional<Arclength::Point> best;
    int          side = 0; // which end moved last
    for (unsigned int evaluation = 0; evaluation < 20; ++evaluation)
      {
        const double alpha = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
        Arclength::Point point;
        try
          {
            point = arclength.step_towards(from, to, alpha);
          }
        catch (const StepFailure &failure)
          {
            log << "    locating the limit point: " << failure.what() << std::endl;
            break;
          }
        if (!best || std::abs(point.load_rate) < std::abs(best->load_rate))
          best = point;
        if (std::abs(point.load_rate) < 1e-7 || hi - lo < 1e-9 * chord)
          break;
        if ((point.load_rate > 0) == (g_lo > 0))
          {
            lo   = alpha;
            g_lo = point.load_rate;
            if (side == -1)
              g_hi /= 2;
            side = -1;
          }
        else
          {
            hi   = alpha;
            g_hi = point.load_rate;
            if (side == 1)
              g_lo /= 2;
            side = 1;
          }
      }
    if (best)
      log << "    limit point at load factor " << best->load_factor
          << " (load rate " << best->load_rate << ")" << std::endl;
    return best;
  }



  Arclength::Point
  PathFollowing::load_controlled_step(EquilibriumProblem      &problem,
                                      const NewtonSolver      &newton,
                                      const Arclength::Point  &current,
                                      const Arclength::Point  *guide,
                                      const double             load_factor)
  {
    // Predictor: the line through the last converged point and @p guide
    // (the previous point, or an arclength step past the target).
    Arclength::Point next{current.a, load_factor, 0, 0.};
    if (guide != nullptr && guide->load_factor != current.load_factor)
      {
        Arclength::Vector direction = guide->a;
        direction -= current.a;
        next.a.add((load_factor - current.load_factor) /
                     (guide->load_factor - current.load_factor),
                   direction);
      }
    const auto result  = newton.solve(problem, next.a, load_factor);
    next.iterations    = result.iterations;
    next.residual_norm = result.residual_norm;
    return next;
  }
} // namespace softopt
