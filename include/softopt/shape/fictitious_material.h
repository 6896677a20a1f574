#ifndef softopt_shape_fictitious_material_h
#define softopt_shape_fictitious_material_h

#include <softopt/physics/hyperelastic_parts.h>

namespace softopt
{
  /**
   * The fictitious energy of the shape filter (Eq. Wshape, after Dahlberg et
   * al. 2025):
   *   W_psi = K_psi/2 (1/k_psi (e^{k_psi (J - 1)} - 1) - ln J)
   *         + G_psi/2 (J^{-2/3} tr C - 3),
   * in mm^-1 (K_psi, G_psi) with k_psi dimensionless. The exponential term
   * stiffens compression and the logarithm keeps J > 0.
   */
  class FictitiousMaterial
  {
  public:
    FictitiousMaterial(const double K, const double G, const double k)
      : K(K)
      , G(G)
      , k(k)
    {}

    template <typename Number>
    Number
    energy(const Tensor<2, 3, Number> &F) const
    {
      using std::exp;
      using std::log;
      using std::pow;
      const Number J = determinant(F);
      return 0.5 * K * ((exp(k * (J - 1.)) - 1.) / k - log(J)) +
             0.5 * G * (pow(J, -2. / 3.) * scalar_product(F, F) - 3.);
    }

    /** P = dW_psi/dF: the isochoric part and U'(J) = K/2 (e^{k(J-1)} - 1/J). */
    template <typename Number>
    Tensor<2, 3, Number>
    first_piola(const Tensor<2, 3, Number> &F) const
    {
      using std::exp;
      const Number J     = determinant(F);
      const Number dU_dJ = 0.5 * K * (exp(k * (J - 1.)) - 1. / J);
      return HyperelasticParts::isochoric_stress(G, F) +
             HyperelasticParts::volumetric_stress(dU_dJ, F);
    }

    /** A = dP/dF, with U''(J) = K/2 (k e^{k(J-1)} + 1/J^2). */
    Tensor<4, 3>
    tangent(const Tensor<2, 3> &F) const
    {
      const double J = determinant(F);
      const double e = std::exp(k * (J - 1.));
      return HyperelasticParts::isochoric_tangent(G, F) +
             HyperelasticParts::volumetric_tangent(0.5 * K * (e - 1. / J),
                                                   0.5 * K * (k * e + 1. / (J * J)),
                                                   F);
    }

  private:
    const double K, G, k;
  };
} // namespace softopt

#endif
