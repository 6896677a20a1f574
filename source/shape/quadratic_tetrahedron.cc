#include <deal.II/base/tensor.h>

#include <softopt/shape/quadratic_tetrahedron.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace softopt
{
  double
  jacobian_ratio(const QuadraticTetrahedron &t)
  {
    // Barycentric L_0 = 1 - x - y - z, L_a = x_a, and their gradients.
    const std::array<Tensor<1, 3>, 4> dL{{Tensor<1, 3>({-1., -1., -1.}),
                                          Tensor<1, 3>({1., 0., 0.}),
                                          Tensor<1, 3>({0., 1., 0.}),
                                          Tensor<1, 3>({0., 0., 1.})}};
    std::vector<Point<3>> points{Point<3>(0, 0, 0), Point<3>(1, 0, 0),
                                 Point<3>(0, 1, 0), Point<3>(0, 0, 1),
                                 Point<3>(.25, .25, .25)};
    for (const auto &[local, node] : t.edges)
      points.push_back((points[local.first] + points[local.second]) / 2.);
    double smallest = std::numeric_limits<double>::max(), largest = 0;
    for (const auto &x : points)
      {
        const std::array<double, 4> L{{1 - x[0] - x[1] - x[2], x[0], x[1], x[2]}};
        Tensor<2, 3>                J;
        // Corners: L_a (2 L_a - 1); edges: 4 L_a L_b.
        for (unsigned int a = 0; a < 4; ++a)
          J += outer_product(Tensor<1, 3>(t.corners[a]), (4 * L[a] - 1) * dL[a]);
        for (const auto &[local, node] : t.edges)
          J += outer_product(Tensor<1, 3>(node),
                             4 * (L[local.first] * dL[local.second] +
                                  L[local.second] * dL[local.first]));
        smallest = std::min(smallest, determinant(J));
        largest  = std::max(largest, determinant(J));
      }
    return smallest / largest;
  }



  double
  mean_ratio(const std::array<Point<3>, 4> &p)
  {
    const double V = ((p[1] - p[0]) * cross_product_3d(p[2] - p[0], p[3] - p[0])) / 6.;
    double edges = 0;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int b = a + 1; b < 4; ++b)
        edges += (p[a] - p[b]).norm_square();
    return V > 0 ? 12. * std::pow(3. * V, 2. / 3.) / edges : V;
  }
} // namespace softopt
