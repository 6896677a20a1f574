#ifndef softopt_shape_wall_thickness_h
#define softopt_shape_wall_thickness_h

#include <deal.II/base/point.h>

#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/design_configuration.h>

#include <array>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace softopt
{
  /** The thickness of the body's walls at the nodes of its surface. */
  struct WallThickness
  {
    /** The corners of the surface triangles, each once, in mm: points of
     * the quadratic faces, k x k flat triangles a face (k = 2: design.stl's
     * four triangles at its nodes). */
    std::vector<Point<3>> nodes;
    /** The surface triangles, three indices into nodes each, outward. */
    std::vector<std::array<unsigned int, 3>> triangles;
    /** At each node, the distance along the inward normal (the mean of
     * the normals of the triangles around it) to the next surface
     * triangle, in mm; infinite where the ray leaves the body through
     * none (it cannot on a closed surface). */
    std::vector<double> thickness;
    /** Per node: whether its ray ended on a face turned more than 60
     * degrees from facing it (|cos| < 1/2 between the ray and that face's
     * normal): near an edge of the part, the ray along a tilted normal
     * leaves through the neighbouring face (a sample 0.18 mm above a base
     * whose side leans 13 degrees in measured 0.78 mm). That is a corner,
     * not a wall: two sides of a wall face each other, and a wedge wider
     * than 60 degrees is one a mold fills. Its thickness is left out of
     * the minimum and of the quantity "thin walls". */
    std::vector<bool> corner;
    /** The smallest thickness (of the nodes whose ray ended at no corner)
     * and the node where it occurs. */
    double   minimum = std::numeric_limits<double>::infinity();
    Point<3> where;
    /** Nodes of the part's surface whose ray found no opposite wall (for
     * the inward rays none on a closed surface, a sign of a surface that is
     * not; for the outward ones the rays that leave). */
    unsigned int n_without_opposite = 0;

    /** Whether the rays went along the outward normal (gaps outside the
     * part) instead of the inward one (its walls). */
    bool outward = false;

    /** Of each node, the design DoFs (x, y, z) of the mesh nodes it is
     * made of with their weights: node = sum of weight * mesh node (one
     * mesh node, weight 1, at the corners and midside nodes of a face). */
    std::vector<std::vector<std::pair<double, BoundaryFace::NodeDofs>>> node_dofs;

    /** How each ray went: the triangles around each node, which
     * triangles lie on a symmetry plane, the triangles' unit normals, and
     * per node the planes' triangles its ray was reflected at, the
     * triangle it ended on (none: no finite thickness), and whether
     * thickness_gradient() has its derivative: a straight ray (no
     * reflection) from a node off the planes that ends at no corner. */
    std::vector<std::vector<unsigned int>> around;
    std::vector<bool>                      on_mirror;
    std::vector<Tensor<1, 3>>              unit_normal;
    std::vector<std::vector<unsigned int>> reflections;
    static constexpr unsigned int          none = static_cast<unsigned int>(-1);
    std::vector<unsigned int>              hit;
    std::vector<bool>                      differentiable;
  };

  /**
   * The wall thickness of the design X = X_o + psi, what a cast part needs
   * (castability): from every node of the boundary surface, a ray along
   * the inward normal to the first surface triangle it meets (CGAL's AABB
   * tree, skipping the triangles around the node). Faces with a boundary
   * id in @p mirrors are symmetry planes, not surfaces of the part: no ray
   * starts there, a node on their rim takes the normal projected onto the
   * plane, and a ray that meets one is reflected (the body goes on beyond
   * it). On a thick sphere octant the thickness is B - A at every
   * node of its spherical surfaces. With @p outward the rays go along the
   * outward normal instead: the gap to the next surface outside the part
   * (between two folds of a bellows: a wall of the mold; across the
   * cavity: its core), infinite where the ray leaves. The surface is each
   * quadratic face split into @p subdivisions^2 flat triangles on its
   * curved map (curved_triangles()); 2: at the face's nodes, which on a
   * coarse mesh lie a millimetre apart and miss narrower slots.
   * Collective; the result is on rank 0 (minimum and where on every rank).
   */
  WallThickness
  wall_thickness(const DesignConfiguration          &design,
                 const std::set<types::boundary_id> &mirrors,
                 const bool                          outward      = false,
                 const unsigned int                  subdivisions = 2);

  /** wall_thickness() of a whole part (no symmetry planes) both ways:
   * its walls (inward rays) and its gaps (outward rays), from one sampled
   * surface and one AABB tree. Collective. */
  std::pair<WallThickness, WallThickness>
  walls_and_gaps(const DesignConfiguration &design, const unsigned int subdivisions);

  /** The subdivisions k of wall_thickness() that sample the surface
   * about @p sampling_size mm apart: the mean edge length of the mesh's
   * boundary faces over @p sampling_size, rounded up, at least 2 (2 also
   * for @p sampling_size 0: the faces' nodes); faces with longer edges
   * than the mean are sampled coarser. From the triangulation's vertices,
   * so k changes only with a new mesh, not with the design. At most 64
   * (an error above). Collective. */
  unsigned int
  surface_subdivisions(const DesignConfiguration &design, const double sampling_size);

  /**
   * The derivative of @p wall's thickness at node @p i with respect to the
   * positions of the nodes it depends on: the node itself and the corners
   * of the triangles around it (its direction, their area-weighted mean
   * normal), and the corners of the triangle its ray ends on (through that
   * triangle's plane). The ray thickness is smooth while the ray stays on
   * the same triangle: piecewise smooth and continuous in the positions.
   * Empty where wall.differentiable[i] is not set (reflected rays, nodes
   * on symmetry planes, rays that end at a corner). On rank 0, after
   * wall_thickness().
   */
  std::vector<std::pair<unsigned int, Tensor<1, 3>>>
  thickness_gradient(const WallThickness &wall, const unsigned int i);

  /** Writes @p wall as a ParaView surface (.vtu) with the point field
   * wall_thickness_mm (gap_mm for outward rays; -1 where the ray found no
   * opposite surface, -2 at a corner) into @p file (rank 0's call writes). */
  void
  write_wall_thickness_vtu(const WallThickness &wall, const std::string &file);
} // namespace softopt

#endif
