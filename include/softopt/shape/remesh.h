#ifndef softopt_shape_remesh_h
#define softopt_shape_remesh_h

#include <softopt/shape/design_configuration.h>

#include <string>

namespace softopt
{
  /** What remesh_design() made: its worst element and which of gmsh's
   * algorithms made it. */
  struct NewMesh
  {
    /** Below this mean ratio (the default), an element of HXT's mesh is a
     * sliver: elsewhere its meshes are at about 0.3 (the gripper's 0.8 mm
     * mesh 0.28); a sliver it left was at 0.0075. */
    static constexpr double sliver_quality = 0.1;

    /** The worst mean ratio of the kept mesh's tetrahedra (corners). */
    double worst_quality = 1;
    /** Whether Delaunay's mesh was kept. */
    bool delaunay = false;
    /** Whether HXT's worst element was below the sliver quality, so that
     * Delaunay meshed the design too; then the worst element of each. */
    bool   meshed_twice           = false;
    double hxt_worst_quality      = 0;
    double delaunay_worst_quality = 0;
    /** Whether gmsh's Delaunay failed on the design, so that HXT's mesh,
     * sliver and all, was kept (gmsh's message: the .delaunay.log file
     * beside the mesh). */
    bool delaunay_failed = false;

    /** A sentence for the log if HXT's mesh had a sliver (which mesh was
     * kept, and both worst elements); empty otherwise. */
    std::string
    note() const;
  };

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
   * gmsh's HXT algorithm meshes the volume; where it leaves an element of
   * mean ratio below @p sliver_quality, its Delaunay algorithm
   * meshes it too, and the mesh with the better worst element is kept. If
   * Delaunay fails there, HXT's mesh is kept (a sliver is better than no
   * new mesh) and the note says so.
   *
   * Collective. Rank 0 writes @p msh_file (gmsh format 2.2) and, beside it,
   * the boundary it was meshed from (.surface.msh, linear) and the gmsh
   * script (.geo; .delaunay.geo for the second mesh). Throws a message with
   * gmsh's log if gmsh fails.
   */
  NewMesh
  remesh_design(const DesignConfiguration &design,
                const std::string         &msh_file,
                const double               mesh_size      = 0,
                const double               sliver_quality = NewMesh::sliver_quality);

  /** The mean length of the straight edges of the design's boundary faces
   * (corner to corner), in mm. Collective. */
  double
  mean_boundary_edge_length(const DesignConfiguration &design);
} // namespace softopt

#endif
