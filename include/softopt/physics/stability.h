#ifndef softopt_physics_stability_h
#define softopt_physics_stability_h

#include <softopt/physics/hyperelastic_problem.h>

#include <memory>

namespace softopt
{
  /** The eigenpair of lowest_eigenvalue(). */
  struct LowestEigenvalue
  {
    /** The smallest positive eigenvalue, or on a descending branch (the
     * state is unstable under pressure) the negative one nearest zero: N/mm,
     * or dimensionless with a metric M (lowest_eigenvalue()). */
    double value = 0;
    /** ||K^{-1} M phi - phi / value||_M |value| for the eigenvector phi
     * (||phi||_M = 1; M = I without a metric): a bound on the relative
     * error of 1 / value. */
    double residual = 0;
    /** Lanczos steps. */
    unsigned int iterations = 0;
    HyperelasticProblem::Vector vector;
  };

  /**
   * The metric K_0 of lowest_eigenvalue(): the condensed tangent at rest of
   * @p problem's body (its mesh, mapping, boundaries and DoF numbering)
   * with the same isochoric material and almost no bulk term (bulk modulus
   * G_0 / 900). Then K(0) - K_0 is positive semidefinite, so mu >= 1 at
   * rest, and mu = 1 for modes without a change of volume. Under load mu
   * is a mode's stiffness relative to its shear stiffness at rest. With the
   * bulk term in K_0 (nu = 0.49, or even nu = 0) every mode that keeps the
   * volume of the deformed body but not of the body at rest would have a
   * small mu at any pressure (doc/theory.md). Collective.
   */
  class StabilityMetric
  {
  public:
    /** Sets up the body at rest and assembles K_0. */
    explicit StabilityMetric(const HyperelasticProblem &problem);
    ~StabilityMetric();

    /** Assembles K_0 again: for a new design on the same mesh (the
     * mapping's positions changed). */
    void
    reassemble();

    const PETScWrappers::MPI::SparseMatrix &
    matrix() const;

    /** The body at rest whose tangent matrix() is: its residual's shape
     * derivative is that of K_0 (the quantity "softening"). */
    const HyperelasticProblem &
    at_rest_problem() const;

  private:
    std::unique_ptr<const Material>     material;
    std::unique_ptr<HyperelasticProblem> at_rest;
  };

  /**
   * The smallest positive eigenvalue of the condensed tangent K(a) at load
   * factor @p load_factor, or, if K has a negative eigenvalue (a
   * descending branch: unstable under pressure; the factorization's
   * negative pivots say so), the negative one nearest zero; on the free
   * displacement DoFs (the Dirichlet and the condensed pressure DoFs
   * removed). With @p metric M (symmetric positive definite on the free
   * DoFs) the same for mu of K phi = mu M phi: with the StabilityMetric, mu
   * is the stiffness of the softest mode relative to its own shear
   * stiffness at rest (at least 1 at rest, 0 at a limit point), the same on
   * any mesh. K is symmetric: the follower pressure on a closed cavity is
   * conservative.
   *
   * Lanczos on K^{-1} M with K's factorization and full
   * reorthogonalization; its extreme Ritz values are 1 / mu for the two
   * eigenvalues wanted, and converge where the spectrum clusters (equal
   * pairs on an axisymmetric part, many nearly equal modes on a sphere,
   * mu near 1 for every isochoric mode at low load). Assembles and
   * factorizes K (the factorization is left for the next solve). Stops
   * when the Ritz pair's residual estimate falls below @p tolerance
   * relative, or after @p max_iterations Lanczos steps (reported).
   * @p start, if given, is a guess of the mode (the last design's): Lanczos
   * starts from it plus a tenth of the start that has every mode in it, so
   * that a mode that has become softer than the guessed one is still found.
   * Collective.
   */
  LowestEigenvalue
  lowest_eigenvalue(HyperelasticProblem               &problem,
                    const HyperelasticProblem::Vector &a,
                    const double                       load_factor,
                    const double                       tolerance      = 1e-6,
                    const unsigned int                 max_iterations = 100,
                    const PETScWrappers::MPI::SparseMatrix *metric    = nullptr,
                    const HyperelasticProblem::Vector      *start     = nullptr);
} // namespace softopt

#endif
