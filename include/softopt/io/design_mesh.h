#ifndef softopt_io_design_mesh_h
#define softopt_io_design_mesh_h

#include <softopt/shape/design_configuration.h>

#include <string>

namespace softopt
{
  /**
   * Writes the design X = X_o + psi as a quadratic gmsh mesh (format 2.2):
   * every tetrahedron with its ten nodes at their design positions, so the
   * mesh has the design's curved P2 surface and interior, and every
   * boundary face as a six-node triangle whose physical tag is its
   * boundary id. Read back by Geometry, it is the same body on the same
   * cells: an analysis of it repeats one of the design to round-off.
   * Nodes and elements are sorted, so the file does not depend on the
   * number of MPI ranks. Collective; rank 0 writes @p file aside and
   * renames it, so a good mesh is never left half-written.
   */
  void
  write_design_mesh(const DesignConfiguration &design, const std::string &file);
} // namespace softopt

#endif
