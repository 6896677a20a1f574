#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <softopt/app/analysis.h>
#include <softopt/app/optimization.h>
#include <softopt/app/output_directory.h>
#include <softopt/io/stl_writer.h>
#include <softopt/io/tracked_points.h>
#include <softopt/optimization/checkpoint.h>
#include <softopt/optimization/shape_optimizer.h>

#include <cstdlib>
#include <filesystem>

namespace softopt
{
  namespace
  {
    /** Runs scripts/plot_optimization on the output directory if Debian's
     * python3 with matplotlib is there; says so if not. */
    void
    plot(const std::string &directory, const ConditionalOStream &pcout)
    {
      const std::string script = SOFTOPT_SOURCE_DIR "/scripts/plot_optimization";
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      const bool available =
        std::filesystem::exists(script) &&
        std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0;
      if (!available)
        {
          pcout << "Plots skipped: they need /usr/bin/python3 with matplotlib "
                   "(apt-get install python3-matplotlib) and "
                << script << std::endl;
          return;
        }
      const std::string command =
        "/usr/bin/python3 " + script + " '" + directory + "'";
      if (std::system(command.c_str()) != 0)
        pcout << "Plotting failed: " << command << std::endl;
    }
  } // namespace



  int
  run_optimization(Settings &settings, const bool restart)
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    Timer timer;
    // A checkpoint written after a remesh lives on that mesh.
    if (restart)
      Checkpoint::select_mesh(settings.output_directory, settings.geometry.mesh_file);
    DesignProblem problem(settings);
    pcout << "Mesh: " << problem.hyperelastic_problem().get_dof_handler()
                           .get_triangulation()
                           .n_global_active_cells()
          << " tetrahedra, "
          << problem.design_configuration().get_dof_handler().n_dofs()
          << " design variables" << std::endl;
    // The final analysis tracks these points on the final design; say now,
    // not hours later, where they land on the initial one.
    if (!settings.tracked_points.empty())
      TrackedPoints(problem.hyperelastic_problem(),
                    problem.design_configuration(),
                    settings.tracked_points)
        .print(pcout);

    // Input is checked: only now touch the output directory.
    const OutputDirectory out(settings.output_directory, MPI_COMM_WORLD);
    if (!restart)
      out.write_parameters(settings.prm);
    ShapeOptimizer     optimizer(settings, problem, out);
    const std::string  reason = optimizer.run(restart);
    pcout << "Stopped: " << reason << std::endl;
    out.write_text("stop_reason.txt", reason + "\n");

    // The final design: the last one the physics accepted (a refused
    // design leaves it in place, DesignProblem::evaluate).
    const unsigned int n_triangles =
      write_design_stl(problem.design_configuration(), out.file("design.stl"));
    pcout << "Wrote " << out.file("design.stl") << " (" << n_triangles
          << " triangles, mm)" << std::endl;

    pcout << "\nForward analysis of the final design:" << std::endl;
    const std::string final_directory = out.file("final_analysis");
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::create_directories(final_directory);
    MPI_Barrier(MPI_COMM_WORLD);
    // The design's targets and equal steps (the path sorts out repeats).
    std::vector<double> targets = problem.target_load_factors();
    const unsigned int  n       = settings.optimization.final_analysis_steps;
    for (unsigned int i = 1; i <= n; ++i)
      targets.push_back(double(i) / n);
    const auto result = follow_load_path(problem.hyperelastic_problem(),
                                         problem.design_configuration(),
                                         settings,
                                         problem.functionals(),
                                         targets,
                                         final_directory,
                                         pcout);
    plot(out.path(), pcout);
    if (settings.print_timings)
      {
        // The unit of scripts/bench_iteration: one assembly plus one
        // numerical factorization of the physics (means over every mesh
        // of the run).
        pcout << "Physics over the run: " << problem.physics_statistics().summary()
              << std::endl;
        problem.timer().print_summary();
        pcout << "Wall time: " << timer.wall_time() << " s" << std::endl;
      }
    return optimizer.failed() || result.failed ? 1 : 0;
  }
} // namespace softopt
