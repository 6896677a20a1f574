#include <deal.II/base/mpi.h>

#include <softopt/app/analysis.h>
#include <softopt/app/castability.h>
#include <softopt/app/mold.h>
#include <softopt/app/settings.h>
#include <softopt/base/on_rank_zero.h>
#include <softopt/io/csv_writer.h>
#include <softopt/io/output_directory.h>
#include <softopt/io/stl_writer.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/self_intersection.h>
#include <softopt/shape/wall_thickness.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace softopt
{
  void
  MoldParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mold");
    prm.declare_entry("Split plane normal",
                      "0, 0, 1",
                      vector_pattern(),
                      "\"softopt mold\": the outer mold is two halves split by "
                      "the plane with this normal through the actuator's axis "
                      "(the normal of the clamped base through its centroid); "
                      "each half is pulled off along its side's normal.");
    prm.declare_entry("Wall thickness",
                      "5",
                      Patterns::Double(0),
                      "Mold material around the body on every side (mm).");
    prm.declare_entry("Key radius",
                      "1.5",
                      Patterns::Double(0),
                      "Radius (mm) of the four spherical registration keys on "
                      "the split plane, in the side walls: bumps on half_a, "
                      "seats in half_b. Less than half the Wall thickness.");
    prm.declare_entry("Pour opening diameter",
                      "4",
                      Patterns::Double(0),
                      "The pour opening (mm), on the split plane through the "
                      "mold's top: the clamped base is cast upwards, where the "
                      "core stems leave the mold.");
    prm.declare_entry("Vent diameter",
                      "1.5",
                      Patterns::Double(0),
                      "The vent (mm), opposite the pour opening.");
    prm.declare_entry("Stem diameter",
                      "4",
                      Patterns::Double(0),
                      "Each closed cavity's core has a stem of this diameter "
                      "(mm) along the axis through the clamped base: it holds "
                      "the core and leaves the inlet for the air.");
    prm.declare_entry("Stem length",
                      "10",
                      Patterns::Double(0),
                      "How far (mm) the stems reach beyond the mold, to hold "
                      "the cores in place.");
    prm.declare_entry("Undercut tolerance",
                      "0.1",
                      Patterns::Double(0),
                      "An overhang of the part smaller than this (mm, measured "
                      "from a half's face) is not an undercut: a molding face "
                      "is one when a ray along the half's pull direction, "
                      "started this far inside the half, meets the part. The "
                      "flat facets of a curved wall overhang by their sagitta "
                      "where the split plane cuts it; silicone flexes more.");
    prm.leave_subsection();
  }



  void
  MoldParameters::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    prm.enter_subsection("Mold");
    auto &d        = dimensions;
    d.split_normal = parse_vector(prm.get("Split plane normal"),
                                  input.where("Mold", "Split plane normal"));
    AssertThrow(d.split_normal.norm() > 0,
                ExcMessage(input.where("Mold", "Split plane normal") + " is zero."));
    d.wall               = prm.get_double("Wall thickness");
    d.key_radius         = prm.get_double("Key radius");
    d.pour_diameter      = prm.get_double("Pour opening diameter");
    d.vent_diameter      = prm.get_double("Vent diameter");
    d.stem_diameter      = prm.get_double("Stem diameter");
    d.stem_length        = prm.get_double("Stem length");
    d.undercut_tolerance = prm.get_double("Undercut tolerance");
    prm.leave_subsection();
    for (const auto &[entry, value] : {std::pair<std::string, double>{"Wall thickness", d.wall},
                                       {"Key radius", d.key_radius},
                                       {"Pour opening diameter", d.pour_diameter},
                                       {"Vent diameter", d.vent_diameter},
                                       {"Stem diameter", d.stem_diameter}})
      AssertThrow(value > 0, ExcMessage(input.where("Mold", entry) + " must be positive."));
    AssertThrow(d.key_radius < d.wall / 2,
                ExcMessage(input.where("Mold", "Key radius") + " = " +
                           CsvWriter::format(d.key_radius) +
                           " mm must be less than half the Wall thickness, so that the keys "
                           "stay inside the mold's side walls."));
  }



  namespace
  {
    /** "(x, y, z) mm"; no negative zeros. */
    std::string
    place(const Point<3> &p, const std::string &unit = " mm")
    {
      std::ostringstream s;
      s << std::setprecision(4) << "(" << p[0] + 0.0 << ", " << p[1] + 0.0 << ", " << p[2] + 0.0
        << ")" << unit;
      return s.str();
    }

    /** The mold's files, written into @p folder (rank 0). */
    void
    write_mold(const Mold &mold, const std::string &folder)
    {
      std::ostringstream parts;
      parts << "part,file,triangles,volume_mm3,volume_in_box_mm3,closed,manifold\n";
      double sum = 0;
      for (const auto &part : mold.parts)
        {
          write_stl(part.corners, folder + "/" + part.name + ".stl", "softopt mold: " + part.name);
          parts << part.name << "," << part.name << ".stl," << part.corners.size() / 9 << ","
                << CsvWriter::format(part.volume) << "," << CsvWriter::format(part.volume_in_box)
                << "," << part.closed << "," << part.manifold << "\n";
          sum += part.volume_in_box;
        }
      parts << "sum of the parts,,,," << CsvWriter::format(sum) << ",,\n"
            << "box,,,," << CsvWriter::format(mold.box_volume) << ",,\n";
      write_whole_file(folder + "/parts.csv", parts.str());

      std::ostringstream rows;
      rows << "check,value,unit,x_mm,y_mm,z_mm,verdict\n";
      for (const auto &u : mold.undercuts)
        {
          rows << "undercut " << u.half << "," << CsvWriter::format(u.area) << ",mm2,";
          for (unsigned int d = 0; d < 3; ++d)
            rows << (u.area > 0 ? CsvWriter::format(u.where[d]) : "") << ",";
          rows << (u.area > 0 ? "warning" : "ok") << "\n";
        }
      write_whole_file(folder + "/undercuts.csv", rows.str());

      // The frame, for renders and for whoever places the parts.
      std::ostringstream frame;
      frame << "direction,x,y,z\n";
      for (const auto &[name, v] : {std::pair<std::string, Tensor<1, 3>>{"axis", mold.axis},
                                    {"split_normal", mold.split_normal}})
        frame << name << "," << CsvWriter::format(v[0] + 0.0) << ","
              << CsvWriter::format(v[1] + 0.0) << "," << CsvWriter::format(v[2] + 0.0) << "\n";
      write_whole_file(folder + "/frame.csv", frame.str());
    }
  } // namespace



  int
  run_mold(const Settings &settings, const MPI_Comm comm)
  {
    const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
    ConditionalOStream pcout(std::cout, root);
    const std::string  mesh = final_design_mesh(settings, comm);
    const OutputDirectory out(settings.output_directory, comm);
    const AnalysisBody    body(settings, comm, mesh);
    const std::string     which =
      mesh.empty() ? "the mesh of " + settings.input->path() : "the final design <" + mesh + ">";
    pcout << "Mold of " << which << " (" << body.triangulation->n_global_active_cells()
          << " tetrahedra)" << std::endl;

    // What no mold can make.
    std::set<types::boundary_id> clamped, cavity;
    for (const auto &[id, fixed] : settings.geometry.dirichlet_boundaries)
      {
        AssertThrow(!settings.geometry.is_symmetry_plane(id),
                    ExcMessage("No mold for " + which + ": boundary " + std::to_string(id) +
                               " is a symmetry plane, and a mold needs the whole actuator."));
        clamped.insert(id);
      }
    cavity.insert(settings.geometry.pressure_boundary_ids.begin(),
                  settings.geometry.pressure_boundary_ids.end());
    const auto crossing = design_self_intersections(*body.design);
    AssertThrow(crossing.pairs == 0,
                ExcMessage("No mold for " + which + ": its surface intersects itself (" +
                           std::to_string(crossing.pairs) + " pairs of triangles, one near " +
                           place(crossing.where) + "); it cannot be cast."));
    const auto   wall    = wall_thickness(
      *body.design, {}, false, surface_subdivisions(*body.design, settings.castability.sampling_size));
    const double minimum = settings.castability.minimum_wall_thickness;
    AssertThrow(wall.minimum >= minimum,
                ExcMessage("No mold for " + which + ": its wall is " +
                           CsvWriter::format(wall.minimum) + " mm thin at " + place(wall.where) +
                           ", less than Castability / Minimum wall thickness = " +
                           CsvWriter::format(minimum) + " mm (wall_thickness.vtu of "
                           "check-design shows where)."));

    std::vector<types::boundary_id> ids;
    const auto corners = gathered_boundary_triangles(*body.design, &ids);
    Mold       mold;
    on_rank_zero(comm, [&]() {
      mold = make_mold(corners, ids, clamped, cavity, settings.mold.dimensions);
      for (const auto &part : mold.parts)
        AssertThrow(part.manifold,
                    ExcMessage("No mold for " + which + ": its part " + part.name +
                               " is not a closed manifold as an STL file stores it (vertices "
                               "closer than a float resolves, or a pinched vertex). Another "
                               "Mold / Wall thickness or Split plane normal may avoid it."));
      // Aside, then renamed: an earlier mold stays whole until this one is.
      const std::string folder = out.file("mold"), aside = out.file("mold.tmp");
      std::filesystem::remove_all(aside);
      std::filesystem::create_directory(aside);
      write_mold(mold, aside);
      std::filesystem::remove_all(folder);
      std::filesystem::rename(aside, folder);
    });

    if (root)
      {
        pcout << "Wrote " << out.file("mold") << "/ (parts.csv, undercuts.csv, frame.csv):"
              << std::endl;
        double sum = 0;
        for (const auto &part : mold.parts)
          {
            pcout << "  " << std::setw(7) << std::left << part.name << std::right
                  << " volume " << std::setprecision(6) << part.volume_in_box
                  << " mm^3 in the box, " << part.corners.size() / 9 << " triangles, "
                  << "closed manifold" << std::endl;
            sum += part.volume_in_box;
          }
        pcout << "  the parts fill the box: " << sum << " of " << mold.box_volume
              << " mm^3 (relative difference " << std::setprecision(2)
              << std::abs(sum - mold.box_volume) / mold.box_volume << ")" << std::endl;
        for (const auto &u : mold.undercuts)
          pcout << "  undercut of " << u.half << " (pulled along "
                << place(Point<3>(u.pull), "")
                << "): " << std::setprecision(4) << u.area << " mm^2 of "
                << u.molding_area << " mm^2 molding surface"
                << (u.area > 0 ? ", the largest face at " + place(u.where) +
                                   ": warning, the part must flex to release" :
                                 ": ok")
                << std::endl;
      }
    return 0;
  }
} // namespace softopt
