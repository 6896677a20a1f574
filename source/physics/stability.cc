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
  namespace
  {
    /** @p base's isochoric part with almost no bulk term: nu = -0.995 is
     * a bulk modulus of G_0 / 900 (zero would leave the condensed pressure
     * undefined). */
    class IsochoricPart : public Material
    {
    public:
      explicit IsochoricPart(const Material &base)
        : Material(base.shear_modulus, -0.995)
        , base(base)
      {}

      double
      isochoric_energy(const Tensor<2, 3> &F) const override
      {
        return base.isochoric_energy(F);
      }

      Tensor<2, 3>
      isochoric_stress(const Tensor<2, 3> &F) const override
      {
        return base.isochoric_stress(F);
      }

      Tensor<4, 3>
      isochoric_tangent(const Tensor<2, 3> &F) const override
      {
        return base.isochoric_tangent(F);
      }

    private:
      const Material &base;
    };
  } // namespace



  StabilityMetric::StabilityMetric(const HyperelasticProblem &problem)
    : material(std::make_unique<IsochoricPart>(problem.get_material()))
  {
    at_rest = std::make_unique<HyperelasticProblem>(problem.get_dof_handler().get_triangulation(),
                                                    problem.get_mapping(),
                                                    problem.get_geometry(),
                                                    *material,
                                                    0.);
    at_rest->setup_system();
    // Its matrix multiplies the problem's vectors.
    AssertThrow(at_rest->get_dof_handler().locally_owned_dofs() ==
                    problem.get_dof_handler().locally_owned_dofs() &&
                  at_rest->get_constraints().n_constraints() ==
                    problem.get_constraints().n_constraints(),
                ExcInternalError());
    reassemble();
  }



  StabilityMetric::~StabilityMetric() = default;



  void
  StabilityMetric::reassemble()
  {
    HyperelasticProblem::Vector r, P;
    at_rest->assemble(at_rest->create_vector(), 0., r, P, true);
  }



  const PETScWrappers::MPI::SparseMatrix &
  StabilityMetric::matrix() const
  {
    return at_rest->tangent();
  }



  const HyperelasticProblem &
  StabilityMetric::at_rest_problem() const
  {
    return *at_rest;
  }



  LowestEigenvalue
  lowest_eigenvalue(HyperelasticProblem               &problem,
                    const HyperelasticProblem::Vector &a,
                    const double                       load_factor,
                    const double                       tolerance,
                    const unsigned int                 max_iterations,
                    const PETScWrappers::MPI::SparseMatrix *metric,
                    const HyperelasticProblem::Vector      *start)
  {
    using Vector = HyperelasticProblem::Vector;
    Vector r, P;
    problem.assemble(a, load_factor, r, P, true);
    problem.factorize();
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

    // M y (y itself without a metric).
    Vector     M_y = problem.create_vector(), K_y = problem.create_vector();
    const auto apply_metric = [&](const Vector &y, Vector &result) {
      if (metric)
        {
          metric->vmult(result, y);
          free_part(result);
        }
      else
        result = y;
    };

    // Lanczos on T = K^{-1} M, self-adjoint in the M inner product, with
    // full reorthogonalization: the Ritz values of the tridiagonal matrix
    // approach T's extreme eigenvalues theta = 1 / mu, the largest (the
    // smallest positive mu) and, if K has a negative eigenvalue, the most
    // negative (the negative mu nearest zero), even where the spectrum
    // clusters (mu near 1 for every isochoric mode with a metric), where
    // subspace iteration stalls. Starts with every mode in it, the same on
    // any number of ranks (and with the guess @p start).
    std::vector<Vector> Q;
    Vector              q = problem.create_vector();
    for (const auto i : q.locally_owned_elements())
      q(i) = std::sin(0.7548776662 * double(i) + 0.3);
    q.compress(VectorOperation::insert);
    free_part(q);
    Vector     M_q       = problem.create_vector();
    const auto normalize = [&]() {
      apply_metric(q, M_q);
      const double q_norm = std::sqrt(M_q * q);
      q /= q_norm;
      M_q /= q_norm;
    };
    normalize();
    if (start != nullptr)
      {
        // The guess, and a tenth of every mode: Lanczos converges from the
        // guess in fewer steps and still finds a mode that has overtaken it.
        Vector guess = *start;
        free_part(guess);
        apply_metric(guess, M_y);
        const double guess_norm = std::sqrt(M_y * guess);
        if (guess_norm > 0)
          {
            q *= 0.1;
            q.add(1. / guess_norm, guess);
            normalize();
          }
      }
    // With negative pivots K has as many negative eigenvalues (and, M being
    // positive definite, as many negative mu): then the wanted end is the
    // most negative theta, and the iteration goes on until it is negative.
    const bool          unstable = problem.n_negative_pivots() > 0;
    std::vector<double> alpha, beta;
    LowestEigenvalue    result;
    FullMatrix<double>  S;
    unsigned int        chosen = 0;
    Vector              w = problem.create_vector();
    for (result.iterations = 1;; ++result.iterations)
      {
        Q.push_back(q);
        problem.solve(M_q, w);
        free_part(w);
        alpha.push_back(M_q * w);
        // w -= Q (Q^T M w), twice: the three-term recurrence alone loses
        // orthogonality once a Ritz value has converged.
        for (unsigned int pass = 0; pass < 2; ++pass)
          {
            apply_metric(w, K_y); // K_y holds M w here
            for (const auto &q_i : Q)
              w.add(-(q_i * K_y), q_i);
          }
        apply_metric(w, K_y);
        beta.push_back(std::sqrt(std::max(0., K_y * w)));

        // The tridiagonal matrix's eigenpairs.
        const unsigned int       j = alpha.size();
        LAPACKFullMatrix<double> T(j, j);
        for (unsigned int i = 0; i < j; ++i)
          {
            T(i, i) = alpha[i];
            if (i + 1 < j)
              T(i, i + 1) = T(i + 1, i) = beta[i];
          }
        T.set_property(LAPACKSupport::symmetric);
        dealii::Vector<double> theta;
        T.compute_eigenvalues_symmetric(-std::numeric_limits<double>::max(),
                                        std::numeric_limits<double>::max(),
                                        0.,
                                        theta,
                                        S);
        AssertThrow(theta.size() == j,
                    ExcMessage("LAPACK found " + std::to_string(theta.size()) + " of the " +
                               std::to_string(j) + " eigenvalues of the Lanczos matrix"));
        // Ascending: theta[0] is the most negative, theta[j-1] the largest.
        chosen       = unstable ? 0 : j - 1;
        result.value = 1. / theta[chosen];
        // ||T x - theta x||_M = beta_j |s_j| for the Ritz vector x = Q s.
        const double estimate = beta.back() * std::abs(S(j - 1, chosen)) / std::abs(theta[chosen]);
        if ((estimate <= tolerance && (theta[chosen] < 0) == unstable) ||
            result.iterations == max_iterations)
          break;
        // The next q and M q (K_y holds M w).
        q = w;
        q /= beta.back();
        M_q = K_y;
        M_q /= beta.back();
      }

    result.vector = problem.create_vector();
    for (unsigned int i = 0; i < Q.size(); ++i)
      result.vector.add(S(i, chosen), Q[i]);
    // r = K^{-1} M x - x / mu, measured in the M norm relative to 1 / mu:
    // a bound on the relative error of 1 / mu (K^{-1} M is self-adjoint in
    // the M inner product), explicitly rather than from the recurrence.
    apply_metric(result.vector, M_y);
    const double x_norm = std::sqrt(M_y * result.vector);
    problem.solve(M_y, w);
    free_part(w);
    w.add(-1. / result.value, result.vector);
    apply_metric(w, M_y);
    result.residual = std::sqrt(std::max(0., M_y * w)) * std::abs(result.value) / x_norm;
    return result;
  }
} // namespace softopt
