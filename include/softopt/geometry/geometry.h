#ifndef softopt_geometry_geometry_h
#define softopt_geometry_geometry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/base/input.h>
#include <softopt/geometry/gmsh_mesh.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * The body to analyze and the roles of its boundaries (subsection
   * "Geometry"): the tetrahedral mesh, read from a gmsh .msh file or meshed
   * by calling gmsh on a .geo file, and which boundary ids are clamped,
   * pressurized or designed. Boundary ids are gmsh's physical surface tags.
   */
  class Geometry
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    /**
     * Reads the mesh @p file (empty: the parameter file's Mesh file) on
     * every rank (running gmsh first for a .geo), checks that every
     * boundary id named in the parameter file exists, partitions the cells
     * with METIS and builds the fully distributed triangulation. Returns
     * the midside nodes of gmsh's quadratic mesh (initial_coordinates()).
     */
    EdgeMidpoints
    create_triangulation(parallel::fullydistributed::Triangulation<3> &triangulation,
                         const std::string &file = "") const;

    /** The mesh file, resolved against the parameter file's folder. */
    std::string mesh_file;

    /** Target element size in mm when meshing a .geo file. */
    double mesh_size = 2.0;

    /** Further numbers for gmsh (-setnumber name value) when meshing a .geo. */
    std::map<std::string, double> mesh_parameters;

    /** Fixed displacement components on each Dirichlet boundary id. */
    std::map<types::boundary_id, std::array<bool, 3>> dirichlet_boundaries;

    /** Whether boundary @p id is a symmetry plane (a Dirichlet boundary
     * fixing only some components): a cut through the body, not its
     * surface. */
    bool
    is_symmetry_plane(const types::boundary_id id) const;

    /** The boundary ids that are symmetry planes. */
    std::set<types::boundary_id>
    symmetry_planes() const;

    /** Boundary ids of the closed cavity's walls (the follower pressure). */
    std::vector<types::boundary_id> pressure_boundary_ids;

    /** Boundary ids of the design surface dOmega^d. */
    std::vector<types::boundary_id> design_boundary_ids;

    /**
     * Partitions @p serial with METIS (under MPI) and builds the fully
     * distributed @p triangulation from it.
     */
    static void
    distribute(Triangulation<3>                             &serial,
               parallel::fullydistributed::Triangulation<3> &triangulation);

  private:
    /** Runs gmsh on @p mesh_file (meshing a .geo with quadratic
     * tetrahedra) and returns the path of the format 2.2 .msh it wrote;
     * messages start with @p where_mesh. */
    std::string
    mesh_with_gmsh(const MPI_Comm     comm,
                   const std::string &mesh_file,
                   const std::string &where_mesh) const;

    /** Throws unless the pressure boundary closes a cavity (up to symmetry
     * planes through the origin). */
    void
    check_cavity_is_closed(const Triangulation<3> &serial) const;


    /** Where each boundary role came from, for messages. */
    std::string where_dirichlet, where_pressure, where_design, where_mesh;
  };

  /** Whether the boundary id @p id is one of @p ids. */
  bool
  is_in(const std::vector<types::boundary_id> &ids, const types::boundary_id id);

  /**
   * The initial design coordinates X_o at the DoFs of a P2 vector field on
   * a triangulation made by Geometry::create_triangulation(): vertices, and
   * the @p edge_midpoints it returned, the midside nodes of gmsh's
   * quadratic mesh, which lie on the curved CAD surfaces (straight
   * midpoints for a linear mesh). In mm.
   */
  void
  initial_coordinates(const DoFHandler<3>        &dof_handler,
                      const EdgeMidpoints        &edge_midpoints,
                      PETScWrappers::MPI::Vector &coordinates);
} // namespace softopt

#endif
