#ifndef softopt_path_path_following_h
#define softopt_path_path_following_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/path/arclength.h>
#include <softopt/path/equilibrium_problem.h>
#include <softopt/path/newton_solver.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * Follows the equilibrium path r_a(a, lambda) = 0 from lambda = 0 with load
   * control or Crisfield's arclength method, and lands exactly on each target
   * load factor (subsection "Loading"): a step that crosses a target is
   * redone from the last converged state with load control to the target.
   * Knows residuals and solves, not physics.
   */
  class PathFollowing
  {
  public:
    enum class Method
    {
      load_control,
      arclength
    };

    /** Its entries of subsection "Loading" (which Loading declares). */
    struct Parameters
    {
      /** Declares the entries in the current subsection. */
      static void
      declare_parameters(ParameterHandler &prm);

      /** Reads them from the current subsection. */
      void
      parse_parameters(ParameterHandler &prm, const InputFile &input);

      Method method = Method::load_control;
      /** The weight w of the load factor in the arclength constraint. */
      double       load_factor_weight = 1;
      double       initial_increment  = 1;
      double       minimum_increment  = 1e-4;
      double       maximum_increment  = 1.;
      unsigned int maximum_steps      = 200;
      /** Arclength step control: the largest angle (radians) between a
       * step's predictor and its converged increment, and the largest
       * change of the displacement per step relative to the linear
       * response at rest to the full load, |Delta u| / |u_f^0|. */
      double maximum_turning_angle = 10 * M_PI / 180;
      double maximum_state_change  = 0.25;
      /** Load control that cannot go on (three failed steps from one
       * converged point past the first) follows the rest of the path with
       * arclength: through a limit point, onto the branch that a part
       * inflated from rest snaps to. False: it stops there. */
      bool arclength_past_limit_points = true;
      /** The path stops, failed, where the load factor passes a maximum
       * (a limit point: the load rate turns negative) before the last
       * target: the design loop's "Limit point below a target = refuse". */
      bool stop_at_limit_point = false;
      /** The pressure (kPa) at load factor 1, for messages only (0: none). */
      double full_load_kPa = 0;
    };

    /** With the default parameters (load control, one step). */
    PathFollowing();

    explicit PathFollowing(const Parameters &parameters);

    /** A converged point of the path. */
    struct PathPoint
    {
      unsigned int step              = 0;
      double       load_factor       = 0;
      unsigned int newton_iterations = 0;
      double       residual_norm     = 0;
      bool         at_target         = false;
      /** A limit point of the load (d lambda / ds = 0) located between two
       * steps of an arclength path. */
      bool limit_point = false;
    };

    /**
     * Called after every converged step with the state there; returns a
     * reason to stop (for example a cavity volume limit), or "" to go on.
     */
    using Observer =
      std::function<std::string(const PathPoint &,
                                const EquilibriumProblem::Vector &)>;

    /** The stop reason of a path that reached every target. */
    static constexpr const char *reached_last_target = "reached the last target load factor";

    /** How the path ended, and the states kept at the targets. */
    struct Result
    {
      /** Printed and written to the output. */
      std::string stop_reason;
      /** False if the path stopped because a step could not be solved. */
      bool failed = false;
      /** The last converged point. */
      PathPoint last;
      /** Where load control handed over to arclength (negative: never). */
      double arclength_from = -1;
      /** The load factors of the limit points located, in path order. */
      std::vector<double> limit_load_factors;
      /** Whether the path stopped at a maximum of the load below a target
       * (Parameters::stop_at_limit_point). */
      bool stopped_at_limit_point = false;
      /** Converged states at the targets reached, in order. */
      std::vector<double>                     target_load_factors;
      std::vector<EquilibriumProblem::Vector> target_states;
    };

    /**
     * Follows the path from the zero state up to the last of @p targets
     * (positive), or until a stop criterion or a step that cannot be solved.
     */
    Result
    run(EquilibriumProblem        &problem,
        const NewtonSolver        &newton,
        const std::vector<double> &targets,
        const Observer            &observer,
        const ConditionalOStream  &log) const;

  private:
    const Parameters parameters;

    /** How much shorter than @p next's arclength the steps should be
     * (< 1) or may be (> 1) for the turning angle and state change. */
    double
    step_control(const Arclength::Point &next) const;

    /** The limit point between @p from and @p to, converged points of an
     * arclength path whose load rates differ in sign: the zero of the load
     * rate along the chord by regula falsi (Illinois); none if no point
     * between them converged. */
    static std::optional<Arclength::Point>
    locate_limit_point(const Arclength          &arclength,
                       const Arclength::Point   &from,
                       const Arclength::Point   &to,
                       const ConditionalOStream &log);

    /** Newton at fixed @p load_factor from @p current, predicted along the
     * line from @p current through @p guide (if given). */
    static Arclength::Point
    load_controlled_step(EquilibriumProblem     &problem,
                         const NewtonSolver     &newton,
                         const Arclength::Point &current,
                         const Arclength::Point *guide,
                         const double            load_factor);
  };
} // namespace softopt

#endif
