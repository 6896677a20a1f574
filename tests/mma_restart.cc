// An exact restart of MMA: on the three-bar truss in min-max form (see
// mma_three_bar_truss.cc), run 4 iterations, save the state (iteration
// count, x^{k-1}, x^{k-2}, asymptotes), load it into a fresh MMA object and
// continue; the iterates must equal those of an uninterrupted run bit for
// bit. Also: a state with the wrong number of variables is rejected.

#include "mma_tests.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  const MPI_Comm     comm  = MPI_COMM_WORLD;
  const LocalRange   local(3, comm);
  const unsigned int begin = local.begin, end = local.end, n_local = local.size;

  using Row                      = softopt::MMA::RowType;
  const std::vector<Row>    rows = {Row::objective,
                                    Row::objective,
                                    Row::objective,
                                    Row::constraint};
  const std::vector<double> x0   = {1.5, 0.5, 1.0};
  std::vector<double>       xmin(n_local, 0.001), xmax(n_local, 3.);

  // One MMA iteration on the local part x of the areas.
  auto step = [&](softopt::MMA &mma, std::vector<double> &x) {
    std::vector<double>              f;
    std::vector<std::vector<double>> df;
    three_bar_truss(gather_all(comm, x), f, df);
    min_max_update(mma, x, f, df, local, xmin, xmax);
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
          << below(difference, 1e-14) << std::endl;
  deallog << "iteration count: " << mma.n_iterations() << std::endl;

  // The areas after n_total iterations (near the optimum 0.75 1.5 0.75).
  const std::vector<double> x_global = gather_all(comm, x);
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
