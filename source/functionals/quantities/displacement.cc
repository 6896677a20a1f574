// The design-surface means of the paper: the displacement along a direction
// field (objectives, Eq. g0) and its square (constraints, Eq. constraint).

#include <softopt/functionals/design_surface.h>
#include <softopt/functionals/direction_field.h>
#include <softopt/functionals/quantity.h>

namespace softopt
{
  namespace
  {
    /**
     * 1 / |dOmega^d| int (u . v)^k dS over the design surface in the design
     * configuration, k = 1 or 2, with v the subsection's direction field.
     */
    template <int k>
    class SurfaceMean : public Quantity
    {
    public:
      /** The direction field's entries are declared for every quantity. */
      static void
      declare_parameters(ParameterHandler &)
      {}

      SurfaceMean(ParameterHandler  &prm,
                  const InputFile   &input,
                  const std::string &subsection,
                  const double       load_factor)
        : Quantity({load_factor})
        , direction(DirectionFields::create(prm, input, subsection))
      {}

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States              &states,
            Derivatives               *derivatives) const override
      {
        const auto s = integrate_over_design_surface(
          problem, design, *states[0], *direction, derivatives != nullptr);
        const double top = k == 1 ? s.linear : s.quadratic;
        if (derivatives != nullptr)
          {
            // d(top / area) = d top / area - top d area / area^2
            derivatives->d_da = {k == 1 ? s.d_linear_da : s.d_quadratic_da};
            derivatives->d_da[0] *= 1. / s.area;
            derivatives->d_dX = k == 1 ? s.d_linear_dX : s.d_quadratic_dX;
            derivatives->d_dX *= 1. / s.area;
            derivatives->d_dX.add(-top / (s.area * s.area), s.d_area_dX);
          }
        return top / s.area;
      }

    private:
      const std::unique_ptr<const DirectionField> direction;
    };

    using MeanDisplacement        = SurfaceMean<1>;
    using MeanSquaredDisplacement = SurfaceMean<2>;
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(MeanDisplacement,
                            "displacement",
                            "the mean of u . v over the design surface, in mm "
                            "(Eq. g0; v the \"Direction field\").")
  SOFTOPT_REGISTER_QUANTITY(MeanSquaredDisplacement,
                            "squared displacement",
                            "the mean of (u . v)^2 over the design surface, in "
                            "mm^2 (Eq. constraint; v the \"Direction field\").")
} // namespace softopt
