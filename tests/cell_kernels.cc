// The hand-derived shape derivative of the condensed element residual,
// d(mu . r^e)/dX (Eq. adj3's dr/dpsi on one cell, with the element
// pressure p~(u, X) condensed), against central finite differences of
// mu . r^e(u, X + h V) for a curved, distorted quadratic tetrahedron with a
// large displacement, for both material models. The error must fall as h^2
// to the round-off floor.

#include <deal.II/base/quadrature_lib.h>

#include <softopt/physics/cell_kernels.h>

#include "tests.h"

using namespace softopt_tests;
using softopt::NodalVectors;

double
contract(const NodalVectors &a, const NodalVectors &b)
{
  double sum = 0;
  for (unsigned int n = 0; n < 10; ++n)
    sum += a[n] * b[n];
  return sum;
}

void
check(const softopt::Material &material)
{
  const softopt::ReferenceTetrahedron reference(QGaussSimplex<3>(3),
                                                QGaussSimplex<2>(4));
  // The reference tetrahedron's nodes (vertices, then edge midpoints in
  // the element's line order), scaled to mm and distorted.
  const std::array<Point<3>, 4> v{
    {Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(0, 1, 0), Point<3>(0, 0, 1)}};
  const std::array<std::array<unsigned int, 2>, 6> lines{
    {{{0, 1}}, {{1, 2}}, {{0, 2}}, {{0, 3}}, {{1, 3}}, {{2, 3}}}};
  NodalVectors X, u, mu, V;
  for (unsigned int n = 0; n < 10; ++n)
    {
      const Point<3> xi =
        n < 4 ? v[n] : Point<3>((v[lines[n - 4][0]] + v[lines[n - 4][1]]) / 2);
      for (unsigned int c = 0; c < 3; ++c)
        {
          X[n][c]  = 2. * xi[c] + 0.15 * random(3 * n + c, 1);
          u[n][c]  = 0.3 * random(3 * n + c, 2);
          mu[n][c] = random(3 * n + c, 3);
          V[n][c]  = random(3 * n + c, 4);
        }
    }

  NodalVectors d = softopt::CellKernels::condensed_residual_shape_derivative(
    reference, material, u, X, mu);
  const double exact = contract(d, V);
  double previous = 0;
  for (const double h : {1e-2, 1e-3, 1e-4})
    {
      NodalVectors Xp = X, Xm = X;
      for (unsigned int n = 0; n < 10; ++n)
        {
          Xp[n] += h * V[n];
          Xm[n] -= h * V[n];
        }
      const double fd =
        (contract(mu, softopt::CellKernels::condensed_residual(reference, material, u, Xp)) -
         contract(mu, softopt::CellKernels::condensed_residual(reference, material, u, Xm))) /
        (2 * h);
      // Central differences: the error falls as h^2 (about 20 h^2 here).
      const double e = std::abs(fd - exact) / std::abs(exact);
      deallog << "  h = " << h << ": relative difference to central differences "
              << below(e, 100 * h * h);
      if (previous > 0)
        deallog << ", " << rate(previous, e, 10 * h, h);
      deallog << std::endl;
      previous = e;
    }
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  deallog << "neo-Hookean, nu = 0.49" << std::endl;
  check(*neo_hookean(1.2, 0.49));
  deallog << "Yeoh, nu = 0.4999" << std::endl;
  check(*yeoh("0.2, 0.05, 0.01", 0.4999));
}
