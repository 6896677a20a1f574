// An exact restart of MMA: on the three-bar truss in min-max form (see
// mma_three_bar_truss.cc), run 4 iterations, save the state (iteration
// count, x^{k-1}, x^{k-2}, asymptotes), load it into a fresh MMA object and
// continue; the iterates must equal those of an uninterrupted run bit for
// bit. Also: a state with the wrong number of variables is rejected.

#include <softopt/optimization/mma.h>

#include "tests.h"

using namespace softopt_tests;

namespace
{
  const double r           = 1. / std::sqrt(2.);
  const double e[3][2]     = {{-r, r}, {0, 1}, {r, r}};
  const double loads[3][2] = {{-r, r}, {0, 2 * r}, {r, r}};

  // The three compliances and the volume constraint, and their gradients,
  // at the (global) areas x.
  void
  evaluate(const std::vector<double>        &x,
           std::vector<double>              &f,
           std::vector<std::vector<double>> &df)
  {
    f.assign(4, 0.);
    df.assign(4, std::vector<double>(3));
    double K[2][2] = {{0, 0}, {0, 0}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
          K[a][b] += x[i] * e[i][a] * e[i][b];
    const double det = K[0][0] * K[1][1] - K[0][1] * K[1][0];
    for (unsigned int l = 0; l < 3; ++l)
      {
        const double u[2] = {(K[1][1] * loads[l][0] - K[0][1] * loads[l][1]) /
                               det,
                             (K[0][0] * loads[l][1] - K[1][0] * loads[l][0]) /
                               det};
        f[l]              = loads[l][0] * u[0] + loads[l][1] * u[1];
        for (unsigned int i = 0; i < 3; ++i)
          df[l][i] = -std::pow(e[i][0] * u[0] + e[i][1] * u[1], 2);
      }
    f[3] = (x[0] + x[1] + x[2]) / 3. - 1.;
    for (unsigned int i = 0; i < 3; ++i)
      df[3][i] = 1. / 3.;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
  const unsigned int size  = Utilities::MPI::n_mpi_processes(comm);
  const unsigned int begin = 3 * rank / size, end = 3 * (rank + 1) / size;
  const unsigned int n_local = end - begin;

  using Row                      = softopt::MMA::RowType;
  const std::vector<Row>    rows = {Row::objective,
                                    Row::objective,
                                    Row::objective,
                                    Row::constraint};
  const std::vector<double> x0   = {1.5, 0.5, 1.0};
  std::vector<double>       xmin(n_local, 0.001), xmax(n_local, 3.);

  // One MMA iteration on the local part x of the areas.
  auto step = [&](softopt::MMA &mma, std::vector<double> &x) {
    std::vector<double> x_global;
    for (const auto &part : Utilities::MPI::all_gather(comm, x))
      x_global.insert(x_global.end(), part.begin(), part.end());
    std::vector<double>              f;
    std::vector<std::vector<double>> df;
    evaluate(x_global, f, df);
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
  };

  const unsigned int n_before = 4, n_total = 12;

  // The uninterrupted run.
  std::vector<std::vector<double>> reference;
  {
    softopt::MMA        mma(n_local, rows, comm);
    std::vector<double> x(x0.begin() + begin, x0.begin() + end);
    for (unsigned int k = 0; k < n_total; ++k)
      {
        step(mma, x);
        reference.push_back(x);
      }
  }

  // The interrupted run: save after n_before iterations, continue in a new
  // object (and a copy of x as it would be read back from a file).
  std::stringstream   state;
  std::vector<double> x_saved;
  {
    softopt::MMA        mma(n_local, rows, comm);
    std::vector<double> x(x0.begin() + begin, x0.begin() + end);
    for (unsigned int k = 0; k < n_before; ++k)
      step(mma, x);
    mma.save(state);
    x_saved = x;
  }
  softopt::MMA mma(n_local, rows, comm);
  mma.load(state);
  deallog << "iterations after load: " << mma.n_iterations() << std::endl;
  std::vector<double> x          = x_saved;
  double              difference = 0;
  for (unsigned int k = n_before; k < n_total; ++k)
    {
      step(mma, x);
      for (unsigned int j = 0; j < n_local; ++j)
        difference = std::max(difference, std::abs(x[j] - reference[k][j]));
    }
  difference = Utilities::MPI::max(difference, comm);
  deallog << "iterations " << n_before + 1 << "-" << n_total
          << " after the restart: max |x - x_uninterrupted| = "
          << error(difference) << std::endl;
  deallog << "iteration count: " << mma.n_iterations() << std::endl;

  // The areas after n_total iterations (near the optimum 0.75 1.5 0.75).
  std::vector<double> x_global;
  for (const auto &part : Utilities::MPI::all_gather(comm, x))
    x_global.insert(x_global.end(), part.begin(), part.end());
  deallog << "x =" << std::fixed << std::setprecision(6);
  for (const double xj : x_global)
    deallog << " " << xj;
  deallog << std::endl;

  // A state must not load into an MMA object of another size.
  softopt::MMA other(n_local + 1, rows, comm);
  state.clear();
  state.seekg(0);
  try
    {
      other.load(state);
      deallog << "a state of the wrong size was accepted" << std::endl;
    }
  catch (const ExceptionBase &)
    {
      deallog << "a state of the wrong size is rejected" << std::endl;
    }
}
