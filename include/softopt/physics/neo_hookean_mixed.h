#ifndef softopt_physics_neo_hookean_mixed_h
#define softopt_physics_neo_hookean_mixed_h

#include <deal.II/base/tensor.h>

#include <softopt/physics/hyperelastic_parts.h>

#include <cmath>

namespace softopt
{
  using namespace dealii;

  /**
   * The nearly incompressible neo-Hookean material in the mixed form of
   * Sussman and Bathe (Eqs. c1, Wmod, p). With p = -K (J - 1) inserted,
   * Eq. Wmod,
   *   W~(F, p~) = W(F) - (p - p~)^2 / (2K),
   * simplifies to
   *   W~(F, p~) = G/2 (J^{-2/3} tr C - 3) - p~ (J - 1) - p~^2 / (2K),
   * so p~ is the pressure (positive in compression) and dW~/dp~ = 0 is the
   * weak pressure equation of Eq. deltaW01. Units: MPa.
   */
  class NeoHookeanMixed
  {
  public:
    /** E in MPa, nu in (-1, 0.5). */
    NeoHookeanMixed(const double youngs_modulus, const double poissons_ratio)
      : shear_modulus(youngs_modulus / (2. * (1. + poissons_ratio)))
      , bulk_modulus(youngs_modulus / (3. * (1. - 2. * poissons_ratio)))
    {}

    /** G = E / (2 (1 + nu)). */
    const double shear_modulus;

    /** K = E / (3 (1 - 2 nu)). */
    const double bulk_modulus;

    /** W~(F, p~) in MPa (energy per unit reference volume). */
    template <typename Number>
    Number
    energy(const Tensor<2, 3, Number> &F, const Number &p) const
    {
      using std::pow;
      const Number J  = determinant(F);
      const Number I1 = scalar_product(F, F);
      return 0.5 * shear_modulus * (pow(J, -2. / 3.) * I1 - 3.) -
             p * (J - 1.) - p * p / (2. * bulk_modulus);
    }

    /**
     * The first Piola-Kirchhoff stress P = dW~/dF = F S~ in MPa:
     *   P = G J^{-2/3} (F - tr C / 3 F^{-T}) - p~ J F^{-T},
     * the isochoric part and a volumetric part with U'(J) = -p~.
     */
    template <typename Number>
    Tensor<2, 3, Number>
    first_piola(const Tensor<2, 3, Number> &F, const Number &p) const
    {
      const Number minus_p = -p;
      return HyperelasticParts::isochoric_stress(shear_modulus, F) +
             HyperelasticParts::volumetric_stress(minus_p, F);
    }

    /**
     * The tangent A = dP/dF (material and geometric stiffness together,
     * the B^T D B + G^T Y G of Eq. LinMat), A[i][J][k][L] = dP_iJ / dF_kL.
     */
    Tensor<4, 3>
    tangent(const Tensor<2, 3> &F, const double p) const
    {
      return HyperelasticParts::isochoric_tangent(shear_modulus, F) +
             HyperelasticParts::volumetric_tangent(-p, 0., F);
    }

    /** dP/dp~ = -J F^{-T}: the coupling K_up of Eq. LinMat. */
    Tensor<2, 3>
    pressure_coupling(const Tensor<2, 3> &F) const
    {
      return -determinant(F) * transpose(invert(F));
    }

    /** The Cauchy stress sigma = P F^T / J in MPa. */
    Tensor<2, 3>
    cauchy_stress(const Tensor<2, 3> &F, const double p) const
    {
      return first_piola(F, p) * transpose(F) / determinant(F);
    }
  };
} // namespace softopt

#endif
