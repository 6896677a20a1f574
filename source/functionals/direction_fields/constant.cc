// A direction field is one file like this one: a class deriving from
// DirectionField, with declare_parameters() and a constructor reading its
// entries, and the registration line at the bottom.

#include <softopt/functionals/direction_field.h>

namespace softopt
{
  namespace
  {
    /** A constant direction v (the paper's (1, 0, 0) and (-1, 0, 0)). */
    class Constant : public DirectionField
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Direction",
                          "1, 0, 0",
                          vector_pattern(),
                          "The constant direction (dimensionless, used as "
                          "given, not normalized), as three comma-separated "
                          "numbers; also the direction s^j of a constraint.");
      }

      Constant(ParameterHandler  &prm,
               const InputFile   &input,
               const std::string &subsection)
        : direction(parse_vector(prm.get("Direction"),
                                 input.where(subsection, "Direction")))
      {
        // A zero direction makes the functional zero for every design.
        AssertThrow(direction.norm() > 0,
                    ExcMessage(input.where(subsection, "Direction") +
                               ": the direction must not be zero (the "
                               "functional would be 0 for every design)."));
      }

      Tensor<1, 3>
      value(const Point<3> &) const override
      {
        return direction;
      }

      Tensor<2, 3>
      gradient(const Point<3> &) const override
      {
        return {};
      }

    private:
      const Tensor<1, 3> direction;
    };
  } // namespace

  SOFTOPT_REGISTER_DIRECTION_FIELD(Constant,
                                   "constant",
                                   "the vector given by \"Direction\".")
} // namespace softopt
