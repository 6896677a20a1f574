#ifndef softopt_shape_remesh_h
#define softopt_shape_remesh_h

#include <softopt/shape/design_configuration.h>

#include <string>

namespace softopt
{
  /**
   * A new tetrahedral mesh of the design X = X_o + psi, for when the mesh
   * update of Section 5 would keep elements the design has flattened:
   * gmsh meshes the volume enclosed by the design's boundary triangles
   * (through their corner nodes, each tagged with its boundary id), so the
   * boundary triangulation and its ids stay and the interior is new.
   * Quadratic tetrahedra; the midside nodes of the boundary edges are moved
   * from gmsh's straight midpoints to the design's, so the new mesh has
   * the design's curved P2 surface (interior midside nodes are straight).
   *
   * With @p mesh_size > 0 (mm) the boundary is first refined: each face is
   * split into n x n triangles on its P2 surface, n the mean boundary edge
   * over @p mesh_size (rounded up: boundary edges of at most mesh_size on
   * average, and of at least half of it once n >= 2), and gmsh's size grows
   * from the boundary's to @p mesh_size at a depth of 2 @p mesh_size
   * (not the boundary's throughout): a finer mesh of the same curved body
   * (verification, the mesh-size schedule).
   *
   * Collective. Rank 0 writes @p msh_file (gmsh format 2.2) and, beside it,
   * the boundary it was meshed from (.surface.msh, linear) and the gmsh
   * script (.geo). Throws a message with gmsh's log if gmsh fails.
   */
  void
  remesh_design(const DesignConfiguration &design,
                const std::string         &msh_file,
                const double               mesh_size = 0);

  /** The mean length of the straight edges of the design's boundary faces
   * (corner to corner), in mm. Collective. */
  double
  mean_boundary_edge_length(const DesignConfiguration &design);
} // namespace softopt

#endif
