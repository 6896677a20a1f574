#include <softopt/io/output_parameters.h>

namespace softopt
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Print timings",
                      "true",
                      Patterns::Bool(),
                      "Print wall times at the end of a run (tests switch "
                      "this off so that their output holds only physics).");
    prm.enter_subsection("Output");
    prm.declare_entry("VTU output",
                      "every step",
                      Patterns::Selection("every step|targets|none"),
                      "Which converged states of the load path are written "
                      "as VTU files (listed in solution.pvd, for ParaView); "
                      "\"none\" also switches off the design snapshots of "
                      "\"optimize\" (VTU and STL).");
    prm.declare_entry("Deformed STL",
                      "false",
                      Patterns::Bool(),
                      "Whether the load path (\"analyze\" and the final "
                      "analysis of \"optimize\") writes the deformed surface "
                      "at each target load factor (Target load factors and "
                      "those of the objectives and constraints, not the "
                      "final analysis' equal steps) as deformed_<p>kPa.stl "
                      "(binary, mm, next to load_path.csv), for renders of "
                      "the inflated part (scripts/render_stl).");
    prm.declare_entry("Stability",
                      "false",
                      Patterns::Bool(),
                      "Whether the load path (\"analyze\" and the final "
                      "analysis of \"optimize\") writes, at every converged "
                      "step, load_path.csv's column \"stability\": the "
                      "stiffness of the softest mode relative to its shear "
                      "stiffness at rest (the smallest positive mu of K phi = "
                      "mu K_0 phi, K_0 the tangent at rest without the bulk "
                      "term): at least 1 at rest, 0 at a limit point (where "
                      "the part snaps under pressure control, whatever the "
                      "mode), and on a descending branch the negative mu "
                      "nearest zero. Costs a factorization and a few dozen "
                      "solves per step, a second matrix, and up to 100 "
                      "vectors while it computes.");
    prm.declare_entry(
      "Tracked points",
      "",
      Patterns::Anything(),
      "Named points whose displacement is written at every converged step "
      "of the load path (\"analyze\" and the final analysis of "
      "\"optimize\") to tracked_points.csv, next to load_path.csv, for "
      "comparison with markers tracked on video "
      "(scripts/compare_experiment --markers). The syntax is \"name: x, y, "
      "z; name: x, y, z\" with the coordinates in mm in the design "
      "configuration (the mesh as read for \"analyze\", the optimized "
      "design for \"optimize\"), for example \"tip: 60, 0, 11.5; side: "
      "30, 0, 11.5\" (the actuator's axis is x); names are letters, "
      "digits, '_' and '-'. Each point is replaced by the nearest node of "
      "the quadratic mesh on the body's "
      "surface (every boundary face except symmetry planes, i.e. Dirichlet "
      "boundaries that fix only some components); the program prints the "
      "node chosen and its distance, and warns if that exceeds half the "
      "longest edge of its boundary face or 1 mm, whichever is larger (the "
      "point is then probably not on the surface). The file holds step, "
      "load_factor, pressure_kPa and, for each name, the node's position "
      "<name>_X_mm, <name>_Y_mm, <name>_Z_mm and its displacement "
      "<name>_ux_mm, <name>_uy_mm, <name>_uz_mm. Empty: no tracked points, "
      "no file.");
    prm.leave_subsection();

  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    print_timings    = prm.get_bool("Print timings");
    prm.enter_subsection("Output");
    const std::string vtu = prm.get("VTU output");
    vtu_output = vtu == "every step" ? VtuOutput::every_step :
                 vtu == "targets"    ? VtuOutput::targets :
                                       VtuOutput::none;
    deformed_stl = prm.get_bool("Deformed STL");
    stability    = prm.get_bool("Stability");
    tracked_points =
      parse_named_points(prm.get("Tracked points"),
                         input.where("Output", "Tracked points"));
    prm.leave_subsection();

  }
} // namespace softopt
