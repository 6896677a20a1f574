#ifndef softopt_io_stl_writer_h
#define softopt_io_stl_writer_h

#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/design_configuration.h>

#include <string>
#include <vector>

namespace softopt
{
  /**
   * Writes the boundary of the design X = X_o + psi as a binary STL in mm,
   * for mold design: every boundary face of the quadratic mesh is split at
   * its edge midpoints into four triangles, oriented with outward normals.
   * Neighbouring faces share their corner and midpoint nodes, whose
   * coordinates are read from the same degrees of freedom, so the surface
   * is watertight (every edge in exactly two triangles, in opposite
   * directions). Collective; rank 0 writes @p file (through a temporary
   * file, so a good STL is never left half-written). Returns the number of
   * triangles. With @p deformation, the deformed surface X + u.
   */
  unsigned int
  write_design_stl(const DesignConfiguration &design,
                   const std::string         &file,
                   const Deformation         *deformation = nullptr);

  /** Writes the triangles @p corners (9 numbers each, outward) as a binary
   * STL in mm with the 80-character header @p title, through a temporary
   * file. Call on one rank. */
  void
  write_stl(const std::vector<double> &corners, const std::string &file, const std::string &title);
} // namespace softopt

#endif
