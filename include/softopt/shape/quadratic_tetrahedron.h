#ifndef softopt_shape_quadratic_tetrahedron_h
#define softopt_shape_quadratic_tetrahedron_h

#include <deal.II/base/point.h>

#include <array>
#include <utility>

namespace softopt
{
  using namespace dealii;

  /** A quadratic (ten-node) tetrahedron: its four corners and, per edge,
   * the edge's corners (local numbers 0-3) and its midside node. */
  struct QuadraticTetrahedron
  {
    std::array<Point<3>, 4>                                                corners;
    std::array<std::pair<std::pair<unsigned int, unsigned int>, Point<3>>, 6> edges;
  };

  /**
   * min det J / max det J of the quadratic map of @p t, sampled at its ten
   * nodes and its centroid: 1 for straight edges, below 1 as curved edges
   * make J vary, 0 or less for a degenerate or inverted element. Invariant
   * under translations, rotations and scaling. The remesher keeps an
   * element's edges straight where curving them takes this below 0.2.
   */
  double
  jacobian_ratio(const QuadraticTetrahedron &t);

  /** The mean-ratio quality of the straight tetrahedron through
   * @p corners: 12 (3 V)^(2/3) / (sum of squared edge lengths), 1 if
   * equilateral, 0 if flat; the signed volume V if it is negative
   * (inverted). */
  double
  mean_ratio(const std::array<Point<3>, 4> &corners);
} // namespace softopt

#endif
