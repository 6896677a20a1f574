// The volume of the pressurized cavity.

#include <softopt/functionals/design_surface.h>
#include <softopt/functionals/functional.h>
#include <softopt/functionals/quantity.h>

namespace softopt
{
  namespace
  {
    /** V_c, the cavity volume at the state (mm^3). */
    class CavityVolume : public Quantity
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      explicit CavityVolume(const double load_factor)
        : Quantity({load_factor})
      {}

      CavityVolume(ParameterHandler &,
                   const InputFile &,
                   const std::string &,
                   const double load_factor)
        : CavityVolume(load_factor)
      {}

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States              &states,
            Derivatives               *derivatives) const override
      {
        if (derivatives == nullptr)
          return cavity_volume(problem, design, *states[0]);
        derivatives->d_da.resize(1);
        return cavity_volume(
          problem, design, *states[0], &derivatives->d_da[0], &derivatives->d_dX);
      }
    };
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(CavityVolume,
                            "cavity volume",
                            "the volume V_c of the pressurized cavity, in mm^3.")

  std::unique_ptr<Functional>
  Functionals::cavity_volume(const double load_factor)
  {
    return std::make_unique<Functional>("V",
                                        Functional::Kind::objective,
                                        std::make_unique<CavityVolume>(load_factor),
                                        1.,
                                        0.);
  }
} // namespace softopt
