#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <softopt/base/on_rank_zero.h>
#include <softopt/geometry/geometry.h>
#include <softopt/geometry/gmsh_mesh.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace softopt
{
  void
  Geometry::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry(
      "Mesh file",
      "../meshes/actuator.geo",
      Patterns::FileName(),
      "The tetrahedral mesh, relative to this parameter file's folder: a gmsh "
      ".msh file (format 2.2 or 4.1, linear tetrahedra, with a Physical Volume "
      "and Physical Surfaces whose tags are the boundary ids used below), or "
      "a gmsh .geo file that softopt meshes with gmsh at the mesh size below "
      "(the .geo reads it as DefineConstant[h = ...]).");
    prm.declare_entry("Mesh size",
                      "2",
                      Patterns::Double(1e-6),
                      "Target element size in mm when meshing a .geo file "
                      "(ignored for a .msh file).");
    prm.declare_entry(
      "Mesh parameters",
      "",
      Patterns::Map(Patterns::Anything(),
                    Patterns::Double(),
                    0,
                    Patterns::Map::max_int_value,
                    ";",
                    ":"),
      "Numbers passed to gmsh when meshing a .geo file, as \"name: value; "
      "name: value\" (gmsh's -setnumber; the .geo declares them with "
      "DefineConstant), for example \"r: 9; H2: 12\" for the actuator, in "
      "mm.");
    prm.declare_entry(
      "Dirichlet boundaries",
      "1: xyz",
      Patterns::Map(Patterns::Integer(0, 254),
                    Patterns::Anything(),
                    1,
                    Patterns::Map::max_int_value,
                    ";",
                    ":"),
      "Boundaries with zero displacement, as \"id: components; id: "
      "components\" with components from x, y, z: \"1: xyz\" clamps boundary "
      "1, \"5: x\" fixes only the x displacement (a symmetry plane normal to "
      "x).");
    prm.declare_entry("Pressure boundary ids",
                      "2",
                      Patterns::List(Patterns::Integer(0, 254), 1),
                      "Boundary ids of the walls of the closed, pressurized "
                      "cavity (the follower pressure acts on them).");
    prm.declare_entry("Design boundary ids",
                      "3",
                      Patterns::List(Patterns::Integer(0, 254)),
                      "Boundary ids of the design surface dOmega^d on which "
                      "objectives and constraints are evaluated.");
    prm.leave_subsection();
  }



  void
  Geometry::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    prm.enter_subsection("Geometry");
    where_mesh = input.where("Geometry", "Mesh file");
    mesh_file  = input.resolve(prm.get("Mesh file"));
    mesh_size  = prm.get_double("Mesh size");
    mesh_parameters.clear();
    for (const auto &item : Utilities::split_string_list(prm.get("Mesh parameters"), ';'))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        mesh_parameters[parts[0]] = Utilities::string_to_double(parts[1]);
      }

    where_dirichlet      = input.where("Geometry", "Dirichlet boundaries");
    dirichlet_boundaries = parse_dirichlet_boundaries(prm.get(
                                                        "Dirichlet boundaries"),
                                                      where_dirichlet);
    where_pressure        = input.where("Geometry", "Pressure boundary ids");
    pressure_boundary_ids = parse_boundary_ids(prm.get("Pressure boundary ids"),
                                               where_pressure);
    where_design        = input.where("Geometry", "Design boundary ids");
    design_boundary_ids = parse_boundary_ids(prm.get("Design boundary ids"),
                                             where_design);
    prm.leave_subsection();

    const std::string extension =
      std::filesystem::path(mesh_file).extension().string();
    AssertThrow(extension == ".msh" || extension == ".geo",
                ExcMessage(where_mesh + ": <" + mesh_file +
                           "> is neither a .msh nor a .geo file."));
    AssertThrow(std::ifstream(mesh_file).good(),
                ExcMessage(where_mesh + ": cannot read <" + mesh_file + ">."));

    // gmsh sets only numbers its .geo declares (and ignores others).
    if (!mesh_parameters.empty())
      {
        const std::string where = input.where("Geometry", "Mesh parameters");
        AssertThrow(extension == ".geo",
                    ExcMessage(where + ": numbers for gmsh need a .geo Mesh "
                                       "file, not <" + mesh_file + ">."));
        const auto known = geo_constants(mesh_file);
        std::string list;
        for (const auto &name : known)
          list += (list.empty() ? "" : ", ") + name;
        for (const auto &[name, value] : mesh_parameters)
          AssertThrow(known.count(name) == 1 && name != "h",
                      ExcMessage(where + ": <" + name + "> is " +
                                 (name == "h" ? "set by \"Mesh size\"" :
                                                "not declared by DefineConstant "
                                                "in <" + mesh_file + ">, which "
                                                "declares: " + list) + "."));
      }
  }



  namespace
  {
    /** "softopt-<host>-": the prefix of this machine's temporary meshes
     * (a temporary folder may be shared by the nodes of a cluster). */
    std::string
    temporary_prefix()
    {
      char host[256] = {};
      ::gethostname(host, sizeof(host) - 1);
      return "softopt-" + std::string(host) + "-";
    }

    /** Removes the temporary meshes softopt-<host>-<pid>-* of this
     * machine's runs that no longer exist (killed before they could). */
    void
    remove_stale_temporary_meshes(const std::filesystem::path &folder)
    {
      const std::string prefix = temporary_prefix();
      std::error_code   error;
      for (const auto &entry : std::filesystem::directory_iterator(folder, error))
        {
          const std::string name = entry.path().filename().string();
          if (name.rfind(prefix, 0) != 0)
            continue;
          const pid_t pid = std::atoi(name.c_str() + prefix.size());
          if (pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH)
            std::filesystem::remove(entry.path(), error);
        }
    }
  } // namespace



  std::string
  Geometry::mesh_with_gmsh(const MPI_Comm     comm,
                           const std::string &mesh_file,
                           const std::string &where_mesh) const
  {
    // Rank 0 writes gmsh's format 2.2 into a temporary file: a .geo meshed
    // with quadratic tetrahedra (midside nodes on the CAD surfaces), a .msh
    // converted as it is. Every rank then reads that file.
    std::string msh_file;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        remove_stale_temporary_meshes(std::filesystem::temp_directory_path());
        const auto tmp = std::filesystem::temp_directory_path() /
                         (temporary_prefix() + std::to_string(::getpid()) + "-" +
                          std::filesystem::path(mesh_file).stem().string());
        msh_file      = tmp.string() + ".msh";
        const bool geo = std::filesystem::path(mesh_file).extension() == ".geo";
        std::vector<std::string> arguments{geo ? "-3" : "-0"};
        if (geo)
          {
            arguments.insert(arguments.end(), {"-order", "2"});
            const auto set_number = [&](const std::string &name, const double value) {
              std::ostringstream number;
              number << std::setprecision(17) << value;
              arguments.insert(arguments.end(), {"-setnumber", name, number.str()});
            };
            set_number("h", mesh_size);
            for (const auto &[name, value] : mesh_parameters)
              set_number(name, value);
          }
        arguments.insert(arguments.end(), {"-format", "msh22"});
        arguments.push_back(mesh_file);
        const std::string error = run_gmsh(arguments, msh_file);
        if (!error.empty())
          msh_file = "gmsh failed on <" + mesh_file + "> " + error;
      }
    msh_file = Utilities::MPI::broadcast(comm, msh_file, 0);
    AssertThrow(msh_file.rfind("gmsh failed", 0) != 0,
                ExcMessage(where_mesh + ": " + msh_file));
    return msh_file;
  }



  EdgeMidpoints
  Geometry::create_triangulation(
    parallel::fullydistributed::Triangulation<3> &triangulation,
    const std::string                            &file) const
  {
    // A mesh other than the parameter file's (a new mesh of the design,
    // named by a checkpoint) is named by itself in messages.
    const std::string  mesh_file  = file.empty() ? this->mesh_file : file;
    const std::string  where_mesh = mesh_file == this->mesh_file ?
                                      this->where_mesh :
                                      "The mesh <" + mesh_file + ">";
    const MPI_Comm     comm     = triangulation.get_communicator();
    const std::string  msh_file = mesh_with_gmsh(comm, mesh_file, where_mesh);
    const unsigned int rank     = Utilities::MPI::this_mpi_process(comm);
    const std::string  linear_file =
      msh_file + ".linear" + std::to_string(rank) + ".msh";

    Triangulation<3> serial;
    EdgeMidpoints    edge_midpoints;
    std::string      error;
    try
      {
        edge_midpoints = split_quadratic_gmsh_mesh(msh_file, linear_file);
        GridIn<3>     grid_in(serial);
        std::ifstream in(linear_file);
        grid_in.read_msh(in);
      }
    catch (const std::exception &e)
      {
        error = user_message(e);
      }
    std::filesystem::remove(linear_file);
    MPI_Barrier(comm);
    if (rank == 0)
      std::filesystem::remove(msh_file);
    // Messages name the temporary copy gmsh wrote: name the user's file.
    const std::string copy = "The mesh <" + msh_file + "> ";
    if (error.rfind(copy, 0) == 0)
      error = "the mesh <" + mesh_file + "> " + error.substr(copy.size());
    else if (!error.empty())
      error = "cannot read the mesh <" + mesh_file + ">: " + error;
    AssertThrow(error.empty(), ExcMessage(where_mesh + ": " + error));

    for (const auto &cell : serial.active_cell_iterators())
      AssertThrow(cell->reference_cell() == ReferenceCells::Tetrahedron,
                  ExcMessage(where_mesh + ": softopt needs a mesh of "
                                          "tetrahedra only."));

    // Every boundary id the case names must exist in the mesh.
    const auto present = serial.get_boundary_ids();
    const auto check   = [&](const types::boundary_id id,
                           const std::string       &where) {
      std::string list;
      for (const auto b : present)
        list += (list.empty() ? "" : ", ") + std::to_string(b);
      AssertThrow(is_in(present, id),
                  ExcMessage(where + ": the mesh has no boundary with id " +
                             std::to_string(id) + " (it has " + list + ")."));
    };
    for (const auto &[id, components] : dirichlet_boundaries)
      check(id, where_dirichlet);
    for (const auto id : pressure_boundary_ids)
      check(id, where_pressure);
    for (const auto id : design_boundary_ids)
      check(id, where_design);

    check_cavity_is_closed(serial);
    distribute(serial, triangulation);
    return edge_midpoints;
  }



  void
  Geometry::check_cavity_is_closed(const Triangulation<3> &serial) const
  {
    // The follower pressure is conservative, with a symmetric load stiffness,
    // only on a closed surface (Eq. LinMat): every edge of the pressure
    // boundary must belong to two of its faces, or lie on a coordinate plane
    // through the origin that a Dirichlet condition makes a symmetry plane.
    std::map<unsigned int, std::pair<unsigned int, Triangulation<3>::line_iterator>>
      faces_per_line;
    for (const auto &cell : serial.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            is_in(pressure_boundary_ids, cell->face(f)->boundary_id()))
          for (unsigned int l = 0; l < cell->face(f)->n_lines(); ++l)
            {
              auto &entry = faces_per_line[cell->face(f)->line(l)->index()];
              ++entry.first;
              entry.second = cell->face(f)->line(l);
            }

    std::array<bool, 3> symmetry_plane{{false, false, false}};
    for (const auto &[id, fixed] : dirichlet_boundaries)
      for (unsigned int d = 0; d < 3; ++d)
        symmetry_plane[d] |= fixed[d];
    const double tolerance = 1e-8 * GridTools::diameter(serial);

    unsigned int open_edges = 0;
    Point<3>     example;
    for (const auto &[index, entry] : faces_per_line)
      {
        const auto &[count, line] = entry;
        if (count != 1)
          continue;
        bool on_symmetry_plane = false;
        for (unsigned int d = 0; d < 3; ++d)
          on_symmetry_plane |= symmetry_plane[d] &&
                               std::abs(line->vertex(0)[d]) < tolerance &&
                               std::abs(line->vertex(1)[d]) < tolerance;
        if (!on_symmetry_plane && open_edges++ == 0)
          example = line->center();
      }
    std::ostringstream message;
    message << where_pressure << ": the pressure boundary is not a closed "
            << "cavity: " << open_edges << " of its edges border on "
            << "other boundaries (one at " << example << "). The follower "
            << "pressure needs the walls of a closed cavity, or of one cut "
            << "by symmetry planes through the origin (x = 0, y = 0 or "
            << "z = 0 with that displacement component fixed).";
    AssertThrow(open_edges == 0, ExcMessage(message.str()));
  }



  bool
  is_in(const std::vector<types::boundary_id> &ids, const types::boundary_id id)
  {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
  }



  void
  initial_coordinates(const DoFHandler<3>        &dof_handler,
                      const EdgeMidpoints        &edge_midpoints,
                      PETScWrappers::MPI::Vector &coordinates)
  {
    // Vertex DoFs of FE_SimplexP(2) come first, then one DoF per line.
    const FiniteElement<3> &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto [component, base] = fe.system_to_component_index(i);
              if (!coordinates.in_local_range(dof_indices[i]))
                continue;
              const Point<3> X =
                base < 4 ? cell->vertex(base) :
                           edge_midpoints(cell->line(base - 4)->vertex(0),
                                          cell->line(base - 4)->vertex(1));
              coordinates(dof_indices[i]) = X[component];
            }
        }
    coordinates.compress(VectorOperation::insert);
  }



  void
  Geometry::distribute(Triangulation<3>                             &serial,
                       parallel::fullydistributed::Triangulation<3> &triangulation)
  {
    const MPI_Comm     comm    = triangulation.get_communicator();
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    if (n_ranks > 1)
      GridTools::partition_triangulation(n_ranks, serial);
    const auto description =
      TriangulationDescription::Utilities::create_description_from_triangulation(
        serial, comm);
    triangulation.create_triangulation(description);
  }
  bool
  Geometry::is_symmetry_plane(const types::boundary_id id) const
  {
    const auto d = dirichlet_boundaries.find(id);
    if (d == dirichlet_boundaries.end())
      return false;
    const auto n_fixed = std::count(d->second.begin(), d->second.end(), true);
    return n_fixed > 0 && n_fixed < 3;
  }



  std::set<types::boundary_id>
  Geometry::symmetry_planes() const
  {
    std::set<types::boundary_id> ids;
    for (const auto &[id, fixed] : dirichlet_boundaries)
      if (is_symmetry_plane(id))
        ids.insert(id);
    return ids;
  }
} // namespace softopt
