#ifndef softopt_shape_self_intersection_h
#define softopt_shape_self_intersection_h

#include <deal.II/base/point.h>

#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/design_configuration.h>

namespace softopt
{
  /** Where the design surface passes through itself. */
  struct SelfIntersection
  {
    /** Pairs of surface triangles that intersect (four per quadratic face,
     * split at its midside nodes as in design.stl); 0: none. */
    unsigned int pairs = 0;
    /** A point of the first such pair, in mm (the centroid of one of its
     * triangles). */
    Point<3> where;
  };

  /**
   * Self-intersections of the boundary of the design configuration X =
   * X_o + psi, or with @p deformation of the deformed one X + u (CGAL's
   * Polygon_mesh_processing on the surface gathered on rank 0, with exact
   * predicates). A design that passes through itself cannot be cast, and
   * the model, which has no contact, would go on computing it; a deformed
   * surface that passes through itself has walls in contact. Collective;
   * every rank gets the result.
   */
  SelfIntersection
  design_self_intersections(const DesignConfiguration &design,
                            const Deformation         *deformation = nullptr);
} // namespace softopt

#endif
