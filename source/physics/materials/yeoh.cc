// A material model is one file like this one: a class deriving from
// Material with the isochoric energy, its stress and its tangent, a static
// declare_parameters() and a constructor reading the entries (in subsection
// Material), and the registration line at the bottom. Copy it, rename the
// class and the entry, change the three functions of W_iso, add the model to
// the loop in tests/material_derivatives.cc and run that test: it checks the
// stress and tangent against finite differences.
//
// The Yeoh model, W_iso = sum_i C_i0 (I1^ - 3)^i, is common for silicone
// elastomers (Ecoflex, Dragon Skin) at the large strains of soft actuators.
// Every model that depends on I1^ = J^{-2/3} tr C only has
//   dW/dF     = W'(I1^) dI1^/dF,
//   d2W/dF2   = W''(I1^) dI1^/dF (x) dI1^/dF + W'(I1^) d2I1^/dF2,
// and dI1^/dF, d2I1^/dF2 are the neo-Hookean stress and tangent with G = 2.

#include <deal.II/base/utilities.h>

#include <softopt/physics/hyperelastic_parts.h>
#include <softopt/physics/material.h>

namespace softopt
{
  namespace
  {
    class Yeoh : public Material
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Yeoh coefficients",
                          "0.2, 0.01, 0",
                          Patterns::List(Patterns::Double(), 1),
                          "Yeoh: C_10, C_20, C_30, ... in MPa (as many as "
                          "given), W_iso = sum_i C_i0 (I1^ - 3)^i; G_0 = "
                          "2 C_10 > 0.");
      }

      Yeoh(ParameterHandler &prm,
           const InputFile  &input,
           const double      poissons_ratio)
        : Material(2. * first_coefficient(prm, input), poissons_ratio)
        , C(parse_doubles(prm.get("Yeoh coefficients"),
                          input.where("Material", "Yeoh coefficients")))
      {}

      double
      isochoric_energy(const Tensor<2, 3> &F) const override
      {
        const double x = invariant(F) - 3.;
        double       W = 0, power = 1;
        for (const double c : C)
          W += c * (power *= x);
        return W;
      }

      Tensor<2, 3>
      isochoric_stress(const Tensor<2, 3> &F) const override
      {
        return derivative(F, 1) * HyperelasticParts::isochoric_stress(2., F);
      }

      Tensor<4, 3>
      isochoric_tangent(const Tensor<2, 3> &F) const override
      {
        const Tensor<2, 3> dI = HyperelasticParts::isochoric_stress(2., F);
        return derivative(F, 2) * outer_product(dI, dI) +
               derivative(F, 1) * HyperelasticParts::isochoric_tangent(2., F);
      }

    private:
      /** C_10, C_20, ... */
      const std::vector<double> C;

      /** I1^ = J^{-2/3} tr C. */
      static double
      invariant(const Tensor<2, 3> &F)
      {
        return std::pow(determinant(F), -2. / 3.) * scalar_product(F, F);
      }

      /** The n-th derivative of W_iso in I1^ (n = 1, 2). */
      double
      derivative(const Tensor<2, 3> &F, const unsigned int n) const
      {
        const double x = invariant(F) - 3.;
        double       W = 0;
        for (unsigned int i = n; i <= C.size(); ++i)
          {
            double factor = C[i - 1];
            for (unsigned int k = 0; k < n; ++k)
              factor *= i - k;
            W += factor * std::pow(x, static_cast<int>(i - n));
          }
        return W;
      }

      static double
      first_coefficient(ParameterHandler &prm, const InputFile &input)
      {
        const std::string where = input.where("Material", "Yeoh coefficients");
        const double C10 = parse_doubles(prm.get("Yeoh coefficients"), where)[0];
        AssertThrow(C10 > 0,
                    ExcMessage(where + ": C_10 must be positive (the shear "
                               "modulus at small strain is 2 C_10), got " +
                               Utilities::to_string(C10) + "."));
        return C10;
      }
    };
  } // namespace

  SOFTOPT_REGISTER_MATERIAL(Yeoh,
                            "Yeoh",
                            "sum_i C_i0 (I1^ - 3)^i (entry \"Yeoh "
                            "coefficients\").")
} // namespace softopt
