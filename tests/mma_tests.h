// Shared helpers of the MMA tests: the block of design variables this rank
// owns, the gathered global vector, numbers printed to 6 decimals, and the
// three-bar truss of mma_three_bar_truss.cc and mma_restart.cc.
#ifndef softopt_tests_mma_tests_h
#define softopt_tests_mma_tests_h

#include <softopt/io/csv_writer.h>
#include <softopt/optimization/mma.h>

#include "tests.h"

#include <vector>

namespace softopt_tests
{
  /** The contiguous block [begin, end) of n variables this rank owns. */
  struct LocalRange
  {
    LocalRange(const unsigned int n, const MPI_Comm comm)
      : begin(n * Utilities::MPI::this_mpi_process(comm) /
              Utilities::MPI::n_mpi_processes(comm))
      , end(n * (Utilities::MPI::this_mpi_process(comm) + 1) /
            Utilities::MPI::n_mpi_processes(comm))
      , size(end - begin)
    {}

    const unsigned int begin, end, size;
  };

  /** Every rank's local part, concatenated in rank order. */
  inline std::vector<double>
  gather_all(const MPI_Comm comm, const std::vector<double> &local)
  {
    std::vector<double> global;
    for (const auto &part : Utilities::MPI::all_gather(comm, local))
      global.insert(global.end(), part.begin(), part.end());
    return global;
  }

  /** One min-max MMA update (f_0 = 0) of the local part @p x, with the
   * local parts of the global gradients @p df. */
  inline void
  min_max_update(softopt::MMA                           &mma,
                 std::vector<double>                    &x,
                 const std::vector<double>              &f,
                 const std::vector<std::vector<double>> &df,
                 const LocalRange                       &local,
                 const std::vector<double>              &xmin,
                 const std::vector<double>              &xmax)
  {
    std::vector<ArrayView<const double>> df_local;
    for (const auto &gradient : df)
      df_local.emplace_back(gradient.data() + local.begin, local.size);
    mma.update(x,
               0.,
               ArrayView<const double>(),
               f,
               df_local,
               make_array_view(xmin),
               make_array_view(xmax));
  }

  /** A number rounded to 6 decimals, without "-0". */
  inline std::string
  fixed(const double value)
  {
    return softopt::CsvWriter::fixed(value, 6);
  }

  /**
   * The three-bar truss (see mma_three_bar_truss.cc): bars of unit length
   * and modulus along e_i, K(x) = sum_i x_i e_i e_i^T, three load cases.
   * Rows 0-2 of @p f are the compliances C_l = p_l^T K^-1 p_l, row 3 the
   * volume constraint (x1 + x2 + x3)/3 - 1; @p df their gradients, at the
   * (global) areas @p x.
   */
  inline void
  three_bar_truss(const std::vector<double>        &x,
                  std::vector<double>              &f,
                  std::vector<std::vector<double>> &df)
  {
    const double r           = 1. / std::sqrt(2.);
    const double e[3][2]     = {{-r, r}, {0, 1}, {r, r}};
    const double loads[3][2] = {{-r, r}, {0, 2 * r}, {r, r}};
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
        const double u[2] = {(K[1][1] * loads[l][0] - K[0][1] * loads[l][1]) / det,
                             (K[0][0] * loads[l][1] - K[1][0] * loads[l][0]) / det};
        f[l] = loads[l][0] * u[0] + loads[l][1] * u[1];
        // dC/dx_i = -u^T dK/dx_i u = -(e_i . u)^2
        for (unsigned int i = 0; i < 3; ++i)
          df[l][i] = -std::pow(e[i][0] * u[0] + e[i][1] * u[1], 2);
      }
    f[3] = (x[0] + x[1] + x[2]) / 3. - 1.;
    for (unsigned int i = 0; i < 3; ++i)
      df[3][i] = 1. / 3.;
  }
} // namespace softopt_tests

#endif
