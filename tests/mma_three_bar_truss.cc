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
  const unsigned int begin = local.begin, end = local.end, n_local = local.size;

  const std::vector<double> x_opt = {0.75, 1.5, 0.75};
  const double              c_opt = 8. / 9.;

  // Rows 0-2: the compliances (objective rows), row 3: the volume.
  std::vector<double>              f;
  std::vector<std::vector<double>> df;
  std::vector<double>              x_global;
  auto evaluate = [&](const std::vector<double> &x) {
    x_global = gather_all(comm, x);
    three_bar_truss(x_global, f, df);
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
      min_max_update(mma, x, f, df, local, xmin, xmax);
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
