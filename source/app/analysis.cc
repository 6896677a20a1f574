#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <softopt/app/analysis.h>
#include <softopt/base/step_failure.h>
#include <softopt/shape/self_intersection.h>
#include <softopt/io/output_directory.h>
#include <softopt/functionals/design_surface.h>
#include <softopt/functionals/direction_field.h>
#include <softopt/io/csv_writer.h>
#include <softopt/io/pvd_series.h>
#include <softopt/io/stl_writer.h>
#include <softopt/io/tracked_points.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/physics/stability.h>
#include <softopt/shape/design_configuration.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>


namespace softopt
{
  namespace
  {
    /** The design-surface means of load_path.csv: u_x, and the inward
     * radial displacement about the x axis. */
    std::pair<double, double>
    design_means(const HyperelasticProblem         &problem,
                 const DesignConfiguration         &design,
                 const HyperelasticProblem::Vector &a)
    {
      if (problem.get_geometry().design_boundary_ids.empty())
        return {std::nan(""), std::nan("")};
      static const auto x_axis = DirectionFields::create_default("constant");
      static const auto inward = DirectionFields::create_default("inward radial");
      const auto s_x  = integrate_over_design_surface(problem, design, a, *x_axis, false);
      const auto s_in = integrate_over_design_surface(problem, design, a, *inward, false);
      return {s_x.linear / s_x.area, s_in.linear / s_in.area};
    }



    /** A functional's extreme values along a load path, and its value at
     * its target (at the last of its targets if it reads several states). */
    struct Extrema
    {
      double minimum = std::numeric_limits<double>::infinity();
      double maximum = -std::numeric_limits<double>::infinity();
      double minimum_kPa = 0, maximum_kPa = 0;
      double at_target   = std::nan("");

      void
      add(double value, const double p_kPa)
      {
        value += 0.; // no -0 in the summary
        if (value < minimum)
          std::tie(minimum, minimum_kPa) = std::make_pair(value, p_kPa);
        if (value > maximum)
          std::tie(maximum, maximum_kPa) = std::make_pair(value, p_kPa);
      }
    };



    /** load_path_summary.csv and its printed lines: for each functional its
     * value at its target beside its best (objectives: lowest; constraints:
     * highest) value along the path and the pressure there. */
    void
    write_summary(const std::vector<const Functional *> &functionals,
                  const std::vector<Extrema>            &extrema,
                  const double                           pressure_kPa,
                  const std::string                     &directory,
                  const MPI_Comm                         comm,
                  const ConditionalOStream              &pcout)
    {
      CsvWriter summary(directory + "/load_path_summary.csv",
                        {"functional",
                         "kind",
                         "target_pressure_kPa",
                         "value_at_target",
                         "minimum",
                         "pressure_at_minimum_kPa",
                         "maximum",
                         "pressure_at_maximum_kPa"},
                        comm);
      pcout << "Along the path:" << std::endl;
      for (unsigned int i = 0; i < functionals.size(); ++i)
        {
          const Functional &f = *functionals[i];
          const Extrema    &e = extrema[i];
          const bool  objective = f.kind() == Functional::Kind::objective;
          const char *kind      = objective ? "objective" : "constraint";
          const double target_kPa =
            f.load_factors().empty() ? std::nan("") : f.load_factors().back() * pressure_kPa;
          summary.add_row({f.name(),
                           kind,
                           CsvWriter::format(target_kPa),
                           CsvWriter::format(e.at_target),
                           CsvWriter::format(e.minimum),
                           CsvWriter::format(e.minimum_kPa),
                           CsvWriter::format(e.maximum),
                           CsvWriter::format(e.maximum_kPa)});
          pcout << "  " << f.name() << " (" << kind << ", "
                << (objective ? "lower" : "higher") << " is "
                << (objective ? "better" : "worse") << "): ";
          if (f.load_factors().empty())
            {
              pcout << e.at_target << " (of the shape alone)" << std::endl;
              continue;
            }
          else if (std::isnan(e.at_target))
            pcout << "target " << target_kPa << " kPa not on the path";
          else
            pcout << e.at_target << " at its target " << target_kPa << " kPa";
          pcout << "; lowest " << e.minimum << " at " << e.minimum_kPa
                << " kPa, highest " << e.maximum << " at " << e.maximum_kPa
                << " kPa" << std::endl;
        }
    }
  } // namespace



  PathFollowing::Result
  follow_load_path(HyperelasticProblem                   &problem,
                   const DesignConfiguration             &design,
                   const Settings                        &settings,
                   const std::vector<const Functional *> &functionals,
                   const std::vector<double>             &targets,
                   const std::string                     &directory,
                   const ConditionalOStream              &pcout)
  {
    const MPI_Comm comm = problem.get_dof_handler().get_communicator();
    // An earlier analysis's verdict goes first: a kill on the way leaves
    // load_path.csv up to the last converged step and no stop reason.
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      for (const char *name : {"/stop_reason.txt", "/load_path_summary.csv"})
        {
          std::error_code error;
          std::filesystem::remove(directory + name, error);
        }
    HyperelasticProblem::Vector a = problem.create_vector();
    const double initial_volume   = cavity_volume(problem, design, a);

    std::vector<std::string> columns{"step",
                                     "load_factor",
                                     "pressure_kPa",
                                     "cavity_volume_mm3",
                                     "delta_volume_mm3",
                                     "design_mean_ux_mm",
                                     "design_mean_inward_radial_mm"};
    // Each objective and constraint along the whole path (its value as if
    // its target were the current load factor; one of several states only
    // at the last of them).
    for (const auto *f : functionals)
      columns.push_back(f->name());
    // The smallest positive mu of K(a) phi = mu K_0 phi (past a fold the
    // negative mu nearest zero), K_0 the tangent at rest without the bulk
    // term (StabilityMetric): each mode's stiffness relative to its shear
    // stiffness at rest.
    std::unique_ptr<StabilityMetric> metric;
    if (settings.output.stability)
      {
        metric = std::make_unique<StabilityMetric>(problem);
        columns.emplace_back("stability");
        pcout << "Stability at rest (the smallest positive mu of K phi = mu K_0 phi, K_0 the "
              << "tangent at rest without the bulk term; at least 1): "
              << lowest_eigenvalue(problem, a, 0., 1e-6, 100, &metric->matrix()).value
              << std::endl;
      }
    for (const auto *c : {"newton_iterations",
                          "residual_norm_N",
                          "at_target",
                          "limit_point",
                          "self_contact"})
      columns.emplace_back(c);
    CsvWriter load_path(directory + "/load_path.csv", columns, comm);
    PvdSeries pvd(directory + "/solution.pvd", comm);

    // The displacement history of named surface points, for markers
    // tracked on video (only if any are named).
    std::unique_ptr<TrackedPoints> tracked;
    std::unique_ptr<CsvWriter>     tracked_csv;
    if (!settings.output.tracked_points.empty())
      {
        tracked = std::make_unique<TrackedPoints>(problem,
                                                  design,
                                                  settings.output.tracked_points);
        tracked->print(pcout);
        std::vector<std::string> tracked_columns{"step",
                                                 "load_factor",
                                                 "pressure_kPa"};
        for (const auto &c : tracked->csv_columns())
          tracked_columns.push_back(c);
        tracked_csv = std::make_unique<CsvWriter>(directory +
                                                    "/tracked_points.csv",
                                                  tracked_columns,
                                                  comm);
      }

    std::vector<Extrema> extrema(functionals.size());
    unsigned int         vtu_counter = 0;
    bool                 in_contact  = false;
    std::map<double, HyperelasticProblem::Vector> target_states;
    // The case's own targets (not the final analysis' equal steps): their
    // states for the functionals of several states, and where "Deformed
    // STL" writes the deformed surface.
    const std::vector<double> design_targets = case_targets(settings);
    const auto   record      = [&](const PathFollowing::PathPoint  &point,
                            const HyperelasticProblem::Vector &state) {
      const bool at_design_target =
        point.at_target && std::binary_search(design_targets.begin(),
                                              design_targets.end(),
                                              point.load_factor);
      if (at_design_target)
        target_states[point.load_factor] = state;
      const double volume           = cavity_volume(problem, design, state);
      const auto [mean_ux, mean_in] = design_means(problem, design, state);
      const double p_kPa = point.load_factor * settings.loading.pressure_kPa;
      std::vector<std::string> row{std::to_string(point.step),
                                   CsvWriter::format(point.load_factor),
                                   CsvWriter::format(p_kPa),
                                   CsvWriter::format(volume),
                                   CsvWriter::format(volume - initial_volume),
                                   CsvWriter::format(mean_ux),
                                   CsvWriter::format(mean_in)};
      for (unsigned int i = 0; i < functionals.size(); ++i)
        {
          const Functional &f           = *functionals[i];
          const auto       &lf          = f.load_factors();
          const bool        shape_alone = lf.empty();
          // One of the shape alone (thin walls) is the same all along; one of
          // several states (compliance ratio) has a value only at the last of
          // its targets, once the path has passed them all, and one of the
          // tangent at its load factor (softening) only there.
          double value = std::nan("");
          if (shape_alone && !std::isnan(extrema[i].at_target))
            value = extrema[i].at_target;
          else if (lf.size() <= 1 && f.along_load_path())
            value = f.evaluate_at(problem, design, state);
          else if (point.at_target && point.load_factor == lf.back())
            {
              Functional::States at;
              for (const double l : lf)
                if (const auto it = target_states.find(l); it != target_states.end())
                  at.push_back(&it->second);
              // A state the quantity refuses (softening past a limit point)
              // is a NaN in the table, not the end of the analysis.
              if (at.size() == lf.size())
                try
                  {
                    extrema[i].at_target = value = f.evaluate(problem, design, at, nullptr);
                  }
                catch (const StepFailure &failure)
                  {
                    pcout << "  " << f.name() << " at load factor " << lf.back()
                          << ": no value (" << failure.what() << ")" << std::endl;
                  }
            }
          row.push_back(CsvWriter::format(value));
          extrema[i].add(value, p_kPa);
          if (shape_alone || (point.at_target && f.load_factors().size() == 1 &&
                              f.load_factors()[0] == point.load_factor))
            extrema[i].at_target = value;
        }
      double stability = std::nan("");
      if (settings.output.stability)
        {
          const auto eigen =
            lowest_eigenvalue(problem, state, point.load_factor, 1e-6, 100, &metric->matrix());
          stability = eigen.value;
          row.push_back(CsvWriter::format(stability));
          if (eigen.residual > 1e-4) // the value to 1e-4 relative at worst
            pcout << "  warning: the stability eigenvalue did not converge in "
                  << eigen.iterations << " Lanczos steps (error bound " << eigen.residual
                  << "); its value is approximate" << std::endl;
        }
      row.push_back(std::to_string(point.newton_iterations));
      row.push_back(CsvWriter::format(point.residual_norm));
      row.push_back(point.at_target ? "1" : "0");
      row.push_back(point.limit_point ? "1" : "0");
      // Walls that touch: the deformed surface passes through itself, as
      // the model has no contact (castability.csv's deformed self-contact).
      const auto               u = problem.ghosted(state);
      const Deformation        deformed{problem.get_dof_handler(), u};
      const SelfIntersection   contact = design_self_intersections(design, &deformed);
      row.push_back(contact.pairs > 0 ? "1" : "0");
      load_path.add_row(row);
      if (settings.output.deformed_stl && at_design_target)
        {
          std::ostringstream name;
          name << directory << "/deformed_" << p_kPa << "kPa.stl";
          write_design_stl(design, name.str(), &deformed);
        }
      if (tracked)
        {
          std::vector<std::string> tracked_row{std::to_string(point.step),
                                               CsvWriter::format(point.load_factor),
                                               CsvWriter::format(p_kPa)};
          for (const auto &entry : tracked->csv_entries(state))
            tracked_row.push_back(entry);
          tracked_csv->add_row(tracked_row);
        }
      if (settings.output.vtu_output == OutputParameters::VtuOutput::every_step ||
          (settings.output.vtu_output == OutputParameters::VtuOutput::targets &&
           point.at_target))
        pvd.add(point.load_factor,
                problem.write_vtu(state, directory, "solution", vtu_counter++));
      pcout << "step " << std::setw(3) << point.step << "  lambda "
            << std::setprecision(10) << point.load_factor << "  p " << p_kPa
            << " kPa  V " << volume << " mm^3  dV " << volume - initial_volume
            << " mm^3  mean u_x " << mean_ux << " mm  mean u_in " << mean_in
            << " mm  Newton " << point.newton_iterations;
      if (settings.output.stability)
        pcout << "  stability " << stability;
      pcout << (point.limit_point ? "  (limit point)" : "") << std::endl;
      if (contact.pairs > 0 && !in_contact)
        pcout << "  warning: at " << p_kPa << " kPa the deformed surface passes "
              << "through itself (" << contact.pairs << " pairs of triangles, one near ("
              << contact.where << ") mm): walls in contact, which the model does "
              << "not resolve; its results beyond this pressure are not the part's"
              << std::endl;
      in_contact = contact.pairs > 0;
      if (settings.loading.maximum_volume_ratio > 0 &&
          volume > settings.loading.maximum_volume_ratio * initial_volume)
        return std::string("the cavity volume exceeded ") +
               Utilities::to_string(settings.loading.maximum_volume_ratio) +
               " times its initial volume";
      return std::string();
    };

    record({0, 0., 0, 0., false}, a);
    const PathFollowing::Result result = PathFollowing(settings.loading.path).run(
      problem, settings.newton, targets, record, pcout);
    pcout << "Stopped: " << result.stop_reason << std::endl;
    if (!functionals.empty())
      write_summary(functionals,
                    extrema,
                    settings.loading.pressure_kPa,
                    directory,
                    comm,
                    pcout);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_whole_file(directory + "/stop_reason.txt", result.stop_reason + "\n");
    return result;
  }



  AnalysisBody::AnalysisBody(const Settings   &settings,
                             const MPI_Comm    comm,
                             const std::string &mesh_file)
    : triangulation(std::make_unique<parallel::fullydistributed::Triangulation<3>>(comm))
  {
    design  = std::make_unique<DesignConfiguration>(
      *triangulation, settings.geometry.create_triangulation(*triangulation, mesh_file));
    problem = std::make_unique<HyperelasticProblem>(*triangulation,
                                                    design->get_mapping(),
                                                    settings.geometry,
                                                    *settings.material,
                                                    settings.loading.pressure_kPa * 1e-3);
    problem->setup_system();
    problem->set_linear_solver(settings.linear_solver);
  }



  int
  run_analysis(const Settings &settings, const MPI_Comm comm)
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(comm) == 0);
    Timer              setup_timer;

    const AnalysisBody body(settings, comm);
    HyperelasticProblem       &problem = *body.problem;
    const DesignConfiguration &design  = *body.design;
    pcout << "Mesh: " << body.triangulation->n_global_active_cells()
          << " tetrahedra, " << problem.get_dof_handler().n_dofs()
          << " degrees of freedom" << std::endl;

    const double initial_volume =
      cavity_volume(problem, design, problem.create_vector());
    AssertThrow(initial_volume > 0,
                ExcMessage(settings.input->where("Geometry",
                                                 "Pressure boundary ids") +
                           ": the pressure boundary does not enclose a "
                           "positive cavity volume (V = " +
                           Utilities::to_string(initial_volume) +
                           " mm^3). It must be all walls of one closed "
                           "cavity (or a cavity cut by symmetry planes "
                           "through the origin)."));
    pcout << "Cavity volume: " << initial_volume << " mm^3" << std::endl;

    // Input is checked: only now touch the output directory.
    const double setup_time = setup_timer.wall_time();
    const OutputDirectory out(settings.output_directory, comm);
    out.write_parameters(settings.prm);
    std::vector<const Functional *> functionals;
    for (const auto &f : settings.functionals)
      functionals.push_back(f.get());

    Timer path_timer;
    const PathFollowing::Result result =
      follow_load_path(problem,
                       design,
                       settings,
                       functionals,
                       case_targets(settings),
                       out.path(),
                       pcout);
    path_timer.stop();
    if (settings.output.print_timings)
      {
        const auto &stats = problem.get_statistics();
        pcout << "Wall time: mesh and setup " << setup_time
              << " s, path following with output " << path_timer.wall_time()
              << " s\n  " << stats.summary() << std::endl;
      }
    return result.failed ? 1 : 0;
  }
} // namespace softopt
