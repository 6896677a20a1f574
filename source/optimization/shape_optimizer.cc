#include <deal.II/base/timer.h>

#include <softopt/base/on_rank_zero.h>
#include <softopt/io/stl_writer.h>
#include <softopt/optimization/checkpoint.h>
#include <softopt/optimization/shape_optimizer.h>
#include <softopt/shape/remesh.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace softopt
{
  namespace
  {
    /** The field of a history.csv @p row under @p column of @p header
     * (numbers only, no quoting); empty if there is none. */
    std::string
    csv_field(const std::string &header, const std::string &row, const std::string &column)
    {
      std::istringstream names(header), fields(row);
      std::string        name, field;
      while (std::getline(names, name, ',') && std::getline(fields, field, ','))
        if (name == column)
          return field;
      return "";
    }
  } // namespace



  ShapeOptimizer::ShapeOptimizer(const OptimizationParameters &parameters,
                                 const OutputParameters       &output,
                                 DesignProblem                &problem,
                                 const OutputDirectory        &out)
    : parameters(parameters)
    , output(output)
    , problem(problem)
    , out(out)
    , comm(problem.get_communicator())
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
  {
    Assert(!problem.functionals().empty() &&
             problem.functionals().front()->kind() == Functional::Kind::objective,
           ExcMessage("The design loop needs an objective first."));
  }



  ShapeOptimizer::~ShapeOptimizer()
  {
    problem.log_paths(nullptr, ""); // before path_log is destroyed
  }



  std::string
  ShapeOptimizer::run(const bool restart)
  {
    const auto        &opt   = parameters;
    DesignIterate      x     = problem.initial_iterate();
    unsigned int       k     = restart ? resume(x) : 0;
    const unsigned int first = k;
    first_iteration          = k;
    any_accepted             = restart; // the checkpoint's run accepted some
    if (!restart)
      {
        reset_mma(x);
        std::vector<std::string> columns{"iteration"};
        for (const auto *f : problem.functionals())
          columns.push_back(f->name());
        for (const auto *c : {"max_design_change_mm", "wall_time_s",
                              "newton_iterations", "filter_iterations",
                              "min_J_psi", "worst_quality", "worst_element_x_mm",
                              "worst_element_y_mm", "worst_element_z_mm",
                              "from_rest_difference", "branch_switched", "cells"})
          columns.emplace_back(c);
        history = std::make_unique<CsvWriter>(out.file("history.csv"), columns, comm);
      }
    // The steps and halvings of every path from zero (paths.log): what an
    // iteration that fell back to one spent its time on.
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        path_log.open(out.file("paths.log"), restart ? std::ios::app : std::ios::trunc);
        if (restart) // the iterations from k on above are the interrupted run's
          path_log << "restart at iteration " << k << " from the checkpoint" << std::endl;
      }

    for (; k < opt.maximum_iterations; ++k)
      {
        // The state at the top of the iteration; a restart from it makes
        // the iteration's mesh update as the uninterrupted run does.
        if (k > first && opt.every(k, opt.checkpoint_interval))
          Checkpoint::save(out.path(), k, x);
        const double new_size = opt.scheduled_mesh_size(k, mesh_made_at(x)); // 0: none
        const bool   mesh_update = opt.planned_mesh_update(k) ||
                                 new_size > 0 || elements_collapsing(k, x);
        auto before_update = mesh_update ? update_mesh(k, x, new_size) : // X_o <- X_o + psi(d), d <- 0
                                           std::nullopt;

        // After a warm start, check the states against those from rest
        // every "Path from rest interval" iterations, at every mesh update
        // (and new mesh), after a check that switched branch (the designs
        // there have several equilibria: the warm start can leave the
        // physical one again at any iteration), and at the last iteration,
        // whose values the run reports. A restart checks where the
        // uninterrupted run does: the checkpoint holds its states.
        const bool check_from_rest =
          opt.from_rest_interval > 0 &&
          (switched_last_check || opt.every(k, opt.from_rest_interval) ||
           mesh_update || k + 1 == opt.maximum_iterations);

        Timer               timer;
        std::vector<double> values; // psi(d), X, path to every target
        problem.log_paths(path_log.is_open() ? &path_log : nullptr,
                          "iteration " + std::to_string(k));
        const std::string   refused =
          evaluate_or_halve(k, before_update, check_from_rest, x, values);
        if (!refused.empty())
          {
            stopped_on_error = true;
            return refused;
          }
        any_accepted = true;
        const auto &branch  = problem.branch_check(); // states from rest?
        switched_last_check = branch && branch->switched;
        const auto gradients = problem.gradients(x); // adjoints, Eqs. sens01-06
        x.accepted           = x.d;
        if ((k == 0 && opt.output_interval > 0) || opt.every(k, opt.output_interval))
          write_snapshot(k, x);
        const double change = mma_step(x, values, gradients);
        record(k, values, branch, change, timer.wall_time());
      }
    // The final design, unless just written.
    const bool written = opt.output_interval > 0 &&
                         (k - 1 == 0 || opt.every(k - 1, opt.output_interval));
    if (k > first && !written)
      write_snapshot(k - 1, x);
    return "reached the maximum number of iterations (" +
           std::to_string(opt.maximum_iterations) + ")";
  }



  long
  ShapeOptimizer::mesh_made_at(const DesignIterate &x)
  {
    // A new mesh is out/mesh-<k>.msh (update_mesh); the first one is not.
    const std::string stem = std::filesystem::path(x.mesh_file).stem().string();
    if (stem.rfind("mesh-", 0) != 0)
      return -1;
    char      *end = nullptr;
    const long k   = std::strtol(stem.c_str() + 5, &end, 10);
    return *end == '\0' ? k : -1;
  }



  bool
  ShapeOptimizer::failed() const
  {
    return stopped_on_error;
  }



  bool
  ShapeOptimizer::accepted_a_design() const
  {
    return any_accepted;
  }



  std::optional<DesignIterate>
  ShapeOptimizer::update_mesh(const unsigned int k, DesignIterate &x, const double mesh_size)
  {
    // The mesh moves to the design d, not yet evaluated; if that design is
    // refused the update is undone and the step halved on the old mesh.
    std::optional<DesignIterate> before = x;
    try
      {
        problem.update_mesh(x);
        reset_mma(x);
      }
    catch (const std::exception &)
      {
        x = *before; // evaluate() refuses d
        problem.restore(x);
        return std::nullopt;
      }

    // Elements the design flattened stay flat in the updated mesh, and the
    // schedule asks for a finer one: mesh the design anew (not undone: the
    // design is the same).
    const double quality = problem.filter_result().worst_quality;
    if (quality < parameters.remesh_quality || mesh_size > 0)
      {
        const std::string file = out.file("mesh-" + std::to_string(k) + ".msh");
        unsigned long     n_outside = 0;
        try
          {
            n_outside = problem.remesh(x, file, mesh_size);
          }
        catch (const std::exception &e)
          {
            pcout << "  iteration " << k << ": remeshing failed, the run goes "
                  << "on with the updated mesh: " << e.what() << std::endl;
            return before;
          }
        reset_mma(x);
        pcout << "  iteration " << k << ": ";
        if (mesh_size > 0)
          pcout << "the schedule's mesh size " << mesh_size << " mm (boundary edges "
                << std::setprecision(2)
                << mean_boundary_edge_length(problem.design_configuration())
                << std::setprecision(6) << " mm on average)";
        else
          pcout << "worst element quality " << quality << " < "
                << parameters.remesh_quality;
        pcout << ", the design is meshed anew: "
              << problem.hyperelastic_problem()
                   .get_dof_handler()
                   .get_triangulation()
                   .n_global_active_cells()
              << " tetrahedra (" << file << "); "
              << (n_outside == 0 ?
                    "the states carry over" :
                    std::to_string(n_outside) + " new points outside the old "
                    "mesh: the states follow the path from zero")
              << std::endl;
        if (const std::string note = problem.last_new_mesh().note(); !note.empty())
          pcout << "  iteration " << k << ": " << note << std::endl;
        return std::nullopt;
      }
    return before;
  }



  bool
  ShapeOptimizer::elements_collapsing(const unsigned int k, const DesignIterate &x) const
  {
    // Elements the design has flattened since the last mesh update (not
    // those of a mesh that is poor itself: remeshing would not help).
    const double threshold = parameters.remesh_quality;
    if (k == 0 || threshold == 0 || parameters.planned_mesh_update(k))
      return false;
    const auto [design, mesh] = problem.element_quality(x);
    if (design >= threshold || mesh < threshold)
      return false;
    pcout << "  iteration " << k << ": worst element quality " << design << " < "
          << threshold << " since the last mesh update: the mesh update "
          << "comes forward to this iteration" << std::endl;
    return true;
  }



  std::string
  ShapeOptimizer::evaluate_or_halve(const unsigned int            k,
                                    std::optional<DesignIterate> &before_update,
                                    const bool                    check_from_rest,
                                    DesignIterate                &x,
                                    std::vector<double>          &values)
  {
    for (unsigned int halving = 0;; ++halving)
      try
        {
          values = problem.evaluate(x, check_from_rest);
          return "";
        }
      catch (const std::exception &e)
        {
          const std::string reason = user_message(e);
          if (before_update)
            {
              x = *before_update; // the old mesh, its d and its MMA
              before_update.reset();
              problem.restore(x);
            }
          Vector step = x.d;
          step -= x.accepted;
          // At the first iteration and after a new mesh d = accepted = 0:
          // nothing to halve.
          if (halving == parameters.step_halvings || step.linfty_norm() == 0)
            return "the design of iteration " + std::to_string(k) +
                   " was refused: " + reason +
                   (k == 0 ? " No design was accepted: the initial design "
                             "itself cannot be analyzed (try it with \"softopt "
                             "analyze\"), so no design.stl and no final analysis "
                             "are written." :
                             " The last accepted design is that of iteration " +
                               std::to_string(k - 1) + "; checkpoints are in " +
                               Checkpoint::directory(out.path()) + ".");
          // d <- (d_accepted + d) / 2: a shorter step in the same direction,
          // which MMA's next update starts from.
          x.d.sadd(0.5, 0.5, x.accepted);
          pcout << "  iteration " << k << ": design refused (" << reason
                << "); step halved" << std::endl;
        }
  }



  void
  ShapeOptimizer::reset_mma(DesignIterate &x) const
  {
    std::vector<MMA::RowType> rows;
    for (const auto *f : problem.functionals())
      rows.push_back(f->kind() == Functional::Kind::objective ?
                       MMA::RowType::objective :
                       MMA::RowType::constraint);
    MMA::Settings mma_settings;
    mma_settings.move_limit = parameters.move_limit;
    x.mma.emplace(x.d.locally_owned_size(), rows, comm, mma_settings);
  }



  unsigned int
  ShapeOptimizer::resume(DesignIterate &x)
  {
    reset_mma(x); // the layout that Checkpoint::load fills
    const unsigned int k =
      Checkpoint::load(out.path(), problem.hyperelastic_problem().create_vector(), x);
    problem.restore(x);

    // history.csv keeps its header and the rows before the checkpoint; a
    // row cut short by a kill, or a blank line, is dropped. The row just
    // before the checkpoint says whether its check switched branch, so
    // that the restart checks the next design as the uninterrupted run does.
    std::vector<std::string> lines;
    long                     last_row = -1;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ifstream in(out.file("history.csv"));
        for (std::string line; std::getline(in, line);)
          {
            if (lines.empty())
              {
                lines.push_back(line);
                continue;
              }
            const auto fields = std::count(line.begin(), line.end(), ',');
            char      *end    = nullptr;
            const long row    = std::strtol(line.c_str(), &end, 10);
            if (end == line.c_str() || *end != ',' ||
                fields != std::count(lines[0].begin(), lines[0].end(), ','))
              continue;
            last_row = std::max(last_row, row);
            if (row < long(k))
              lines.push_back(line);
            if (row + 1 == long(k))
              switched_last_check = csv_field(lines[0], line, "branch_switched") == "1";
          }
      }
    switched_last_check = Utilities::MPI::broadcast(comm, switched_last_check, 0);
    // A restart that would not run further would only rewrite a finished
    // run's results (a run killed in its final analysis is not finished).
    bool finished = false;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code code;
        finished = std::filesystem::exists(out.file("final_analysis/stop_reason.txt"), code);
      }
    last_row = Utilities::MPI::broadcast(comm, last_row, 0);
    finished = Utilities::MPI::broadcast(comm, finished, 0);
    AssertThrow(!finished || last_row + 1 < long(parameters.maximum_iterations),
                ExcMessage("The run in <" + out.path() + "> has iterations up to " +
                           std::to_string(last_row) + " (history.csv); with "
                           "\"Maximum iterations = " +
                           std::to_string(parameters.maximum_iterations) +
                           "\" (subsection Optimization) a restart would not "
                           "run further and would only rewrite its results. "
                           "Raise Maximum iterations above " +
                           std::to_string(last_row + 1) + " to go on."));
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // The verdicts of the run being continued no longer hold.
        std::error_code error;
        for (const char *name : {"stop_reason.txt",
                                 "final_analysis/stop_reason.txt",
                                 "final_analysis/load_path_summary.csv"})
          std::filesystem::remove(out.file(name), error);
        std::string text;
        for (const auto &line : lines)
          text += line + '\n';
        write_whole_file(out.file("history.csv"), text);
      }
    MPI_Barrier(comm);
    history = std::make_unique<CsvWriter>(out.file("history.csv"), comm);
    pcout << "Restarting at iteration " << k << " from "
          << Checkpoint::directory(out.path()) << std::endl;
    return k;
  }



  double
  ShapeOptimizer::mma_step(DesignIterate             &x,
                           const std::vector<double> &values,
                           const std::vector<Vector> &gradients) const
  {
    // The min-max form needs positive objective rows (z >= 0): shifting
    // every g_i by the same constant C only moves z, and C above the
    // largest |g_i| keeps the bound z >= 0 inactive.
    const auto is_objective = [&](const unsigned int i) {
      return problem.functionals()[i]->kind() == Functional::Kind::objective;
    };
    double shift = 1;
    for (unsigned int i = 0; i < values.size(); ++i)
      if (is_objective(i))
        shift = std::max(shift, 1 + 2 * std::abs(values[i]));
    // A constraint f = Q - Tolerance enters as f / |Tolerance| = Q /
    // |Tolerance| - 1 (magnitude(0) = |Tolerance|): its relative
    // violation. Its elastic variable then costs c_i for a violation the
    // size of the tolerance, whatever the unit of Q; unscaled,
    // thin walls (Tolerance 1e-4) cost 1000 * 4.8e-4 = 0.5 at Q = 5.8e-4,
    // less than the objective gained, and MMA's regularization (raa0)
    // outweighed its gradients.
    std::vector<double> row_scale(values.size(), 1.);
    for (unsigned int i = 0; i < values.size(); ++i)
      if (!is_objective(i) && problem.functionals()[i]->magnitude(0.) > 0)
        row_scale[i] = 1. / problem.functionals()[i]->magnitude(0.);
    std::vector<double> rows = values;
    for (unsigned int i = 0; i < values.size(); ++i)
      rows[i] = row_scale[i] * rows[i] + (is_objective(i) ? shift : 0.);

    const IndexSet owned = x.d.locally_owned_elements();
    const std::vector<types::global_dof_index> indices(owned.begin(), owned.end());
    const auto local = [&](const Vector &v) {
      std::vector<double> entries(indices.size());
      v.extract_subvector_to(indices.begin(), indices.end(), entries.begin());
      return entries;
    };
    std::vector<double> d = local(x.d);
    std::vector<std::vector<double>> dg;
    std::vector<ArrayView<const double>> dg_views;
    for (unsigned int i = 0; i < gradients.size(); ++i)
      {
        dg.push_back(local(gradients[i]));
        for (double &entry : dg.back())
          entry *= row_scale[i];
      }
    for (const auto &g : dg)
      dg_views.emplace_back(g);
    const double bound = parameters.design_bound;
    const std::vector<double> dmin(d.size(), -bound), dmax(d.size(), bound);

    x.mma->update(d, 0., {}, rows, dg_views, dmin, dmax);
    x.d.set(indices, d);
    x.d.compress(VectorOperation::insert);
    return x.mma->last_step();
  }



  void
  ShapeOptimizer::record(const unsigned int                               iteration,
                         const std::vector<double>                       &values,
                         const std::optional<DesignProblem::BranchCheck> &branch,
                         const double                                     change,
                         const double                                     wall_time)
  {
    const auto &health = problem.filter_result();
    std::vector<std::string> row{std::to_string(iteration)};
    for (const double v : values)
      row.push_back(CsvWriter::format(v));
    row.push_back(CsvWriter::format(change));
    row.push_back(CsvWriter::format(wall_time));
    row.push_back(std::to_string(problem.path_report().newton_iterations));
    row.push_back(std::to_string(health.iterations));
    row.push_back(CsvWriter::format(health.min_J_psi));
    row.push_back(CsvWriter::format(health.worst_quality));
    for (unsigned int c = 0; c < 3; ++c)
      row.push_back(CsvWriter::format(health.worst_element[c]));
    const bool compared = branch.has_value();
    row.push_back(compared ? CsvWriter::format(branch->difference) : "");
    row.push_back(compared ? (branch->switched ? "1" : "0") : "");
    row.push_back(std::to_string(
      problem.hyperelastic_problem().get_dof_handler().get_triangulation().n_global_active_cells()));
    history->add_row(row);

    const auto &path = problem.path_report();
    pcout << "iteration " << std::setw(4) << iteration;
    for (unsigned int i = 0; i < values.size(); ++i)
      pcout << "  " << problem.functionals()[i]->name() << " "
            << std::setprecision(8) << values[i];
    pcout << "  max|dd| " << std::setprecision(4) << change << " mm  min J_psi "
          << health.min_J_psi << "  Newton " << path.newton_iterations
          << (path.warm_started ? " (warm)" : "");
    if (!path.secant_failure.empty())
      pcout << " (from the last design's states: the secant start failed, "
            << path.secant_failure << ")";
    if (!path.warm_start_failure.empty() && path.substeps > 0)
      pcout << " (in " << path.substeps << " design substeps: Newton failed from the last "
            << "design's states, " << path.warm_start_failure << ")";
    else if (!path.warm_start_failure.empty())
      pcout << " (path from zero: the warm start failed, " << path.warm_start_failure
            << (path.substep_failure.empty() ? "" : "; the design substeps failed, " +
                                                       path.substep_failure)
            << ")";
    if (compared)
      pcout << "  from rest: " << (branch->switched ? "another branch" : "same branch")
            << " (" << std::setprecision(2) << branch->difference << ")"
            << (branch->switched ? ", the run goes on from the states from rest" : "");
    if (output.print_timings)
      pcout << "  " << std::setprecision(3) << wall_time << " s";
    pcout << std::endl;
  }



  void
  ShapeOptimizer::write_snapshot(const unsigned int iteration, const DesignIterate &x)
  {
    if (output.vtu_output == OutputParameters::VtuOutput::none)
      return;
    // The design's surface, small enough to keep every snapshot of a long
    // run (the paper's panel a: scripts/render_snapshots).
    std::ostringstream stl;
    stl << "snapshots/design_" << std::setw(4) << std::setfill('0') << iteration << ".stl";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::create_directories(out.file("snapshots"));
    write_design_stl(problem.design_configuration(), out.file(stl.str()));

    const auto &physics = problem.hyperelastic_problem();
    const auto  add     = [&](const std::string &name, const Vector &a) {
      auto &series = snapshots[name];
      if (!series) // a restart lists the snapshots before it, too
        series = std::make_unique<PvdSeries>(out.file(name + ".pvd"),
                                             comm,
                                             double(first_iteration));
      series->add(iteration, physics.write_vtu(a, out.path(), name, iteration));
    };
    add("design", physics.create_vector());
    for (const auto &[load_factor, a] : x.states)
      {
        std::ostringstream name;
        name << "deformed_at_" << load_factor;
        add(name.str(), a);
      }
  }
} // namespace softopt
