#ifndef softopt_optimization_secant_predictor_h
#define softopt_optimization_secant_predictor_h

#include <deal.II/lac/petsc_vector.h>

#include <map>
#include <optional>

namespace softopt
{
  using namespace dealii;

  /**
   * The start of a warm-started design: the target states extrapolated along
   * the secant through the last two accepted designs. With X = X_o + psi the
   * nodal positions, the new design's step is projected on the last one,
   *   alpha = (X - X_k) . (X_k - X_{k-1}) / |X_k - X_{k-1}|^2,
   * and every target state starts at a_k + alpha (a_k - a_{k-1}), the first
   * order change of the equilibrium along the part of the step the secant
   * knows. MMA moves the design in nearly the same direction from one
   * iteration to the next, so alpha is near 1 and the start's residual falls
   * about eightfold against a_k (a shape change at fixed nodal
   * displacements strains the nearly incompressible body by far more than
   * the load does): Newton needs one step fewer (doc/theory.md). X is
   * continuous across a mesh update, so the secant survives it. It keeps
   * X_k, X_{k-1} and a_{k-1}; a_k is the caller's (DesignProblem's states).
   */
  class SecantPredictor
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    /** An accepted design as the secant sees it: its nodal positions and
     * its states at the target load factors. */
    struct Design
    {
      Vector                   X;
      std::map<double, Vector> states;
    };

    /** The predicted start and the alpha it used. */
    struct Prediction
    {
      std::map<double, Vector> states;
      double                   alpha;
    };

    /** |alpha| is capped here: a step much longer than the last one is
     * outside what the secant knows. */
    static constexpr double max_alpha = 2;

    /** The start for the design at nodal positions @p X from the last
     * accepted design's @p states; none until two designs were accepted
     * (or if the secant has no length). */
    std::optional<Prediction>
    predict(const Vector &X, const std::map<double, Vector> &states) const;

    /** Records an accepted design at nodal positions @p X; @p last_states
     * are the states of the design accepted before it (empty for the
     * first), which become a_{k-1}. */
    void
    accept(const Vector &X, const std::map<double, Vector> &last_states);

    /** X_k, the positions of the last accepted design (empty if none). */
    const Vector &
    last_positions() const;

    /** X_{k-1} and a_{k-1} (empty if fewer than two were accepted). */
    const Design &
    previous_design() const;

    /** Sets the history (a restart from a checkpoint). */
    void
    restore(const Vector &last_positions, const Design &previous);

  private:
    Vector X_last;
    Design previous;
  };
} // namespace softopt

#endif
