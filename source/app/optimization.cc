#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <softopt/app/analysis.h>
#include <softopt/app/optimization.h>
#include <softopt/app/verification.h>
#include <softopt/io/design_mesh.h>
#include <softopt/io/output_directory.h>
#include <softopt/io/parameter_differences.h>
#include <softopt/base/subprocess.h>
#include <softopt/io/stl_writer.h>
#include <softopt/io/tracked_points.h>
#include <softopt/optimization/checkpoint.h>
#include <softopt/optimization/shape_optimizer.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

namespace softopt
{
  namespace
  {
    /** Runs scripts/plot_optimization on the output directory if Debian's
     * python3 with matplotlib is there; says so if not. */
    void
    plot(const std::string        &directory,
         const MPI_Comm            comm,
         const ConditionalOStream &pcout)
    {
      const std::string script = SOFTOPT_SOURCE_DIR "/scripts/plot_optimization";
      if (Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      const bool available =
        std::filesystem::exists(script) &&
        run_program({"/usr/bin/python3", "-c", "import matplotlib"}, "/dev/null") == 0;
      if (!available)
        {
          pcout << "Plots skipped: they need /usr/bin/python3 with matplotlib "
                   "(apt-get install python3-matplotlib) and "
                << script << std::endl;
          return;
        }
      // The directory is one argument: no shell reads it.
      const std::vector<std::string> command{"/usr/bin/python3", script, directory};
      const std::string              log = directory + "/plot.log";
      const int     status = run_program(command, log);
      std::ifstream     said(log);
      const std::string text((std::istreambuf_iterator<char>(said)),
                             std::istreambuf_iterator<char>());
      pcout << text << std::flush;
      said.close();
      std::filesystem::remove(log);
      if (status != 0)
        pcout << "Plotting failed: " << command_line(command) << std::endl;
    }



    /**
     * A fresh run does not go on from, or mix its rows into, an earlier
     * run's results in its folder; --start-over removes them first. A
     * restart continues the same problem: every entry but those that only
     * say how long to run and what to write must be as the run that wrote
     * parameters.prm had it.
     */
    void
    check_earlier_run(const Settings        &settings,
                      const OutputDirectory &out,
                      const Start            start,
                      const MPI_Comm         comm)
    {
      namespace fs = std::filesystem;
      const std::string checkpoint = Checkpoint::directory(out.path());
      const std::string file       = settings.input->path();
      std::string       error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          // error_code overloads: nothing may throw on rank 0 alone.
          std::error_code code;
          // A run refused at its initial design left a header only.
          const auto has_rows = [](const std::string &csv) {
            std::ifstream in(csv);
            std::string   line;
            unsigned int  lines = 0;
            while (lines < 2 && std::getline(in, line))
              lines += !line.empty();
            return lines >= 2;
          };
          const bool earlier = fs::exists(checkpoint, code) ||
                               fs::exists(checkpoint + ".old", code) ||
                               has_rows(out.file("history.csv"));
          if (start == Start::fresh && earlier)
            error = "The output directory <" + out.path() + "> holds an "
                    "earlier run (history.csv or checkpoint/). Continue it "
                    "with \"softopt optimize " + file + " --restart\", start "
                    "over with \"softopt optimize " + file + " --start-over\" "
                    "(which first removes its checkpoint, history.csv, "
                    "stop_reason.txt, design.stl, design.msh, design.prm, final_analysis/, "
                    "the verification, the castability checks and snapshots/), or set another "
                    "\"Output directory\".";
          else if (start == Start::start_over)
            {
              for (const auto *name : {"checkpoint", "checkpoint.old", "history.csv",
                                       "stop_reason.txt", "final_analysis", "design.stl",
                                       "design.msh", "design.prm", "verification",
                                       "verification.csv", "castability.csv",
                                       "wall_thickness.vtu", "snapshots"})
                if (fs::remove_all(out.file(name), code) == std::uintmax_t(-1))
                  error = "Cannot remove " + out.file(name) + ": " + code.message();
            }
          else if (start == Start::restart && fs::exists(out.file("parameters.prm"), code))
            {
              // What may change: how far to run, how often to save and
              // write, what to print, the final analysis's steps, and
              // where MUMPS keeps its factors.
              const auto differences = parameter_differences(
                out.file("parameters.prm"),
                settings.prm,
                {"Command", "Output directory", "Print timings", "Output/*", "Verification/*",
                 "Optimization/Maximum iterations", "Optimization/Checkpoint interval",
                 "Optimization/Output interval", "Optimization/Final analysis steps",
                 "Linear solver/Out-of-core factors",
                 "Linear solver/Out-of-core factors above cells"});
              if (!differences.empty())
                {
                  error = file + ": --restart continues the run in <" + out.path() +
                          "> with the same problem, but these entries differ "
                          "from its parameters.prm:";
                  for (const auto &d : differences)
                    error += "\n  " + d;
                  error += "\nRestore them, or start over with \"softopt optimize " +
                           file + " --start-over\".";
                }
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      AssertThrow(error.empty(), ExcMessage(error));
    }


    /** design.prm: the case on the final design's mesh (design.msh, beside
     * it), for "softopt analyze" at other pressures, materials or load
     * paths; its results go to design_analysis/ in the output directory. */
    void
    write_design_parameters(const Settings &settings, const OutputDirectory &out)
    {
      ParameterHandler prm;
      Settings::declare_parameters(prm, settings.input.get());
      prm.parse_input(settings.input->path());
      prm.set("Command", "analyze");
      prm.set("Output directory", out.file("design_analysis"));
      prm.enter_subsection("Geometry");
      prm.set("Mesh file", "design.msh");
      prm.set("Mesh parameters", "");
      prm.leave_subsection();
      prm.enter_subsection("Optimization"); // design.msh is the last mesh
      prm.set("Mesh size schedule", "");
      prm.leave_subsection();
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::PRM);
      out.write_text("design.prm", text.str());
    }
  } // namespace



  int
  run_optimization(const Settings &settings, const Start start, const MPI_Comm comm)
  {
    const bool restart = start == Start::restart;
    ConditionalOStream pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0);
    Timer timer;
    const auto &functionals = settings.functionals;
    AssertThrow(!functionals.empty() &&
                  functionals.front()->kind() == Functional::Kind::objective,
                ExcMessage(settings.input->path() +
                           ": \"optimize\" needs at least one objective "
                           "(subsection Objective 1)."));
    // The verification below needs the loop's results, not its memory
    // (factors, states, the filter: 16 GB on the contractor's 0.8 mm mesh),
    // so the loop lives in this block.
    std::optional<OutputDirectory> output;
    bool                           failed = false;
    VerificationRow                first;
    {
      // A checkpoint written after a remesh lives on that mesh.
      DesignProblem problem(settings,
                            comm,
                            restart ? Checkpoint::mesh_file(settings.output_directory) :
                                      "");
      pcout << "Mesh: " << problem.hyperelastic_problem().get_dof_handler()
                             .get_triangulation()
                             .n_global_active_cells()
            << " tetrahedra, "
            << problem.design_configuration().get_dof_handler().n_dofs()
            << " design variables" << std::endl;
      // The final analysis tracks these points on the final design; say now,
      // not hours later, where they land on the initial one.
      if (!settings.output.tracked_points.empty())
        TrackedPoints(problem.hyperelastic_problem(),
                      problem.design_configuration(),
                      settings.output.tracked_points)
          .print(pcout);

      // Input is checked: only now touch the output directory, which this
      // run then owns (a lock), and which holds no other run's results.
      const OutputDirectory &out = output.emplace(settings.output_directory, comm);
      check_earlier_run(settings, out, start, comm);
      if (start != Start::restart)
        out.write_parameters(settings.prm);
      ShapeOptimizer     optimizer(settings.optimization, settings.output, problem, out);
      const std::string  reason = optimizer.run(restart);
      pcout << "Stopped: " << reason << std::endl;
      out.write_text("stop_reason.txt", reason + "\n");
      if (!optimizer.accepted_a_design())
        return 1;

      // The final design: the last one the physics accepted (a refused
      // design leaves it in place, DesignProblem::evaluate).
      const unsigned int n_triangles =
        write_design_stl(problem.design_configuration(), out.file("design.stl"));
      pcout << "Wrote " << out.file("design.stl") << " (" << n_triangles
            << " triangles, mm)" << std::endl;

      write_design_mesh(problem.design_configuration(), out.file("design.msh"));
      write_design_parameters(settings, out);
      pcout << "Wrote " << out.file("design.msh") << " and " << out.file("design.prm")
            << " (the final design as a quadratic mesh, and the case on it: "
               "\"softopt analyze "
            << out.file("design.prm") << "\")" << std::endl;

      pcout << "\nForward analysis of the final design:" << std::endl;
      const std::string final_directory = out.file("final_analysis");
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        std::filesystem::create_directories(final_directory);
      MPI_Barrier(comm);
      // The design's targets and equal steps.
      const std::vector<double> targets = problem.final_analysis_path();
      const auto result = follow_load_path(problem.hyperelastic_problem(),
                                           problem.design_configuration(),
                                           settings,
                                           problem.functionals(),
                                           targets,
                                           final_directory,
                                           pcout);
      check_castability(settings, problem.design_configuration(), out, pcout);
      const auto &dof_handler = problem.hyperelastic_problem().get_dof_handler();
      first.mesh_size_mm = optimization_mesh_size(settings, problem.design_configuration());
      first.cells        = dof_handler.get_triangulation().n_global_active_cells();
      first.dofs         = dof_handler.n_dofs();
      first.values = values_at_targets(problem.hyperelastic_problem(),
                                       problem.design_configuration(),
                                       problem.functionals(),
                                       result);
      failed = optimizer.failed() || result.failed;
      if (settings.output.print_timings)
        {
          // The unit of scripts/bench_iteration: one assembly plus one
          // numerical factorization of the physics (means over every mesh
          // of the run).
          pcout << "Physics over the run: " << problem.physics_statistics().summary()
                << std::endl;
          problem.timer().print_summary();
        }
    }

    const bool verified =
      settings.verification.mesh_sizes.empty() ||
      verify_design(settings, output->file("design.msh"), first, *output, pcout);
    plot(output->path(), comm, pcout);
    if (settings.output.print_timings)
      pcout << "Wall time: " << timer.wall_time() << " s" << std::endl;
    return failed || !verified ? 1 : 0;
  }
} // namespace softopt
