#include <softopt/app/settings.h>
#include <softopt/solvers/direct_solver.h>

#include <filesystem>

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
                      Patterns::Selection("analyze|optimize|verify|check-design|mold|check-gradients"),
                      "What \"softopt CASE.prm\" does when no command is "
                      "given on the command line.");
    OutputParameters::declare_parameters(prm);
    Geometry::declare_parameters(prm);
    Materials::declare_parameters(prm);
    Loading::declare_parameters(prm);
    NewtonSolver::declare_parameters(prm);
    ShapeFilter::Parameters::declare_parameters(prm);
    OptimizationParameters::declare_parameters(prm);
    DirectSolver::declare_parameters(prm);
    VerificationParameters::declare_parameters(prm);
    CastabilityParameters::declare_parameters(prm);
    MoldParameters::declare_parameters(prm);
    Functionals::declare_parameters(prm, input);
  }



  Settings::Settings(const std::string &file)
    : input(std::make_unique<InputFile>(file))
  {
    declare_parameters(prm, input.get());
    prm.parse_input(file);

    output_directory = prm.get("Output directory");
    command          = prm.get("Command");
    output.parse_parameters(prm, *input);
    geometry.parse_parameters(prm, *input);
    material = Materials::create(prm, *input);
    loading.parse_parameters(prm, *input);
    newton.parse_parameters(prm);
    shape_filter.parse_parameters(prm, *input);
    optimization.parse_parameters(prm, *input);
    // The schedule's size at iteration 0 is the first mesh's.
    const auto &schedule = optimization.mesh_size_schedule;
    if (!schedule.empty() && schedule.front().first == 0)
      {
        AssertThrow(std::filesystem::path(geometry.mesh_file).extension() == ".geo",
                    ExcMessage(input->where("Optimization", "Mesh size schedule") +
                               ": a size at iteration 0 sets the size of a .geo "
                               "mesh, but Mesh file <" + geometry.mesh_file +
                               "> is a mesh already; start the schedule after "
                               "iteration 0."));
        geometry.mesh_size = schedule.front().second;
      }
    linear_solver = DirectSolver::parse_parameters(prm);
    verification.parse_parameters(prm, *input);
    castability.parse_parameters(prm, *input);
    mold.parse_parameters(prm, *input);
    for (auto &f : Functionals::create(prm, *input))
      functionals.push_back(std::move(f));
  }
} // namespace softopt
