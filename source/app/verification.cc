#include <deal.II/base/mpi.h>

#include <softopt/app/analysis.h>
#include <softopt/app/settings.h>
#include <softopt/app/verification.h>
#include <softopt/io/csv_writer.h>
#include <softopt/io/output_directory.h>
#include <softopt/io/parameter_differences.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/shape/remesh.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <tuple>

namespace softopt
{
  void
  VerificationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    prm.declare_entry(
      "Mesh sizes",
      "",
      Patterns::List(Patterns::Double(1e-6), 0),
      "Element sizes in mm, for example \"2, 1\" (empty: none). After "
      "\"optimize\", and with \"softopt verify CASE.prm\" for a finished "
      "run, the final design is meshed anew at each size, from its curved "
      "boundary refined to that size, and analyzed at the targets: "
      "verification.csv then gives each functional on the optimization "
      "mesh and on each finer mesh, so you see how far the run's values "
      "can be trusted. Each size costs one analysis on that mesh.");
    prm.declare_entry(
      "Out-of-core factors",
      "false",
      Patterns::Bool(),
      "The verification meshes' factors on disk, as subsection \"Linear "
      "solver\"'s entry of that name does for every factorization: for "
      "meshes whose factors do not fit in memory (at 0.8 mm about 205,000 "
      "tetrahedra, over 24 GB in memory on one rank), while the "
      "optimization's stay in memory (on disk they made a 2 mm design "
      "iteration about twice as slow; doc/benchmarks.md).");
    prm.leave_subsection();
  }



  void
  VerificationParameters::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    prm.enter_subsection("Verification");
    mesh_sizes  = parse_doubles(prm.get("Mesh sizes"), input.where("Verification", "Mesh sizes"));
    out_of_core = prm.get_bool("Out-of-core factors");
    prm.leave_subsection();
  }



  std::vector<double>
  values_at_targets(const HyperelasticProblem             &problem,
                    const DesignConfiguration             &design,
                    const std::vector<const Functional *> &functionals,
                    const PathFollowing::Result           &result)
  {
    std::map<double, const HyperelasticProblem::Vector *> states;
    for (unsigned int i = 0; i < result.target_states.size(); ++i)
      states[result.target_load_factors[i]] = &result.target_states[i];
    std::vector<double> values;
    for (const auto *f : functionals)
      {
        Functional::States at;
        for (const double load_factor : f->load_factors())
          if (const auto it = states.find(load_factor); it != states.end())
            at.push_back(it->second);
        values.push_back(at.size() == f->load_factors().size() ?
                           f->evaluate(problem, design, at, nullptr) :
                           std::nan(""));
      }
    return values;
  }



  double
  optimization_mesh_size(const Settings &settings, const DesignConfiguration &design)
  {
    // After a schedule, the last size the run reached (if it ran that far).
    const auto &schedule = settings.optimization.mesh_size_schedule;
    for (auto entry = schedule.rbegin(); entry != schedule.rend(); ++entry)
      if (entry->first < settings.optimization.maximum_iterations)
        return entry->second;
    const std::string &file = settings.geometry.mesh_file;
    if (file.size() > 4 && file.substr(file.size() - 4) == ".geo")
      return settings.geometry.mesh_size;
    return mean_boundary_edge_length(design);
  }



  namespace
  {
    /** "2mm", "1.5mm": the name of a mesh size in file names. */
    std::string
    size_name(const double h)
    {
      std::ostringstream name;
      name << h << "mm";
      return name.str();
    }

    std::vector<const Functional *>
    functionals_of(const Settings &settings)
    {
      std::vector<const Functional *> functionals;
      for (const auto &f : settings.functionals)
        functionals.push_back(f.get());
      return functionals;
    }

    /** The body's row: its values at the targets of its final analysis,
     * in @p directory. */
    std::pair<VerificationRow, bool>
    analyze(const Settings           &settings,
            const AnalysisBody       &body,
            const double              mesh_size_mm,
            const std::string        &directory,
            const ConditionalOStream &pcout)
    {
      const MPI_Comm comm = body.problem->get_dof_handler().get_communicator();
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        std::filesystem::create_directories(directory);
      MPI_Barrier(comm);
      const auto functionals = functionals_of(settings);
      const auto result      = follow_load_path(*body.problem,
                                           *body.design,
                                           settings,
                                           functionals,
                                           final_analysis_path(settings),
                                           directory,
                                           pcout);
      VerificationRow row;
      row.mesh_size_mm = mesh_size_mm;
      row.cells        = body.triangulation->n_global_active_cells();
      row.dofs         = body.problem->get_dof_handler().n_dofs();
      row.values = values_at_targets(*body.problem, *body.design, functionals, result);
      return {row, !result.failed};
    }

    /** Each functional's value at its targets from a finished final
     * analysis, @p summary (its load_path_summary.csv, written when the
     * path ends); empty if there is none, it is not newer than each of
     * @p inputs (the run's parameters.prm and design.msh: edited or
     * replaced since), the path did not end at its last load factor (the
     * stop_reason.txt beside it: a failure after the last target makes
     * optimize exit 1, and so must verify), it lists functionals of
     * another count or kind (their names are positional: g_1, f_1, ...),
     * or a value is not a finite number (a target was not reached). */
    std::vector<double>
    values_of_final_analysis(const std::string                     &summary,
                             const std::vector<std::string>        &inputs,
                             const std::vector<const Functional *> &functionals)
    {
      std::error_code error;
      const auto      written = std::filesystem::last_write_time(summary, error);
      if (error)
        return {};
      for (const auto &input : inputs)
        if (!(written > std::filesystem::last_write_time(input, error)) || error)
          return {};
      std::string line;
      {
        std::ifstream stop(std::filesystem::path(summary).replace_filename("stop_reason.txt"));
        if (!std::getline(stop, line) || line != PathFollowing::reached_last_target)
          return {};
      }
      std::ifstream in(summary);
      if (!std::getline(in, line))
        return {};
      const auto header = Utilities::split_string_list(line, ',');
      const auto name   = std::find(header.begin(), header.end(), "functional");
      const auto value  = std::find(header.begin(), header.end(), "value_at_target");
      if (name == header.end() || value == header.end())
        return {};
      std::vector<double> values;
      for (const auto *f : functionals)
        {
          if (!std::getline(in, line))
            return {};
          const auto fields = Utilities::split_string_list(line, ',');
          if (fields.size() != header.size() || fields[name - header.begin()] != f->name())
            return {};
          const std::string &field = fields[value - header.begin()];
          char              *end   = nullptr;
          values.push_back(std::strtod(field.c_str(), &end));
          if (field.empty() || end != field.c_str() + field.size() ||
              !std::isfinite(values.back()))
            return {};
        }
      while (std::getline(in, line)) // no rows of other functionals
        if (line.find_first_not_of(" \r\t") != std::string::npos)
          return {};
      return values;
    }

    std::vector<std::string>
    csv_row(const VerificationRow &row)
    {
      std::vector<std::string> entries{CsvWriter::format(row.mesh_size_mm),
                                       std::to_string(row.cells),
                                       std::to_string(row.dofs)};
      for (const double v : row.values)
        entries.push_back(CsvWriter::format(v));
      return entries;
    }
  } // namespace



  bool
  verify_design(const Settings           &settings,
                const std::string        &design_mesh,
                const VerificationRow    &first,
                const OutputDirectory    &out,
                const ConditionalOStream &pcout)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    std::vector<std::string> columns{"mesh_size_mm", "cells", "dofs"};
    for (const auto &f : settings.functionals)
      columns.push_back(f->name());
    CsvWriter csv(out.file("verification.csv"), columns, comm);
    csv.add_row(csv_row(first));
    std::vector<VerificationRow> rows{first};
    bool                         all_solved = true;

    const AnalysisBody design(settings, comm, design_mesh);
    for (const double h : settings.verification.mesh_sizes)
      {
        const std::string name = size_name(h);
        const std::string mesh = out.file("verification/mesh_" + name + ".msh");
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          std::filesystem::create_directories(out.file("verification"));
        MPI_Barrier(comm);
        const NewMesh new_mesh = remesh_design(*design.design, mesh, h);
        const AnalysisBody fine(settings, comm, mesh);
        auto               solver = settings.linear_solver;
        solver.out_of_core |= settings.verification.out_of_core;
        fine.problem->set_linear_solver(solver);
        pcout << "\nVerification on a " << h << " mm mesh ("
              << fine.triangulation->n_global_active_cells() << " tetrahedra, "
              << fine.problem->get_dof_handler().n_dofs()
              << " degrees of freedom):" << std::endl;
        if (!new_mesh.note().empty())
          pcout << new_mesh.note() << std::endl;
        const auto [row, solved] =
          analyze(settings, fine, h, out.file("verification/" + name), pcout);
        csv.add_row(csv_row(row));
        rows.push_back(row);
        all_solved &= solved;
      }

    // A constraint's change relative to its quantity Q, not to f = Q -
    // Tolerance (near 0 when active).
    pcout << "\nVerification (verification.csv), against the optimization mesh"
          << " (a constraint f = Q - Tolerance relative to Q):" << std::endl;
    for (unsigned int i = 0; i < columns.size() - 3; ++i)
      {
        pcout << "  " << columns[i + 3] << ": " << std::setprecision(6)
              << first.values[i] << " (" << first.mesh_size_mm << " mm)";
        for (unsigned int r = 1; r < rows.size(); ++r)
          {
            const double v = rows[r].values[i];
            pcout << ", " << v << " (" << rows[r].mesh_size_mm << " mm, ";
            if (std::isnan(v))
              pcout << "target not reached)";
            else if (const double Q = settings.functionals[i]->magnitude(first.values[i]);
                     Q == 0) // thin walls with every wall thick enough
              pcout << std::showpos << v - first.values[i] << std::noshowpos << ")";
            else
              pcout << std::showpos << std::setprecision(2) << std::fixed
                    << 100 * (v - first.values[i]) / Q << std::noshowpos
                    << std::defaultfloat << std::setprecision(6) << " %)";
          }
        pcout << std::endl;
      }
    return all_solved;
  }



  int
  run_verification(const Settings &settings, const MPI_Comm comm)
  {
    ConditionalOStream pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0);
    const std::string  directory   = settings.output_directory;
    const std::string  design_mesh = directory + "/design.msh";
    AssertThrow(!settings.verification.mesh_sizes.empty(),
                ExcMessage(settings.input->where("Verification", "Mesh sizes") +
                           " is empty: \"verify\" needs at least one mesh size "
                           "(mm), for example \"2, 1\"."));
    AssertThrow(std::filesystem::exists(design_mesh),
                ExcMessage("\"verify\" checks the final design of a finished run, "
                           "but <" + directory + "> (the Output directory of " +
                           settings.input->path() + ") has no design.msh: run "
                           "\"softopt optimize " + settings.input->path() +
                           "\" first."));
    // The same problem as the run's: only what says how to optimize, how
    // to solve (e.g. out-of-core factors for a fine mesh), what to write
    // and how to verify may differ.
    if (std::filesystem::exists(directory + "/parameters.prm"))
      {
        const auto differences = parameter_differences(
          directory + "/parameters.prm",
          settings.prm,
          {"Command", "Output directory", "Print timings", "Output/*", "Optimization/*",
           "Shape filter/*", "Verification/*", "Linear solver/*", "Geometry/Mesh file",
           "Geometry/Mesh size", "Geometry/Mesh parameters"});
        if (!differences.empty())
          {
            std::string error = settings.input->path() + ": \"verify\" analyzes the "
                                "design of the run in <" + directory + "> with the "
                                "same physics, but these entries differ from its "
                                "parameters.prm:";
            for (const auto &d : differences)
              error += "\n  " + d;
            AssertThrow(false, ExcMessage(error + "\nRestore them."));
          }
      }
    const OutputDirectory out(directory, comm);
    const AnalysisBody    design(settings, comm, design_mesh);
    pcout << "The final design of <" << directory << "> (design.msh: "
          << design.triangulation->n_global_active_cells() << " tetrahedra, "
          << design.problem->get_dof_handler().n_dofs()
          << " degrees of freedom):" << std::endl;
    // The optimization mesh's row is the run's final analysis of this
    // design (from rest, like every row), unless it did not reach the end
    // of its path or is older than the parameters or the design (see
    // above).
    const double size = optimization_mesh_size(settings, *design.design);
    const std::string summary = directory + "/final_analysis/load_path_summary.csv";
    VerificationRow   first{size,
                          design.triangulation->n_global_active_cells(),
                          design.problem->get_dof_handler().n_dofs(),
                          Utilities::MPI::broadcast(
                            comm,
                            Utilities::MPI::this_mpi_process(comm) == 0 ?
                              values_of_final_analysis(summary,
                                                       {directory + "/parameters.prm",
                                                        design_mesh},
                                                       functionals_of(settings)) :
                              std::vector<double>(),
                            0)};
    bool solved = true;
    if (!first.values.empty())
      pcout << "  its values at the targets from the run's final analysis ("
            << summary << ")" << std::endl;
    else
      std::tie(first, solved) =
        analyze(settings, design, size, out.file("verification/design_mesh"), pcout);
    const bool fine_solved = verify_design(settings, design_mesh, first, out, pcout);
    return solved && fine_solved ? 0 : 1;
  }
} // namespace softopt
