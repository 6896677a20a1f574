#include <deal.II/base/exceptions.h>

#include <softopt/base/step_failure.h>
#include <softopt/path/path_following.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace softopt
{
  void
  PathFollowing::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("Pressure",
                      "15",
                      Patterns::Double(),
                      "The cavity pressure (relative to the atmosphere) at "
                      "load factor 1, in kPa.");
    prm.declare_entry("Target load factors",
                      "1",
                      Patterns::List(Patterns::Double(0), 1),
                      "Load factors at which the path must land exactly (the "
                      "last one ends the path); dimensionless, pressure = "
                      "load factor x Pressure.");
    prm.declare_entry("Initial load increment",
                      "1",
                      Patterns::Double(1e-12, 1),
                      "The first load factor increment (halved until Newton "
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
    prm.declare_entry("Maximum number of steps",
                      "200",
                      Patterns::Integer(1),
                      "The path stops after this many converged steps.");
    prm.declare_entry("Maximum cavity volume ratio",
                      "0",
                      Patterns::Double(0),
                      "The path stops once the cavity volume exceeds this "
                      "multiple of its initial volume (0: no limit).");
    prm.leave_subsection();
  }



  void
  PathFollowing::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    prm.enter_subsection("Loading");
    pressure_kPa        = prm.get_double("Pressure");
    target_load_factors = parse_doubles(prm.get("Target load factors"),
                                        input.where("Loading",
                                                    "Target load factors"));
    initial_increment    = prm.get_double("Initial load increment");
    minimum_increment    = prm.get_double("Minimum load increment");
    maximum_increment    = prm.get_double("Maximum load increment");
    maximum_steps        = prm.get_integer("Maximum number of steps");
    maximum_volume_ratio = prm.get_double("Maximum cavity volume ratio");
    prm.leave_subsection();

    for (const double t : target_load_factors)
      AssertThrow(t > 0,
                  ExcMessage(input.where("Loading", "Target load factors") +
                             ": every target load factor must be positive."));
    AssertThrow(minimum_increment <= initial_increment,
                ExcMessage(input.where("Loading", "Minimum load increment") +
                           ": must not exceed the initial load increment."));
    AssertThrow(maximum_volume_ratio == 0 || maximum_volume_ratio > 1,
                ExcMessage(input.where("Loading",
                                       "Maximum cavity volume ratio") +
                           ": must be 0 (no limit) or larger than 1."));
  }



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

    Result                     result;
    EquilibriumProblem::Vector a = problem.create_vector();
    EquilibriumProblem::Vector a_old = a, trial = a;
    double       lambda = 0, last_increment = 0, increment = initial_increment;
    unsigned int next_target = 0;

    for (unsigned int step = 1;; ++step)
      {
        if (step > maximum_steps)
          {
            result.stop_reason = "reached the maximum number of steps (" +
                                 std::to_string(maximum_steps) + ")";
            break;
          }

        // Land exactly on the next target (load control).
        const double target = targets[next_target];
        const bool   lands  = increment >= target - lambda;
        const double step_increment = lands ? target - lambda : increment;

        // Secant predictor from the last two converged states.
        trial = a;
        if (last_increment > 0)
          {
            EquilibriumProblem::Vector secant = a;
            secant -= a_old;
            trial.add(step_increment / last_increment, secant);
          }

        NewtonSolver::Result newton_result;
        try
          {
            newton_result =
              newton.solve(problem, trial, lands ? target : lambda + step_increment);
          }
        catch (const StepFailure &failure)
          {
            increment = step_increment / 2;
            log << "    step " << step << " failed at load factor "
                << lambda + step_increment << ": " << failure.what()
                << "; cutting the increment to " << increment << std::endl;
            --step;
            if (increment < minimum_increment)
              {
                std::ostringstream reason;
                reason << "the load step could not be solved above load "
                       << "factor " << lambda << " (the last converged one) "
                       << "even with the minimum increment "
                       << minimum_increment << ": " << failure.what();
                result.stop_reason = reason.str();
                result.failed      = true;
                break;
              }
            continue;
          }

        a_old = a;
        a     = trial;
        last_increment = step_increment;
        lambda         = lands ? target : lambda + step_increment;

        // Grow the increment when Newton converges fast, shrink it when not.
        const double desired = lands ? std::max(increment, step_increment) :
                                       step_increment;
        if (newton_result.iterations <= 3)
          increment = std::min(maximum_increment, 1.5 * desired);
        else if (newton_result.iterations >= 7)
          increment = std::max(minimum_increment, 0.7 * desired);
        else
          increment = desired;

        result.last = {step,
                       lambda,
                       newton_result.iterations,
                       newton_result.residual_norm,
                       lands};
        if (lands)
          {
            result.target_load_factors.push_back(lambda);
            result.target_states.push_back(a);
          }
        const std::string stop = observer(result.last, a);
        if (!stop.empty())
          {
            result.stop_reason = stop;
            break;
          }
        if (lands && ++next_target == targets.size())
          {
            result.stop_reason = "reached the last target load factor";
            break;
          }
      }
    return result;
  }
} // namespace softopt
