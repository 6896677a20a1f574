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

  /** The boundary faces of the whole mesh (locally_owned_boundary_faces()
   * of every rank), gathered on rank 0 in the order of the ranks (empty on
   * the others). Collective. */
  std::vector<BoundaryFace>
  gathered_boundary_faces(const DesignConfiguration &design,
                          const Deformation         *deformation = nullptr);

  /** The four flat triangles of @p face, split at its midside nodes, with
   * its orientation (design.stl's triangles). */
  std::array<std::array<Point<3>, 3>, 4>
  flat_triangles(const BoundaryFace &face);

  /** A point X(xi) = sum_a N_a(xi) X_a of a face's quadratic surface: its
   * position and the weights N_a of the face's six nodes (0-2 its
   * corners, 3-5 its midpoints 0-2). */
  struct SurfacePoint
  {
    Point<3>              x;
    std::array<double, 6> weight;
  };

  /**
   * The quadratic surface of @p face split into k^2 flat triangles at its
   * points of barycentric coordinates (i, j, k - i - j) / k, with the
   * face's orientation: for k = 2 flat_triangles(), for larger k a finer
   * sampling of the curved face than its nodes. A point on an edge is
   * computed from that edge's three nodes alone, the corner with the
   * smaller DoF first, so the two faces sharing the edge give it to the
   * last bit (a watertight surface).
   */
  std::vector<std::array<SurfacePoint, 3>>
  curved_triangles(const BoundaryFace &face, const unsigned int k);

  /** The flat triangles of every boundary face of the mesh, 9 numbers
   * each (x, y, z of its three corners), gathered on rank 0 (empty on the
   * others), and with @p boundary_ids the boundary id of each. Collective. */
  std::vector<double>
  gathered_boundary_triangles(const DesignConfiguration       &design,
                              std::vector<types::boundary_id> *boundary_ids = nullptr,
                              const Deformation               *deformation  = nullptr);
} // namespace softopt

#endif
