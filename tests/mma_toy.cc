// MMA on Svanberg's toy problem ("MMA and GCMMA", 2007), in the ordinary
// form (f_0 is the objective, a_i = 0):
//   minimize x1^2 + x2^2 + x3^2
//   s.t. (x1-5)^2 + (x2-2)^2 + (x3-1)^2 <= 9,
//        (x1-3)^2 + (x2-4)^2 + (x3-3)^2 <= 9,  0 <= x <= 5,
// from x = (4, 3, 2). Both constraints are active at the optimum, computed
// to 12 digits by Newton's method on the KKT conditions. The variables are
// split between the MPI ranks.

#include "mma_tests.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const unsigned int n     = 3;
  const LocalRange   local(n, comm);
  const unsigned int begin = local.begin, end = local.end;

  const std::vector<double> x0            = {4, 3, 2};
  const std::vector<double> x_opt         = {2.017518585676,
                                             1.780011437339,
                                             1.237507148337};
  const double              f_opt         = 8.770245902792;
  const double              centers[2][3] = {{5, 2, 1}, {3, 4, 3}};

  std::vector<double> x(x0.begin() + begin, x0.begin() + end);
  std::vector<double> xmin(end - begin, 0.), xmax(end - begin, 5.);

  using Row = softopt::MMA::RowType;
  softopt::MMA mma(end - begin, {Row::constraint, Row::constraint}, comm);

  // The objective, constraints and gradients at the gathered global x.
  double                           f0;
  std::vector<double>              g(2), df0(n);
  std::vector<std::vector<double>> dg(2, std::vector<double>(n));
  std::vector<double>              x_global;
  auto                             evaluate = [&]() {
    x_global = gather_all(comm, x);
    f0 = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        f0 += x_global[j] * x_global[j];
        df0[j] = 2 * x_global[j];
      }
    for (unsigned int i = 0; i < 2; ++i)
      {
        g[i] = -9;
        for (unsigned int j = 0; j < n; ++j)
          {
            g[i] += std::pow(x_global[j] - centers[i][j], 2);
            dg[i][j] = 2 * (x_global[j] - centers[i][j]);
          }
      }
  };

  evaluate();
  deallog << "start: f0 = " << fixed(f0) << ", g = " << fixed(g[0]) << " "
          << fixed(g[1]) << std::endl;
  for (unsigned int k = 0; k < 100; ++k)
    {
      mma.update(x,
                 f0,
                 ArrayView<const double>(df0.data() + begin, end - begin),
                 g,
                 {ArrayView<const double>(dg[0].data() + begin, end - begin),
                  ArrayView<const double>(dg[1].data() + begin, end - begin)},
                 make_array_view(xmin),
                 make_array_view(xmax));
      evaluate();
      if (mma.n_iterations() <= 5)
        deallog << "iteration " << mma.n_iterations() << ": f0 = " << fixed(f0)
                << ", g = " << fixed(g[0]) << " " << fixed(g[1])
                << ", |dx| = " << error(mma.last_step()) << std::endl;
      if (mma.last_step() < 1e-6)
        break;
    }

  double x_error = 0;
  for (unsigned int j = 0; j < n; ++j)
    x_error = std::max(x_error, std::abs(x_global[j] - x_opt[j]));
  deallog << "converged (|dx| < 1e-6) after " << mma.n_iterations()
          << " iterations" << std::endl;
  deallog << "x = " << fixed(x_global[0]) << " " << fixed(x_global[1]) << " "
          << fixed(x_global[2]) << std::endl;
  deallog << "f0 = " << fixed(f0) << ", g = " << fixed(g[0]) << " "
          << fixed(g[1]) << std::endl;
  deallog << "y = " << fixed(mma.get_y()[0]) << " " << fixed(mma.get_y()[1])
          << ", z = " << fixed(mma.get_z()) << std::endl;
  deallog << "lambda = " << fixed(mma.get_lambda()[0]) << " "
          << fixed(mma.get_lambda()[1]) << " (exact 0.426240 0.759573)"
          << std::endl;
  deallog << "max |x - x*| = " << error(x_error)
          << ", |f0 - f0*| = " << error(std::abs(f0 - f_opt)) << std::endl;
  deallog << "error below 1e-5: " << (x_error < 1e-5 ? "yes" : "NO")
          << std::endl;
}
