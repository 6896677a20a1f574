#ifndef softopt_functionals_functional_h
#define softopt_functionals_functional_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include <memory>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * A function of the equilibrium state at one target load factor: an
   * objective g_i (Eq. g0), a constraint f_j <= 0 (Eq. constraint), or the
   * cavity volume. It gives its value and its partial derivatives in the
   * state a and in the design positions X, from which the adjoint method
   * makes dg/dd.
   */
  class Functional
  {
  public:
    enum class Kind
    {
      objective,
      constraint
    };

    Functional(const std::string &name, const Kind kind, const double load_factor);

    virtual ~Functional() = default;

    /** "g_1", "f_2", "V": the column name in history.csv. */
    const std::string &
    name() const;

    Kind
    kind() const;

    /** The target load factor lambda^i of the state it is evaluated at. */
    double
    load_factor() const;

    /**
     * The value at the state @p a of @p problem on @p design; with non-null
     * @p d_da and @p d_dX also the partial derivatives, on the hyperelastic
     * and the design DoFs.
     */
    virtual double
    evaluate(const HyperelasticProblem        &problem,
             const DesignConfiguration        &design,
             const PETScWrappers::MPI::Vector &a,
             PETScWrappers::MPI::Vector       *d_da,
             PETScWrappers::MPI::Vector       *d_dX) const = 0;

  private:
    std::string name_;
    Kind        kind_;
    double      load_factor_;
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
    std::vector<std::unique_ptr<Functional>>
    create(ParameterHandler &prm, const InputFile &input);

    /** The cavity volume at @p load_factor as a functional (named "V"). */
    std::unique_ptr<Functional>
    cavity_volume(const double load_factor);
  } // namespace Functionals
} // namespace softopt

#endif
