// MMA in the min-max form (a_i = 1 for the objective rows): the three-bar
// truss with three load cases,
//   minimize max(C_1(x), C_2(x), C_3(x))  s.t.  x1 + x2 + x3 <= 3,
//   0.001 <= x <= 3,
// as "minimize z s.t. C_l(x) - z <= 0, (x1 + x2 + x3)/3 - 1 <= 0".
// Three bars of unit length and Young's modulus 1 (x_i their areas) join
// the free node to three supports above it, along the unit vectors
//   e_1 = (-1, 1)/sqrt(2),  e_2 = (0, 1),  e_3 = (1, 1)/sqrt(2),
// so K(x) = sum_i x_i e_i e_i^T and C_l = p_l^T K^-1 p_l. The load cases
// are a unit load along bar 1, a unit load along bar 3, and both at once:
//   p_1 = e_1,  p_2 = e_1 + e_3 = (0, sqrt(2)),  p_3 = e_3.
// At x* = (3/4, 3/2, 3/4), K = diag(3/4, 9/4) and C_1 = C_2 = C_3 = 8/9.
// x* is the optimum: with u_l = K^-1 p_l, -dC_l/dx_i = (e_i.u_l)^2 is
// (64, 8, 16)/81, (16, 32, 16)/81 and (16, 8, 64)/81 for l = 1, 2, 3, so
// the weights mu = (1/6, 2/3, 1/6) (positive, sum 1) give the same value
// 8/27 = lambda on every bar: the KKT conditions of this convex problem
// hold. (A brute-force search over the volume simplex agrees.)

#include <softopt/optimization/mma.h>

#include "tests.h"

using namespace softopt_tests;

namespace
{
  // A number rounded to 6 decimals, without "-0".
  std::string
  fixed(const double value)
  {
    double r = std::round(value * 1e6) / 1e6;
    if (r == 0)
      r = 0;
    std::ostringstream s;
    s << std::fixed << std::setprecision(6) << r;
    return s.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const unsigned int n     = 3;
  const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
  const unsigned int size  = Utilities::MPI::n_mpi_processes(comm);
  const unsigned int begin = n * rank / size, end = n * (rank + 1) / size;
  const unsigned int n_local = end - begin;

  const double              r           = 1. / std::sqrt(2.);
  const double              e[3][2]     = {{-r, r}, {0, 1}, {r, r}};
  const double              loads[3][2] = {{-r, r}, {0, 2 * r}, {r, r}};
  const std::vector<double> x_opt       = {0.75, 1.5, 0.75};
  const double              c_opt       = 8. / 9.;

  // Rows 0-2: the compliances (objective rows), row 3: the volume.
  std::vector<double>              f(4);
  std::vector<std::vector<double>> df(4, std::vector<double>(n));
  std::vector<double>              x_global;
  auto evaluate = [&](const std::vector<double> &x) {
    x_global.clear();
    for (const auto &part : Utilities::MPI::all_gather(comm, x))
      x_global.insert(x_global.end(), part.begin(), part.end());
    double K[2][2] = {{0, 0}, {0, 0}};
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
          K[a][b] += x_global[i] * e[i][a] * e[i][b];
    const double det = K[0][0] * K[1][1] - K[0][1] * K[1][0];
    for (unsigned int l = 0; l < 3; ++l)
      {
        const double u[2] = {(K[1][1] * loads[l][0] - K[0][1] * loads[l][1]) /
                               det,
                             (K[0][0] * loads[l][1] - K[1][0] * loads[l][0]) /
                               det};
        f[l]              = loads[l][0] * u[0] + loads[l][1] * u[1];
        // dC/dx_i = -u^T dK/dx_i u = -(e_i . u)^2
        for (unsigned int i = 0; i < n; ++i)
          df[l][i] = -std::pow(e[i][0] * u[0] + e[i][1] * u[1], 2);
      }
    f[3] = (x_global[0] + x_global[1] + x_global[2]) / 3. - 1.;
    for (unsigned int i = 0; i < n; ++i)
      df[3][i] = 1. / 3.;
  };

  const std::vector<double> x0 = {1.5, 0.5, 1.0};
  std::vector<double>       x(x0.begin() + begin, x0.begin() + end);
  std::vector<double>       xmin(n_local, 0.001), xmax(n_local, 3.);

  using Row = softopt::MMA::RowType;
  softopt::MMA mma(
    n_local,
    {Row::objective, Row::objective, Row::objective, Row::constraint},
    comm);

  auto print = [&](const std::string &label) {
    deallog << label << ": C = " << fixed(f[0]) << " " << fixed(f[1]) << " "
            << fixed(f[2])
            << ", volume = " << fixed(x_global[0] + x_global[1] + x_global[2]);
  };

  evaluate(x);
  print("start");
  deallog << std::endl;
  for (unsigned int k = 0; k < 100; ++k)
    {
      std::vector<ArrayView<const double>> df_local;
      for (const auto &gradient : df)
        df_local.emplace_back(gradient.data() + begin, n_local);
      mma.update(x,
                 0.,
                 ArrayView<const double>(),
                 f,
                 df_local,
                 make_array_view(xmin),
                 make_array_view(xmax));
      evaluate(x);
      if (mma.n_iterations() <= 5)
        {
          print("iteration " + std::to_string(mma.n_iterations()));
          deallog << ", z = " << fixed(mma.get_z())
                  << ", |dx| = " << error(mma.last_step()) << std::endl;
        }
      if (mma.last_step() < 1e-6)
        break;
    }

  double x_error = 0, c_error = 0;
  for (unsigned int i = 0; i < n; ++i)
    x_error = std::max(x_error, std::abs(x_global[i] - x_opt[i]));
  for (unsigned int l = 0; l < 3; ++l)
    c_error = std::max(c_error, std::abs(f[l] - c_opt));
  deallog << "converged (|dx| < 1e-6) after " << mma.n_iterations()
          << " iterations" << std::endl;
  deallog << "x = " << fixed(x_global[0]) << " " << fixed(x_global[1]) << " "
          << fixed(x_global[2]) << std::endl;
  print("final");
  deallog << ", z = " << fixed(mma.get_z()) << std::endl;
  deallog << "lambda = " << fixed(mma.get_lambda()[0]) << " "
          << fixed(mma.get_lambda()[1]) << " " << fixed(mma.get_lambda()[2])
          << " " << fixed(mma.get_lambda()[3])
          << " (exact 0.166667 0.666667 0.166667 0.888889)" << std::endl;
  deallog << "max |x - x*| = " << error(x_error)
          << ", max |C - 8/9| = " << error(c_error) << std::endl;
  deallog << "error below 1e-5: " << (x_error < 1e-5 ? "yes" : "NO")
          << std::endl;
}
