#include <softopt/app/analysis.h>
#include <softopt/app/castability.h>
#include <softopt/app/settings.h>
#include <softopt/base/on_rank_zero.h>
#include <softopt/io/csv_writer.h>
#include <softopt/shape/self_intersection.h>
#include <softopt/shape/wall_thickness.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <tuple>
#include <iomanip>

namespace softopt
{
  void
  CastabilityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Castability");
    prm.declare_entry("Minimum wall thickness",
                      "1",
                      Patterns::Double(0),
                      "Walls of the design thinner than this (mm) get a "
                      "warning in castability.csv: about what casting in "
                      "PVS tolerates. The thickness at a surface node is "
                      "the distance to the opposite surface along the "
                      "inward normal (\"softopt check-design\", and at the "
                      "end of \"optimize\").");
    prm.declare_entry("Minimum gap",
                      "1",
                      Patterns::Double(0),
                      "Gaps outside the design narrower than this (mm) get "
                      "a warning: the distance to the next surface along "
                      "the outward normal, between two lobes or folds a "
                      "wall of the mold, across the cavity its core. "
                      "Measured on whole parts only (no symmetry planes).");
    prm.declare_entry("Sampling size",
                      "0",
                      Patterns::Double(0),
                      "How far apart (mm) the points are where walls and "
                      "gaps are measured, as in the quantity \"thin "
                      "walls\" (0: the faces' corner and midside nodes).");
    prm.leave_subsection();
  }



  void
  CastabilityParameters::parse_parameters(ParameterHandler &prm, const InputFile &)
  {
    prm.enter_subsection("Castability");
    minimum_wall_thickness = prm.get_double("Minimum wall thickness");
    minimum_gap            = prm.get_double("Minimum gap");
    sampling_size          = prm.get_double("Sampling size");
    prm.leave_subsection();
  }



  namespace
  {
    /** The pressure of the first row of @p load_path (a load_path.csv)
     * whose self_contact is 1; "" if none, "none" if there is no such file
     * or column (no final analysis yet). */
    std::string
    first_contact_pressure(const std::string &load_path)
    {
      std::ifstream in(load_path);
      std::string   line;
      if (!std::getline(in, line))
        return "none";
      const auto header   = Utilities::split_string_list(line, ',');
      const auto column   = std::find(header.begin(), header.end(), "self_contact");
      const auto pressure = std::find(header.begin(), header.end(), "pressure_kPa");
      if (column == header.end() || pressure == header.end())
        return "none";
      while (std::getline(in, line))
        {
          const auto fields = Utilities::split_string_list(line, ',');
          if (fields.size() == header.size() && fields[column - header.begin()] == "1")
            return fields[pressure - header.begin()];
        }
      return "";
    }



    /** Writes @p wall's field into @p vtu and adds its row "minimum
     * <measure>" (wall thickness, gap) to castability.csv with a line:
     * the smallest distance and where, "warning" below @p at_least (the
     * entry @p entry) or where an inward ray found no opposite wall (the
     * surface is not closed there); empty when every ray leaves the part
     * (gaps on a convex part). */
    void
    report_minimum(const WallThickness     &wall,
                   const std::string       &measure,
                   const double             at_least,
                   const std::string       &entry,
                   const std::string       &vtu,
                   const OutputDirectory   &out,
                   const MPI_Comm           comm,
                   CsvWriter               &csv,
                   ConditionalOStream      &pcout)
    {
      on_rank_zero(comm, [&]() { write_wall_thickness_vtu(wall, out.file(vtu)); });
      const bool found = std::isfinite(wall.minimum);
      const bool below = wall.minimum < at_least;
      const bool open  = !wall.outward && wall.n_without_opposite > 0;
      std::vector<std::string> row{measure, found ? CsvWriter::format(wall.minimum) : "", "mm"};
      for (unsigned int c = 0; c < 3; ++c)
        row.push_back(found ? CsvWriter::format(wall.where[c]) : "");
      row.push_back(below || open ? "warning" : "ok");
      csv.add_row(row);
      if (found)
        pcout << "  " << measure << ' ' << std::setprecision(4) << wall.minimum << " mm at ("
              << wall.where << ") mm: " << (below ? "warning, below " : "ok, at least ")
              << at_least << " mm (" << entry << "; the field is in " << vtu << ")" << std::endl;
      else
        pcout << "  " << measure << ": none, every " << (wall.outward ? "outward" : "inward")
              << " ray leaves the part" << (open ? "" : ", ok") << std::endl;
      if (open)
        pcout << "  warning: from " << wall.n_without_opposite << " surface nodes the "
              << "inward ray found no opposite wall (-1 in " << vtu << "): is the "
              << "surface closed?" << std::endl;
    }
  } // namespace



  void
  check_castability(const Settings            &settings,
                    const DesignConfiguration &design,
                    const OutputDirectory     &out,
                    ConditionalOStream        &pcout)
  {
    const MPI_Comm comm  = design.get_dof_handler().get_communicator();
    const auto     place = [](const Point<3> &p) {
      return std::vector<std::string>{CsvWriter::format(p[0]),
                                      CsvWriter::format(p[1]),
                                      CsvWriter::format(p[2])};
    };
    CsvWriter csv(out.file("castability.csv"),
                  {"check", "value", "unit", "x_mm", "y_mm", "z_mm", "verdict"},
                  comm);
    pcout << "Castability (castability.csv):" << std::endl;

    const auto         mirrors = settings.geometry.symmetry_planes();
    const unsigned int k = surface_subdivisions(design, settings.castability.sampling_size);
    // Gaps: rays outward, on whole parts only (on a part cut at symmetry
    // planes they would cross the open planes, where the mirrored part is
    // not).
    WallThickness                wall;
    std::optional<WallThickness> gap;
    if (mirrors.empty())
      std::tie(wall, gap) = walls_and_gaps(design, k);
    else
      wall = wall_thickness(design, mirrors, false, k);
    report_minimum(wall, "minimum wall thickness", settings.castability.minimum_wall_thickness,
                   "Minimum wall thickness", "wall_thickness.vtu", out, comm, csv, pcout);
    if (gap)
      report_minimum(*gap, "minimum gap", settings.castability.minimum_gap, "Minimum gap",
                     "gap.vtu", out, comm, csv, pcout);
    else
      {
        csv.add_row({"minimum gap", "", "mm", "", "", "", "not measured"});
        pcout << "  minimum gap: not measured, the part is cut at symmetry planes" << std::endl;
      }

    const auto crossing = design_self_intersections(design);
    std::vector<std::string> row{"self-intersections", std::to_string(crossing.pairs), "triangle pairs"};
    for (const auto &x : place(crossing.where))
      row.push_back(crossing.pairs > 0 ? x : "");
    row.push_back(crossing.pairs > 0 ? "refused" : "ok");
    csv.add_row(row);
    pcout << "  self-intersections: ";
    if (crossing.pairs > 0)
      pcout << crossing.pairs << " pairs of surface triangles, one near (" << crossing.where
            << ") mm: refused, the design cannot be cast" << std::endl;
    else
      pcout << "none, ok" << std::endl;

    // The first pressure of the final analysis at which the deformed
    // surface passes through itself (load_path.csv, self_contact).
    std::string first_contact;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      first_contact = first_contact_pressure(out.file("final_analysis/load_path.csv"));
    first_contact = Utilities::MPI::broadcast(comm, first_contact, 0);
    if (first_contact != "none")
      {
        const bool touches = !first_contact.empty();
        csv.add_row({"deformed self-contact", first_contact, "kPa", "", "", "",
                     touches ? "warning" : "ok"});
        pcout << "  deformed self-contact: "
              << (touches ? "walls touch from " + first_contact +
                              " kPa on (final_analysis/load_path.csv, self_contact): "
                              "warning, the model has no contact beyond" :
                            std::string("none along the final analysis, ok"))
              << std::endl;
      }
  }



  std::string
  final_design_mesh(const Settings &settings, const MPI_Comm comm)
  {
    const std::string design_mesh = settings.output_directory + "/design.msh";
    const bool        finished    = Utilities::MPI::broadcast( // the same mesh on every rank
      comm,
      Utilities::MPI::this_mpi_process(comm) == 0 && std::filesystem::exists(design_mesh),
      0);
    return finished ? design_mesh : "";
  }



  int
  run_check_design(const Settings &settings, const MPI_Comm comm)
  {
    ConditionalOStream    pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0);
    const std::string     design_mesh = final_design_mesh(settings, comm);
    const bool            finished    = !design_mesh.empty();
    const OutputDirectory out(settings.output_directory, comm);
    const AnalysisBody    body(settings, comm, design_mesh);
    pcout << (finished ? "The final design of <" + settings.output_directory + "> (design.msh, " :
                         "The mesh of " + settings.input->path() + " (")
          << body.triangulation->n_global_active_cells() << " tetrahedra)" << std::endl;
    check_castability(settings, *body.design, out, pcout);
    return 0;
  }
} // namespace softopt
