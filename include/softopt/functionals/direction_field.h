#ifndef softopt_functionals_direction_field_h
#define softopt_functionals_direction_field_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <softopt/base/input.h>

#include <functional>
#include <memory>
#include <string>

namespace softopt
{
  /**
   * A direction field v(X) on the design surface (the v^i of Eq. g0 and the
   * s^j of Eq. constraint), evaluated in the design configuration X.
   *
   * To add one: write a class deriving from DirectionField in
   * source/functionals/direction_fields/, and register it there with
   * SOFTOPT_REGISTER_DIRECTION_FIELD (see constant.cc for a template).
   */
  class DirectionField
  {
  public:
    virtual ~DirectionField() = default;

    /** v(X), dimensionless. */
    virtual Tensor<1, 3>
    value(const Point<3> &X) const = 0;

    /** dv_i/dX_j in 1/mm: the problem-specific dv/dpsi of Eq. g0sens. */
    virtual Tensor<2, 3>
    gradient(const Point<3> &X) const = 0;
  };

  namespace DirectionFields
  {
    /** How a direction field is named, documented, declared and made. */
    struct Registration
    {
      std::string name;
      std::string description;
      /** Declares the field's own entries in the current subsection. */
      std::function<void(ParameterHandler &)> declare_parameters;
      /** Makes the field from the entries of the current subsection;
       * the string locates that subsection for messages. */
      std::function<std::unique_ptr<DirectionField>(ParameterHandler &,
                                                    const InputFile &,
                                                    const std::string &)>
        create;
    };

    /** Adds a field to the registry (called by the registration macro). */
    bool
    register_field(const Registration &registration);

    /** Declares "Direction field" and every registered field's entries in
     * the current subsection. */
    void
    declare_parameters(ParameterHandler &prm, const std::string &default_field);

    /** Makes the field the current subsection names. */
    std::unique_ptr<DirectionField>
    create(ParameterHandler  &prm,
           const InputFile   &input,
           const std::string &subsection);

    /** The registered field @p name with its entries at their defaults
     * (constant: (1, 0, 0); inward radial: about the x axis). */
    std::unique_ptr<DirectionField>
    create_default(const std::string &name);
  } // namespace DirectionFields
} // namespace softopt

/** Registers a direction field class under @p name (one line per field,
 * inside namespace softopt). */
#define SOFTOPT_REGISTER_DIRECTION_FIELD(classname, name, description)   \
  namespace                                                             \
  {                                                                     \
    const bool classname##_registered =                                 \
      softopt::DirectionFields::register_field(                         \
        {name,                                                          \
         description,                                                   \
         &classname::declare_parameters,                                \
         [](dealii::ParameterHandler   &prm,                            \
            const softopt::InputFile   &input,                          \
            const std::string          &subsection)                     \
           -> std::unique_ptr<softopt::DirectionField> {                \
           return std::make_unique<classname>(prm, input, subsection);  \
         }});                                                           \
  }

#endif
