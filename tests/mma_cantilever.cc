// MMA on Svanberg's cantilever beam (Svanberg 1987, section 5.1): five
// hollow square segments of fixed wall thickness, x_j the side lengths,
//   minimize 0.0624 (x1 + x2 + x3 + x4 + x5)
//   s.t. 61/x1^3 + 37/x2^3 + 19/x3^3 + 7/x4^3 + 1/x5^3 <= 1,  1 <= x <= 10,
// from x = 5. The constraint is active at the optimum, and the KKT
// conditions 0.0624 = 3 lambda c_j / x_j^4 give it in closed form:
// x_j = c_j^(1/4) (sum_k c_k^(1/4))^(1/3), f0 = 1.339956.

#include "mma_tests.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const unsigned int n     = 5;
  const LocalRange   local(n, comm);
  const unsigned int begin = local.begin, n_local = local.size;

  const std::vector<double> coefficients = {61, 37, 19, 7, 1};
  const double              weight       = 0.0624;

  // The exact optimum.
  double sum_roots = 0;
  for (const double c : coefficients)
    sum_roots += std::pow(c, 0.25);
  std::vector<double> x_opt(n);
  double              f_opt = 0;
  for (unsigned int j = 0; j < n; ++j)
    {
      x_opt[j] = std::pow(coefficients[j], 0.25) * std::cbrt(sum_roots);
      f_opt += weight * x_opt[j];
    }

  // Everything local: the sums over the variables are MPI sums.
  std::vector<double> x(n_local, 5.), xmin(n_local, 1.), xmax(n_local, 10.);
  std::vector<double> df0(n_local, weight), dg(n_local);
  double              f0 = 0;
  std::vector<double> g(1);
  auto                evaluate = [&]() {
    f0   = 0;
    g[0] = 0;
    for (unsigned int j = 0; j < n_local; ++j)
      {
        const double c = coefficients[begin + j];
        f0 += weight * x[j];
        g[0] += c / std::pow(x[j], 3);
        dg[j] = -3 * c / std::pow(x[j], 4);
      }
    f0   = Utilities::MPI::sum(f0, comm);
    g[0] = Utilities::MPI::sum(g[0], comm) - 1;
  };

  softopt::MMA mma(n_local, {softopt::MMA::RowType::constraint}, comm);
  evaluate();
  deallog << "start: f0 = " << fixed(f0) << ", g = " << fixed(g[0])
          << std::endl;
  for (unsigned int k = 0; k < 100; ++k)
    {
      mma.update(x,
                 f0,
                 make_array_view(df0),
                 g,
                 {make_array_view(dg)},
                 make_array_view(xmin),
                 make_array_view(xmax));
      evaluate();
      if (mma.n_iterations() <= 5)
        deallog << "iteration " << mma.n_iterations() << ": f0 = " << fixed(f0)
                << ", g = " << fixed(g[0])
                << ", |dx| = " << error(mma.last_step()) << std::endl;
      if (mma.last_step() < 1e-6)
        break;
    }

  double x_error = 0;
  for (unsigned int j = 0; j < n_local; ++j)
    x_error = std::max(x_error, std::abs(x[j] - x_opt[begin + j]));
  x_error = Utilities::MPI::max(x_error, comm);

  std::vector<double> x_global;
  for (const auto &part : Utilities::MPI::all_gather(comm, x))
    x_global.insert(x_global.end(), part.begin(), part.end());
  deallog << "converged (|dx| < 1e-6) after " << mma.n_iterations()
          << " iterations" << std::endl;
  deallog << "x =";
  for (const double xj : x_global)
    deallog << " " << fixed(xj);
  deallog << std::endl;
  deallog << "f0 = " << fixed(f0) << " (exact " << fixed(f_opt)
          << "), g = " << fixed(g[0]) << std::endl;
  deallog << "max |x - x*| = " << error(x_error)
          << ", |f0 - f0*| = " << error(std::abs(f0 - f_opt)) << std::endl;
  deallog << "error below 1e-5: " << (x_error < 1e-5 ? "yes" : "NO")
          << std::endl;
}
