#ifndef softopt_solvers_refactorization_rule_h
#define softopt_solvers_refactorization_rule_h

#include <limits>

namespace softopt
{
  /**
   * When a modified Newton iteration factorizes its tangent anew: a kept
   * factorization (of the previous design's tangent, or of an earlier
   * step) serves while it reduces the residual by at least a factor 4 per
   * step. Used by the shape filter; the physics' warm starts measured
   * better with Newton steps on their own tangent (doc/benchmarks.md).
   */
  class RefactorizationRule
  {
  public:
    explicit RefactorizationRule(const bool have_factorization)
      : have_factorization(have_factorization)
    {}

    /** Whether the next step factorizes whatever its residual: then its
     * tangent is needed, otherwise only its residual (modified Newton
     * assembles the tangent only for the steps that factorize). */
    bool
    certain() const
    {
      return !have_factorization;
    }

    /** Call once per step with its residual norm, before the solve. */
    bool
    refactorize(const double residual_norm)
    {
      const bool result =
        !have_factorization || residual_norm > 0.25 * previous_norm;
      have_factorization = true;
      previous_norm      = residual_norm;
      return result;
    }

  private:
    bool       have_factorization;
    double     previous_norm = std::numeric_limits<double>::infinity();
  };
} // namespace softopt

#endif
