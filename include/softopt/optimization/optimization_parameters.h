#ifndef softopt_optimization_optimization_parameters_h
#define softopt_optimization_optimization_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>

#include <utility>
#include <vector>

namespace softopt
{
  /** The design loop (subsection "Optimization"), the paper's values by
   * default. */
  struct OptimizationParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    unsigned int maximum_iterations = 350;
    /** The largest change of a design variable per iteration, as a fraction
     * of the box width 2 x design bound (MMA's move limit). */
    double move_limit = 0.025;
    /** |d| <= design bound, in mm. */
    double design_bound = 1.2;
    unsigned int mesh_update_interval = 50;
    /** How many of those periodic mesh updates there are (0: no limit). */
    unsigned int mesh_updates = 0;
    /** One more mesh update at this iteration (0: none). */
    unsigned int final_mesh_update = 0;
    /** A mesh update remeshes the design when its worst element quality
     * is below this, and an accepted design below it brings the update
     * forward (0: never). */
    double       remesh_quality       = 0;
    unsigned int output_interval      = 10;
    unsigned int checkpoint_interval  = 10;
    unsigned int final_analysis_steps = 20;
    /** Every this many iterations (and at mesh updates) the states are
     * checked against those from rest (0: never). */
    unsigned int from_rest_interval = 10;
    /** Relative difference of a functional that counts as another branch. */
    double       branch_tolerance   = 1e-3;
    /** Whether a design with a pressure maximum below a target is refused
     * (its paths from rest then use arclength). */
    bool         refuse_limit_points = false;
    bool         warm_start           = true;
    /** Whether the warm start extrapolates the states along the secant
     * through the last two designs (SecantPredictor). */
    bool         secant_predictor     = true;
    /** Halvings of the design substep when both warm starts fail (0: the
     * path from zero at once). */
    unsigned int warm_start_substeps  = 5;
    /** Halvings of a refused MMA step before the run stops. */
    unsigned int step_halvings = 3;
    /** Whether a design whose surface intersects itself is refused. */
    bool refuse_self_intersections = true;

    /** "Mesh size schedule": element sizes in mm from the iterations
     * given on, ascending in iteration (may start at 0: the first mesh). */
    std::vector<std::pair<unsigned int, double>> mesh_size_schedule;

    /** The element size the schedule asks for at iteration @p k > 0, in
     * mm, if its latest entry at or before @p k (after 0) is later than
     * @p mesh_made_at, the iteration the current mesh was made at (-1: the
     * first mesh); else 0. So a new mesh that failed at its iteration is
     * tried again at the next one. */
    double
    scheduled_mesh_size(const unsigned int k, const long mesh_made_at) const;

    /** Whether iteration @p k is one of the periodic mesh updates or the
     * final one. */
    bool
    planned_mesh_update(const unsigned int k) const
    {
      return (every(k, mesh_update_interval) &&
              (mesh_updates == 0 || k / mesh_update_interval <= mesh_updates)) ||
             (final_mesh_update > 0 && k == final_mesh_update);
    }

    /** Whether iteration @p k > 0 is one of every @p interval (0: none). */
    static bool
    every(const unsigned int k, const unsigned int interval)
    {
      return interval > 0 && k > 0 && k % interval == 0;
    }
  };
} // namespace softopt

#endif
