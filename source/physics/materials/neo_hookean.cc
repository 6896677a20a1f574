// The paper's material (Eq. c1): W_iso = G/2 (J^{-2/3} tr C - 3), with G
// from Young's modulus and Poisson's ratio at small strain.

#include <deal.II/base/utilities.h>

#include <softopt/physics/hyperelastic_parts.h>
#include <softopt/physics/material.h>

namespace softopt
{
  namespace
  {
    class NeoHookean : public Material
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Young's modulus",
                          "1.2",
                          Patterns::Double(),
                          "neo-Hookean: Young's modulus E in MPa at small "
                          "strain, G = E / (2 (1 + nu)); the paper's PVS has "
                          "1.2.");
      }

      NeoHookean(ParameterHandler &prm,
                 const InputFile  &input,
                 const double      poissons_ratio)
        : Material(youngs_modulus(prm, input) / (2. * (1. + poissons_ratio)),
                   poissons_ratio)
      {}

      double
      isochoric_energy(const Tensor<2, 3> &F) const override
      {
        return 0.5 * shear_modulus *
               (std::pow(determinant(F), -2. / 3.) * scalar_product(F, F) - 3.);
      }

      Tensor<2, 3>
      isochoric_stress(const Tensor<2, 3> &F) const override
      {
        return HyperelasticParts::isochoric_stress(shear_modulus, F);
      }

      Tensor<4, 3>
      isochoric_tangent(const Tensor<2, 3> &F) const override
      {
        return HyperelasticParts::isochoric_tangent(shear_modulus, F);
      }

    private:
      static double
      youngs_modulus(ParameterHandler &prm, const InputFile &input)
      {
        const double E = prm.get_double("Young's modulus");
        AssertThrow(E > 0,
                    ExcMessage(input.where("Material", "Young's modulus") +
                               ": must be positive (MPa), got " +
                               Utilities::to_string(E) + "."));
        return E;
      }
    };
  } // namespace

  SOFTOPT_REGISTER_MATERIAL(NeoHookean,
                            "neo-Hookean",
                            "G/2 (I1^ - 3) with I1^ = J^{-2/3} tr C (the "
                            "paper's; entry \"Young's modulus\").")
} // namespace softopt
