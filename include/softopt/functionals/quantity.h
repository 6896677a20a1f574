#ifndef softopt_functionals_quantity_h
#define softopt_functionals_quantity_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/base/input.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * A quantity Q(a^1, ..., a^n, X) of the equilibrium states at some target
   * load factors and of the design positions X: what the entry "Quantity"
   * of an Objective or Constraint subsection names (Functional makes g = w Q
   * or f = Q - tolerance of it). It gives its value and its partial
   * derivatives in each state and in X, from which the adjoint method makes
   * dQ/dd (DesignProblem::gradients()).
   *
   * To add one: write a class deriving from Quantity in
   * source/functionals/quantities/, with declare_parameters() and a
   * constructor reading its entries, and register it there with
   * SOFTOPT_REGISTER_QUANTITY (see point_displacement.cc; doc/extending.md).
   */
  class Quantity
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    /** The states at load_factors(), in that order (ghosted or not). */
    using States = std::vector<const Vector *>;

    /** The partial derivatives: dQ/da^i on the hyperelastic DoFs for each
     * load factor, and dQ/dX on the design DoFs (the positions X = X_o +
     * psi, through which Q depends on the shape). */
    struct Derivatives
    {
      std::vector<Vector> d_da;
      Vector              d_dX;
    };

    /** A quantity of the states at @p load_factors (positive). */
    explicit Quantity(const std::vector<double> &load_factors);

    virtual ~Quantity() = default;

    /** The target load factors lambda^i whose states it reads. */
    const std::vector<double> &
    load_factors() const;

    /** Whether value() of a single state means something for a state at
     * another load factor than its own, as along a load path (false for one
     * that reads the tangent, whose load stiffness is that of its load
     * factor: the final analysis evaluates it at its target only). */
    virtual bool
    along_load_path() const
    {
      return true;
    }

    /**
     * The value at @p states of @p problem on @p design, and with a non-null
     * @p derivatives also the partial derivatives, which it sets up (one
     * d_da per load factor). Collective.
     */
    virtual double
    value(const HyperelasticProblem &problem,
          const DesignConfiguration &design,
          const States              &states,
          Derivatives               *derivatives) const = 0;

  private:
    std::vector<double> load_factors_;
  };

  namespace Quantities
  {
    /** How a quantity is named, documented, declared and made. */
    struct Registration
    {
      std::string name;
      /** One sentence: what Q is, in which unit. */
      std::string description;
      /** Declares the quantity's own entries in the current subsection
       * (entries shared with others, like the direction field's, are
       * declared once for all: Functionals::declare_parameters). */
      std::function<void(ParameterHandler &)> declare_parameters;
      /** Makes it from the entries of the current subsection (the string
       * locates it for messages) at the subsection's "Load factor". */
      std::function<std::unique_ptr<Quantity>(ParameterHandler &,
                                              const InputFile &,
                                              const std::string &,
                                              const double)>
        create;
    };

    /** Adds a quantity to the registry (called by the registration macro). */
    bool
    register_quantity(const Registration &registration);

    /** "Quantity" with every registered name, and every quantity's own
     * entries, in the current subsection. */
    void
    declare_parameters(ParameterHandler &prm, const std::string &default_quantity);

    /** The quantity the current subsection names, at @p load_factor. */
    std::unique_ptr<Quantity>
    create(ParameterHandler  &prm,
           const InputFile   &input,
           const std::string &subsection,
           const double       load_factor);
  } // namespace Quantities
} // namespace softopt

/** Registers a quantity class under @p name (one line per quantity, inside
 * namespace softopt); the class has a static declare_parameters(prm) and a
 * constructor (prm, input, subsection, load_factor). */
#define SOFTOPT_REGISTER_QUANTITY(classname, name, description)           \
  namespace                                                             \
  {                                                                     \
    const bool classname##_registered = softopt::Quantities::register_quantity( \
      {name,                                                            \
       description,                                                     \
       &classname::declare_parameters,                                  \
       [](dealii::ParameterHandler &prm,                                \
          const softopt::InputFile &input,                              \
          const std::string        &subsection,                         \
          const double              load_factor) -> std::unique_ptr<softopt::Quantity> { \
         return std::make_unique<classname>(prm, input, subsection, load_factor); \
       }});                                                             \
  }

#endif
