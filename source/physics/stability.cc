// The eigenvalue of the tangent nearest zero: how far a state is from a
// limit point of its load path.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <softopt/physics/stability.h>

#include <cmath>
#include <limits>

namespace softopt
{
  LowestEigenvalue
  lowest_eigenvalue(HyperelasticProblem               &problem,
                    const HyperelasticProblem::Vector &a,
                    const double                       load_factor,
                    const double                       tolerance,
                    const unsigned int                 max_iterations)
  {
    using Vector = HyperelasticProblem::Vector;
    Vector r, P;
    problem.assemble(a, load_factor, r, P, true);
    problem.factorize();
    const auto &K           = problem.tangent();
    const auto &constraints = problem.get_constraints();

    // Only the free displacement DoFs: the constrained and the condensed
    // rows of K are decoupled diagonals whose values are no eigenvalues of
    // the body.
    const auto free_part = [&](Vector &v) {
      for (const auto i : v.locally_owned_elements())
        if (constraints.is_constrained(i))
          v(i) = 0;
      v.compress(VectorOperation::insert);
      problem.zero_condensed(v);
    };

    // Subspace iteration with a block of m vectors and Rayleigh-Ritz: the
    // eigenvalues nearest zero come in clusters (equal pairs on an
    // axisymmetric part, many nearly equal modes on a sphere), where one
    // vector would converge at the ratio of two nearly equal eigenvalues;
    // the block converges at the ratio to the (m+1)-th. Starts with every
    // mode in them, the same on any number of ranks.
    const unsigned int  m = 4;
    std::vector<Vector> X(m, problem.create_vector()), Y(m, problem.create_vector());
    for (unsigned int k = 0; k < m; ++k)
      {
        for (const auto i : X[k].locally_owned_elements())
          X[k](i) = std::sin((0.7548776662 + 0.1 * k) * double(i) + 0.3 * (k + 1));
        X[k].compress(VectorOperation::insert);
        free_part(X[k]);
      }
    Vector            K_y = problem.create_vector();
    LowestEigenvalue  result;
    double            previous = std::numeric_limits<double>::quiet_NaN();
    LAPACKFullMatrix<double> H(m, m);
    for (result.iterations = 1;; ++result.iterations)
      {
        // Y = K^{-1} X, orthonormalized (twice Gram-Schmidt for safety).
        for (unsigned int k = 0; k < m; ++k)
          {
            problem.solve(X[k], Y[k]);
            free_part(Y[k]);
            for (unsigned int pass = 0; pass < 2; ++pass)
              for (unsigned int j = 0; j < k; ++j)
                Y[k].add(-(Y[j] * Y[k]), Y[j]);
            Y[k] /= Y[k].l2_norm();
          }
        // Rayleigh-Ritz: H = Y^T K Y, symmetric.
        H.reinit(m, m);
        for (unsigned int k = 0; k < m; ++k)
          {
            K.vmult(K_y, Y[k]);
            for (unsigned int j = 0; j <= k; ++j)
              H(j, k) = H(k, j) = Y[j] * K_y;
          }
        H.set_property(LAPACKSupport::symmetric);
        FullMatrix<double> V;
        dealii::Vector<double> values;
        H.compute_eigenvalues_symmetric(-std::numeric_limits<double>::max(),
                                        std::numeric_limits<double>::max(),
                                        0.,
                                        values,
                                        V);
        for (unsigned int k = 0; k < m; ++k)
          {
            X[k] = 0;
            for (unsigned int j = 0; j < m; ++j)
              X[k].add(V(j, k), Y[j]);
          }
        unsigned int nearest = 0;
        for (unsigned int k = 1; k < m; ++k)
          if (std::abs(values[k]) < std::abs(values[nearest]))
            nearest = k;
        result.value = values[nearest];
        result.vector = X[nearest];
        if (std::abs(result.value - previous) <= tolerance * std::abs(result.value) ||
            result.iterations == max_iterations)
          break;
        previous = result.value;
      }
    K.vmult(K_y, result.vector);
    K_y.add(-result.value, result.vector);
    free_part(K_y);
    result.residual = K_y.l2_norm() / std::abs(result.value);
    return result;
  }
} // namespace softopt
