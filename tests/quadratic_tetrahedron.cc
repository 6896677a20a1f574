// The Jacobian ratio of a quadratic tetrahedron (min det J / max det J at
// its ten nodes and centroid), the measure behind the remesher's guard on
// curved boundary edges. On the reference tetrahedron with the midside node
// of edge 0-1 moved by delta along the edge, x = xi + delta e_x 4 L_0 L_1,
// so det J = 1 + 4 delta (L_0 - L_1): 1 + 4 delta at corner 0, 1 - 4 delta
// at corner 1, between them elsewhere, and the ratio is
// (1 - 4 delta) / (1 + 4 delta). The remesher's threshold 0.2 is delta = 1/6;
// delta = 1/4 makes the element degenerate at corner 1, more inverts it.
// The ratio must not change under a rotation, scaling and translation.

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <softopt/shape/quadratic_tetrahedron.h>

#include "tests.h"

#include <cmath>

using namespace softopt_tests;

namespace
{
  softopt::QuadraticTetrahedron
  reference(const double delta)
  {
    softopt::QuadraticTetrahedron t;
    t.corners = {{Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(0, 1, 0), Point<3>(0, 0, 1)}};
    const std::array<std::pair<unsigned int, unsigned int>, 6> edges{
      {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};
    for (unsigned int e = 0; e < 6; ++e)
      {
        const auto [a, b] = edges[e];
        t.edges[e] = {edges[e], (t.corners[a] + t.corners[b]) / 2.};
      }
    t.edges[0].second[0] += delta;
    return t;
  }

  /** x -> 2.5 R x + c, R a rotation about (1, 2, 3). */
  Point<3>
  move(const Point<3> &x)
  {
    Tensor<1, 3> axis({1., 2., 3.});
    axis /= axis.norm();
    const double angle = 0.7;
    // Rodrigues' formula.
    const Tensor<1, 3> r = std::cos(angle) * Tensor<1, 3>(x) +
                           std::sin(angle) * cross_product_3d(axis, Tensor<1, 3>(x)) +
                           (1 - std::cos(angle)) * (axis * Tensor<1, 3>(x)) * axis;
    return Point<3>(2.5 * r + Tensor<1, 3>({10., -4., 7.}));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  for (const double delta : {0., 0.05, 0.1, 1. / 6, 0.2, 0.25, 0.3})
    {
      softopt::QuadraticTetrahedron t = reference(delta);
      const double ratio = softopt::jacobian_ratio(t);
      const double exact = (1 - 4 * delta) / (1 + 4 * delta);
      for (auto &corner : t.corners)
        corner = move(corner);
      for (auto &edge : t.edges)
        edge.second = move(edge.second);
      const double moved = std::abs(softopt::jacobian_ratio(t) - ratio);
      deallog << "delta " << delta << ": ratio " << ratio
              << ", against (1 - 4 delta)/(1 + 4 delta) "
              << (std::abs(ratio - exact) < 1e-14 ? "below 1e-14" : error(ratio - exact))
              << ", moved element " << (moved < 1e-13 ? "below 1e-13" : error(moved))
              << std::endl;
    }
}
