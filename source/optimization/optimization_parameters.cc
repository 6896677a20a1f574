#include <deal.II/base/utilities.h>

#include <softopt/optimization/optimization_parameters.h>

#include <cmath>
#include <string>

namespace softopt
{
  void
  OptimizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Optimization");
    prm.declare_entry("Maximum iterations",
                      "350",
                      Patterns::Integer(0),
                      "Design iterations (MMA updates); the paper uses 350.");
    prm.declare_entry("Move limit",
                      "0.025",
                      Patterns::Double(1e-6, 1),
                      "The largest change of a design variable in one "
                      "iteration, as a fraction of its box width 2 x Design "
                      "bound (dimensionless; the paper uses 0.025).");
    prm.declare_entry("Design bound",
                      "1.2",
                      Patterns::Double(1e-9),
                      "The box constraint |d_k| <= Design bound on every "
                      "design variable, in mm (the paper uses 1.2); also the "
                      "design scale of check-gradients.");
    prm.declare_entry("Mesh update interval",
                      "50",
                      Patterns::Integer(0),
                      "Every this many iterations the mesh coordinates are "
                      "updated, X_o <- X_o + psi and d <- 0, which frees the "
                      "box constraints again (0: never; the paper uses 50).");
    prm.declare_entry("Mesh updates",
                      "0",
                      Patterns::Integer(0),
                      "How many of those periodic mesh updates there are: "
                      "after the last one the design moves within the box "
                      "constraints about the last X_o only, which bounds how "
                      "far it can go (0: no limit). The paper stops after "
                      "three (gripper, extender, contractor) or four "
                      "(grip_extend; grip_contract is not stated) of its "
                      "350 iterations. Updates "
                      "of \"Remesh below quality\", \"Mesh size "
                      "schedule\" and \"Final mesh update\" do not count.");
    prm.declare_entry("Final mesh update",
                      "0",
                      Patterns::Integer(0),
                      "One more mesh update at this iteration, after the "
                      "periodic ones (0: none; not in the paper): the design "
                      "may then move another Design bound about the new X_o "
                      "in the iterations left. Measured on the gripper at "
                      "325 of 350 iterations: 6.6 % more grip on the 2 mm "
                      "mesh, and the run within 6.0 % of its part meshed at "
                      "0.8 mm, as with the last 25 iterations on a 1.2 mm "
                      "mesh, without their 45 min (doc/results.md). Must be "
                      "below Maximum iterations.");
    prm.declare_entry("Remesh below quality",
                      "0",
                      Patterns::Double(0, 1),
                      "At a mesh update, if the design's worst element has a "
                      "mean-ratio quality below this (1: equilateral, 0: "
                      "flat), gmsh meshes the design anew inside its "
                      "boundary triangles (which keep their boundary ids "
                      "and curved midside nodes), written as "
                      "mesh-<iteration>.msh into the output directory; d, psi "
                      "and MMA start afresh and the physics follows the path "
                      "from zero. For designs that flatten elements the mesh "
                      "update keeps (thin walls one element thick). Between "
                      "mesh updates, an accepted design whose worst element "
                      "falls below this (while the mesh it is on, psi = 0, "
                      "is above it) brings the mesh update forward to the "
                      "next iteration, so that elements do not collapse "
                      "between updates. 0: never, as in the paper.");
    prm.declare_entry("Mesh size schedule",
                      "",
                      Patterns::Anything(),
                      "A finer mesh as the design settles: \"size @ "
                      "iteration\" pairs, comma-separated, sizes in mm, "
                      "iterations ascending, e.g. \"4 @ 0, 2 @ 150, 1.2 @ "
                      "300\". At each iteration named (> 0) the mesh is "
                      "updated and the design meshed anew at that size from "
                      "its curved boundary, refined on the design's P2 "
                      "surface (as subsection Verification does); the states "
                      "are carried to the new nodes as Newton's start, the "
                      "design is checked from rest there, and d, psi and MMA "
                      "start afresh. A size at iteration 0 replaces Mesh size "
                      "of subsection Geometry (a .geo mesh only). The new "
                      "meshes are written as mesh-<iteration>.msh into the "
                      "output directory. Each boundary face is split n x n, n "
                      "the smallest with boundary edges of at most the size on "
                      "average; the size grows from theirs at the boundary to "
                      "the size at a depth of twice the size. So from "
                      "boundary edges of 2 mm the steps are 1, 0.67, 0.5 mm...: "
                      "a size of 0.8 after 1.2 (edges of about 1 mm) gives "
                      "0.5 mm boundary edges (the iteration line prints them). "
                      "Empty: the mesh keeps its size.");
    prm.declare_entry("Refuse self-intersecting designs",
                      "true",
                      Patterns::Bool(),
                      "Whether every design's surface is tested for "
                      "self-intersection (CGAL, exact predicates; 1 % of an "
                      "iteration of the quick gripper) and a design that passes through "
                      "itself is refused like an inverted one (the step is "
                      "halved). Such a design cannot be cast, and the model, "
                      "which has no contact, would go on computing it.");
    prm.declare_entry("Output interval",
                      "10",
                      Patterns::Integer(0),
                      "Every this many iterations the design and its deformed "
                      "states are written as VTU, and the design's surface as "
                      "snapshots/design_<iteration>.stl (scripts/render_snapshots "
                      "draws them in a row; 0: only the final design; none with "
                      "Output / VTU output = none).");
    prm.declare_entry("Checkpoint interval",
                      "10",
                      Patterns::Integer(0),
                      "Every this many iterations the whole state is written "
                      "for \"softopt optimize CASE.prm --restart\" (0: never).");
    prm.declare_entry("Warm start",
                      "true",
                      Patterns::Bool(),
                      "Start each design's equilibrium solves from the "
                      "converged states of the previous design at the same "
                      "target load factors (Newton at fixed load factor), and "
                      "its adjoint solve from the last Newton factorization; "
                      "falls back to design substeps (\"Warm start "
                      "substeps\") and then to path following from zero when "
                      "Newton fails from there (see doc/theory.md).");
    prm.declare_entry("Warm start predictor",
                      "secant",
                      Patterns::Selection("secant|none"),
                      "Where a warm start's Newton begins: \"secant\" "
                      "extrapolates the target states along the secant "
                      "through the last two accepted designs (one Newton "
                      "step fewer, doc/theory.md), falling back to the last "
                      "design's states if Newton fails from there; \"none\" "
                      "starts from the last design's states.");
    prm.declare_entry("Warm start substeps",
                      "5",
                      Patterns::Integer(0, 10),
                      "When Newton fails from both warm starts, the design is "
                      "moved from the accepted one to the new one in steps "
                      "(psi_o + t (psi - psi_o), t halved on a failure, at "
                      "most this many halvings of the first half step), each "
                      "with Newton at every target from the states of the "
                      "step before; only if that fails too does the path "
                      "start from zero. 0: straight to the path from zero "
                      "(doc/theory.md).");
    prm.declare_entry("Step halvings",
                      "3",
                      Patterns::Integer(0, 20),
                      "When the physics or the filter refuses a design (an "
                      "inverted element, a load path that does not reach a "
                      "target), the MMA step from the last accepted design is "
                      "halved and the design evaluated again, at most this "
                      "many times before the run stops with the last accepted "
                      "design (0: stop at once).");
    prm.declare_entry("Path from rest interval",
                      "10",
                      Patterns::Integer(0),
                      "Warm-started states can drift onto an equilibrium "
                      "branch that inflating the design from rest does not "
                      "reach. Every this many iterations, at every mesh "
                      "update (also one brought forward, and a new mesh of the "
                      "schedule) and at the last iteration (whose values the run "
                      "reports), the design is also loaded from rest to the "
                      "targets (with subsection Loading's path following and "
                      "increments, as a design without warm start); if a "
                      "functional differs by more "
                      "than Branch tolerance, the run goes on from the states "
                      "reached from rest, says so on the iteration line and "
                      "marks it in history.csv (branch_switched); after such "
                      "a switch the next iterations are checked too, until "
                      "one agrees. 0: never "
                      "(the loop may then report a state the cast part is "
                      "not in; see doc/theory.md).");
    prm.declare_entry("Branch tolerance",
                      "1e-3",
                      Patterns::Double(0),
                      "The largest relative difference between the "
                      "warm-started states and those from rest that counts "
                      "as the same branch (dimensionless): |g_warm - g_rest| "
                      "/ |g_rest| of an objective, |f_warm - f_rest| / "
                      "|Q_rest| of a constraint f = Q - Tolerance (an active "
                      "constraint is near 0, its quantity is not).");
    prm.declare_entry(
      "Limit point below a target",
      "follow",
      Patterns::Selection("follow|refuse"),
      "A design whose pressure has a maximum (a limit point) below a target "
      "snaps through there when inflated. follow: the target state is the "
      "one the part snaps to (the path goes on through the limit point as "
      "subsection Loading says); where the maximum passes the target from one "
      "design to the next the objective jumps (doc/theory.md). refuse: such a "
      "design is refused like an inverted one (the step is halved), for "
      "actuators that must not snap; the loop's paths from rest then use "
      "arclength with its step control, so that no load step can step over "
      "a fold. A warm-started design is tested when it is checked from rest "
      "(Path from rest interval, and always at the last iteration; 1: "
      "every design).");
    prm.declare_entry("Final analysis steps",
                      "20",
                      Patterns::Integer(1, 10000),
                      "The final design is inflated again after the loop "
                      "(final_analysis/load_path.csv); its path lands on this "
                      "many equally spaced load factors in (0, 1] besides "
                      "the targets, for the pressure-volume curve.");
    prm.leave_subsection();
  }



  namespace
  {
    /** "4 @ 0, 2 @ 150" as (iteration, size) pairs; throws naming @p where. */
    std::vector<std::pair<unsigned int, double>>
    parse_schedule(const std::string &text, const std::string &where)
    {
      std::vector<std::pair<unsigned int, double>> schedule;
      for (const auto &item : Utilities::split_string_list(text, ','))
        {
          const auto parts = Utilities::split_string_list(item, '@');
          double     size  = 0;
          long       k     = -1;
          try
            {
              AssertThrow(parts.size() == 2, ExcMessage(""));
              std::size_t end_size = 0, end_k = 0;
              size = std::stod(parts[0], &end_size);
              k    = std::stol(parts[1], &end_k);
              AssertThrow(end_size == parts[0].size() && end_k == parts[1].size(),
                          ExcMessage(""));
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcMessage(where + ": \"" + item + "\" is not \"size @ "
                                     "iteration\" (for example \"2 @ 150\": 2 mm "
                                     "from iteration 150 on)."));
            }
          AssertThrow(size > 0 && std::isfinite(size),
                      ExcMessage(where + ": the size in \"" + item +
                                 "\" must be positive (mm)."));
          AssertThrow(k >= 0 && k < 100000000,
                      ExcMessage(where + ": the iteration in \"" + item +
                                 "\" must be 0 or more (and below 10^8)."));
          AssertThrow(schedule.empty() || long(schedule.back().first) < k,
                      ExcMessage(where + ": the iterations must ascend, but \"" +
                                 item + "\" follows iteration " +
                                 std::to_string(schedule.back().first) + "."));
          schedule.emplace_back(k, size);
        }
      return schedule;
    }
  } // namespace



  double
  OptimizationParameters::scheduled_mesh_size(const unsigned int k, const long mesh_made_at) const
  {
    double size = 0;
    for (const auto &[iteration, h] : mesh_size_schedule)
      if (iteration > 0 && iteration <= k)
        size = long(iteration) > mesh_made_at ? h : 0;
    return size;
  }



  void
  OptimizationParameters::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    prm.enter_subsection("Optimization");
    mesh_size_schedule =
      parse_schedule(prm.get("Mesh size schedule"),
                     input.where("Optimization", "Mesh size schedule"));
    maximum_iterations   = prm.get_integer("Maximum iterations");
    move_limit           = prm.get_double("Move limit");
    design_bound         = prm.get_double("Design bound");
    mesh_update_interval = prm.get_integer("Mesh update interval");
    mesh_updates         = prm.get_integer("Mesh updates");
    final_mesh_update    = prm.get_integer("Final mesh update");
    if (final_mesh_update > 0)
      {
        const std::string where = input.where("Optimization", "Final mesh update") + ": " +
                                  std::to_string(final_mesh_update);
        AssertThrow(final_mesh_update < maximum_iterations,
                    ExcMessage(where + " is not below Maximum iterations (" +
                               std::to_string(maximum_iterations) +
                               "), so the update would never be made."));
        AssertThrow(mesh_update_interval == 0 ||
                      (mesh_updates > 0 &&
                       final_mesh_update > mesh_update_interval * mesh_updates),
                    ExcMessage(where + " is not after the last periodic mesh update "
                               "(Mesh update interval " +
                               std::to_string(mesh_update_interval) + ", Mesh updates " +
                               std::to_string(mesh_updates) + "; 0 is no limit)."));
      }
    remesh_quality       = prm.get_double("Remesh below quality");
    output_interval      = prm.get_integer("Output interval");
    checkpoint_interval  = prm.get_integer("Checkpoint interval");
    final_analysis_steps = prm.get_integer("Final analysis steps");
    from_rest_interval   = prm.get_integer("Path from rest interval");
    branch_tolerance     = prm.get_double("Branch tolerance");
    refuse_limit_points  = prm.get("Limit point below a target") == "refuse";
    warm_start           = prm.get_bool("Warm start");
    secant_predictor     = prm.get("Warm start predictor") == "secant";
    warm_start_substeps  = prm.get_integer("Warm start substeps");
    step_halvings        = prm.get_integer("Step halvings");
    refuse_self_intersections = prm.get_bool("Refuse self-intersecting designs");
    prm.leave_subsection();
  }
} // namespace softopt
