#ifndef softopt_optimization_secant_predictor_h
#define softopt_optimization_secant_predictor_h

#include <deal.II/lac/petsc_vector.h>

#include <map>

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
   * continuous across a mesh update, so the secant survives it.
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

    /** |alpha| is capped here: a step much longer than the last one is
     * outside what the secant knows. */
    static constexpr double max_alpha = 2;

    /** The states to start from for the design at nodal positions @p X,
     * given the last accepted design's @p states (returned unchanged until
     * two designs were accepted). */
    std::map<double, Vector>
    predict(const Vector &X, const std::map<double, Vector> &states);

    /** Records an accepted design: its positions and target states. */
    void
    accept(const Vector &X, const std::map<double, Vector> &states);

    /** The last accepted design and the one before it (empty if there is
     * none yet), for a checkpoint. */
    const Design &
    last_design() const;

    const Design &
    previous_design() const;

    /** Sets the history (a restart from a checkpoint). */
    void
    restore(const Design &previous, const Design &last);

    /** alpha of the last predict() (0 if it had no secant). */
    double
    last_alpha() const;

  private:
    Design last, previous;
    double alpha = 0;
  };
} // namespace softopt

#endif
