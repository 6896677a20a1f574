#include <softopt/app/settings.h>
#include <softopt/solvers/direct_solver.h>

namespace softopt
{
  void
  Settings::declare_parameters(ParameterHandler &prm, const InputFile *input)
  {
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Where results go (relative to the working directory); "
                      "created if missing. A run overwrites the files it "
                      "writes there, but only after its input has been "
                      "checked.");
    prm.declare_entry("Command",
                      "analyze",
                      Patterns::Selection("analyze|optimize|check-gradients"),
                      "What \"softopt CASE.prm\" does when no command is "
                      "given on the command line.");
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
                      "\"optimize\".");
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

    Geometry::declare_parameters(prm);
    Materials::declare_parameters(prm);
    PathFollowing::declare_parameters(prm);
    NewtonSolver::declare_parameters(prm);
    ShapeFilter::declare_parameters(prm);
    OptimizationParameters::declare_parameters(prm);
    DirectSolver::declare_parameters(prm);
    Functionals::declare_parameters(prm, input);
  }



  Settings::Settings(const std::string &file)
    : input(std::make_unique<InputFile>(file))
  {
    declare_parameters(prm, input.get());
    prm.parse_input(file);

    output_directory = prm.get("Output directory");
    command          = prm.get("Command");
    print_timings    = prm.get_bool("Print timings");
    prm.enter_subsection("Output");
    const std::string vtu = prm.get("VTU output");
    vtu_output = vtu == "every step" ? VtuOutput::every_step :
                 vtu == "targets"    ? VtuOutput::targets :
                                       VtuOutput::none;
    tracked_points =
      parse_named_points(prm.get("Tracked points"),
                         input->where("Output", "Tracked points"));
    prm.leave_subsection();

    geometry.parse_parameters(prm, *input);
    material = Materials::create(prm, *input);
    loading.parse_parameters(prm, *input);
    newton.parse_parameters(prm);
    shape_filter.parse_parameters(prm, *input);
    optimization.parse_parameters(prm, *input);
    linear_solver = DirectSolver::parse_parameters(prm);
    functionals = Functionals::create(prm, *input);
  }
} // namespace softopt
