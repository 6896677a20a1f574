#ifndef softopt_physics_stability_h
#define softopt_physics_stability_h

#include <softopt/physics/hyperelastic_problem.h>

namespace softopt
{
  /** The eigenpair of lowest_eigenvalue(). */
  struct LowestEigenvalue
  {
    /** The eigenvalue of the condensed tangent nearest zero (N/mm; negative
     * on a descending branch: the state is unstable under pressure). */
    double value = 0;
    /** ||K phi - value phi|| / |value|, for the eigenvector phi (|phi| = 1). */
    double residual = 0;
    unsigned int iterations = 0;
    HyperelasticProblem::Vector vector;
  };

  /**
   * The eigenvalue nearest zero of the condensed tangent K(a) at load
   * factor @p load_factor, on the free displacement DoFs (the Dirichlet and
   * the condensed pressure DoFs removed), by subspace iteration with four
   * vectors on K's factorization and Rayleigh-Ritz (K is symmetric: the
   * follower pressure on a closed cavity is conservative). The eigenvalues
   * nearest zero come in clusters (equal pairs on an axisymmetric part,
   * many nearly equal modes on a sphere), where a single vector converges
   * at the ratio of two nearly equal eigenvalues. At a limit
   * point of the load path the value is zero whatever the mode's shape:
   * scaled by its value at rest it measures how far a state is from a snap
   * (doc/theory.md, "Keeping the snap above the target").
   *
   * Assembles and factorizes K (the factorization is left for the next
   * solve). Stops when the quotient changes by less than @p tolerance
   * relative, or after @p max_iterations (reported in the result).
   * Collective.
   */
  LowestEigenvalue
  lowest_eigenvalue(HyperelasticProblem               &problem,
                    const HyperelasticProblem::Vector &a,
                    const double                       load_factor,
                    const double                       tolerance      = 1e-8,
                    const unsigned int                 max_iterations = 100);
} // namespace softopt

#endif
