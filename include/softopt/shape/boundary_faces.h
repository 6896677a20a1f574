#ifndef softopt_shape_boundary_faces_h
#define softopt_shape_boundary_faces_h

#include <deal.II/base/point.h>

#include <softopt/shape/design_configuration.h>

#include <array>
#include <vector>

namespace softopt
{
  /** A boundary face of the quadratic mesh in the design configuration
   * X = X_o + psi. */
  struct BoundaryFace
  {
    /** Counter-clockwise seen from outside (outward normal). */
    std::array<Point<3>, 3> corner;
    /** midpoint[k]: the midside node of the edge opposite corner k. */
    std::array<Point<3>, 3> midpoint;
    types::boundary_id      boundary_id;
    /** The design DoFs (x, y, z) of each corner and midside node, in the
     * order of corner and midpoint: what a shape derivative adds to. */
    using NodeDofs = std::array<types::global_dof_index, 3>;
    std::array<NodeDofs, 3> corner_dofs;
    std::array<NodeDofs, 3> midpoint_dofs;
  };

  /** A displacement u on the design's mesh (a state of the physics: its
   * components 0-2 on @p dof_handler, a DoFHandler of the same
   * triangulation with P2 nodes, ghosted). */
  struct Deformation
  {
    const DoFHandler<3>                &dof_handler;
    const PETScWrappers::MPI::Vector &u;
  };

  /**
   * The boundary faces of this rank's cells, with their nodes at X (at
   * X + u with @p deformation: the deformed configuration). Faces
   * of neighbouring cells read shared nodes from the same degrees of
   * freedom, so the whole boundary is watertight to the last bit.
   */
  std::vector<BoundaryFace>
  locally_owned_boundary_faces(const DesignConfiguration &design,
                               const Deformation         *deformation = nullptr);

  /** The four flat triangles of @p face, split at its midside nodes, with
   * its orientation (design.stl's triangles). */
  std::array<std::array<Point<3>, 3>, 4>
  flat_triangles(const BoundaryFace &face);

  /** The design DoFs of the corners of flat_triangles(@p face), alike. */
  std::array<std::array<BoundaryFace::NodeDofs, 3>, 4>
  flat_triangle_dofs(const BoundaryFace &face);

  /** The flat triangles of every boundary face of the mesh, 9 numbers
   * each (x, y, z of its three corners), gathered on rank 0 (empty on the
   * others), and with @p boundary_ids the boundary id of each, with
   * @p dofs the design DoFs of each corner (9 a triangle, as the numbers).
   * Collective. */
  std::vector<double>
  gathered_boundary_triangles(const DesignConfiguration            &design,
                              std::vector<types::boundary_id>      *boundary_ids = nullptr,
                              const Deformation                    *deformation  = nullptr,
                              std::vector<types::global_dof_index> *dofs         = nullptr);
} // namespace softopt

#endif
