#ifndef softopt_functionals_functional_h
#define softopt_functionals_functional_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/functionals/quantity.h>

#include <memory>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * An objective g_i = w Q (Eq. g0, the weight w of "Objective N") or a
   * constraint f_j = Q - tolerance <= 0 (Eq. constraint, the "Tolerance" of
   * "Constraint N") of a registered Quantity Q.
   */
  class Functional
  {
  public:
    using Vector      = Quantity::Vector;
    using States      = Quantity::States;
    using Derivatives = Quantity::Derivatives;

    enum class Kind
    {
      objective,
      constraint
    };

    /** @p scale Q - @p offset. */
    Functional(const std::string               &name,
               const Kind                       kind,
               std::unique_ptr<const Quantity>  quantity,
               const double                     scale,
               const double                     offset);

    /** "g_1", "f_2", "V": the column name in history.csv. */
    const std::string &
    name() const;

    Kind
    kind() const;

    /** The target load factors whose states it reads (Quantity). */
    const std::vector<double> &
    load_factors() const;

    /** The value at @p states (at load_factors()), with a non-null
     * @p derivatives also its partial derivatives (Quantity::value()). */
    double
    evaluate(const HyperelasticProblem &problem,
             const DesignConfiguration &design,
             const States              &states,
             Derivatives               *derivatives) const;

    /** |scale Q| at a value scale Q - offset: what a difference of two
     * values is relative to. An active constraint is near 0, its
     * quantity is not (softening: f = Q - 10 = 3e-5 with Q = 10.00003). */
    double
    magnitude(const double value) const;

    /** Quantity::along_load_path(). */
    bool
    along_load_path() const;

    /** The value along a load path: every state it reads is @p a. */
    double
    evaluate_at(const HyperelasticProblem &problem,
                const DesignConfiguration &design,
                const Vector              &a) const;

  private:
    std::string                     name_;
    Kind                            kind_;
    std::unique_ptr<const Quantity> quantity;
    double                          scale;
    double                          offset;
  };

  namespace Functionals
  {
    /**
     * Declares the subsections "Objective N" and "Constraint N" the file of
     * @p input contains (or "Objective 1" and "Constraint 1" as examples
     * without a file).
     */
    void
    declare_parameters(ParameterHandler &prm, const InputFile *input);

    /** The objectives and constraints of the file, in order. */
    std::vector<std::unique_ptr<const Functional>>
    create(ParameterHandler &prm, const InputFile &input);

    /** The cavity volume at @p load_factor as a functional (named "V"). */
    std::unique_ptr<Functional>
    cavity_volume(const double load_factor);
  } // namespace Functionals
} // namespace softopt

#endif
