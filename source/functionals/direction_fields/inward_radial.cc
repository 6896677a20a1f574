#include <deal.II/base/exceptions.h>

#include <deal.II/base/symmetric_tensor.h>

#include <softopt/functionals/direction_field.h>

namespace softopt
{
  namespace
  {
    /**
     * The unit vector from X towards an axis, perpendicular to it: about
     * the x axis this is the paper's v = (0, -cos theta, -sin theta).
     */
    class InwardRadial : public DirectionField
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Axis point",
                          "0, 0, 0",
                          vector_pattern(),
                          "A point on the axis of the inward radial field, "
                          "in mm.");
        prm.declare_entry("Axis direction",
                          "1, 0, 0",
                          vector_pattern(),
                          "The direction of the axis of the inward radial "
                          "field (normalized internally).");
      }

      InwardRadial(ParameterHandler  &prm,
                   const InputFile   &input,
                   const std::string &subsection)
        : axis_point(parse_vector(prm.get("Axis point"),
                                  input.where(subsection, "Axis point")))
        , axis(parse_vector(prm.get("Axis direction"),
                            input.where(subsection, "Axis direction")))
      {
        AssertThrow(axis.norm() > 0,
                    ExcMessage(input.where(subsection, "Axis direction") +
                               ": the axis direction must not be zero."));
        axis /= axis.norm();
      }

      Tensor<1, 3>
      value(const Point<3> &X) const override
      {
        const Tensor<1, 3> r = radial(X);
        return -r / r.norm();
      }

      /** d(-r/|r|)/dX = -(I - a a - e e)/|r| with e = r/|r|. */
      Tensor<2, 3>
      gradient(const Point<3> &X) const override
      {
        const Tensor<1, 3> r = radial(X);
        const double       rho = r.norm();
        const Tensor<1, 3> e   = r / rho;
        Tensor<2, 3> g = unit_symmetric_tensor<3>() - outer_product(axis, axis) -
                         outer_product(e, e);
        return -g / rho;
      }

    private:
      Tensor<1, 3>
      radial(const Point<3> &X) const
      {
        const Tensor<1, 3> d = X - Point<3>(axis_point);
        const Tensor<1, 3> r = d - (d * axis) * axis;
        AssertThrow(r.norm() > 1e-12,
                    ExcMessage("The inward radial direction is undefined on "
                               "its axis; the design surface touches it."));
        return r;
      }

      const Tensor<1, 3> axis_point;
      Tensor<1, 3>       axis;
    };
  } // namespace

  SOFTOPT_REGISTER_DIRECTION_FIELD(InwardRadial,
                                   "inward radial",
                                   "the unit vector towards the axis given by "
                                   "\"Axis point\" and \"Axis direction\", "
                                   "perpendicular to it (about the x axis: "
                                   "(0, -cos theta, -sin theta)).")
} // namespace softopt
