#ifndef softopt_physics_hyperelastic_parts_h
#define softopt_physics_hyperelastic_parts_h

#include <deal.II/base/tensor.h>

#include <cmath>

namespace softopt
{
  using namespace dealii;

  /**
   * The two parts every energy of this code is made of, with their first
   * Piola stresses and tangents A = dP/dF (A[i][J][k][L] = dP_iJ/dF_kL):
   * the isochoric neo-Hookean part G/2 (J^{-2/3} tr C - 3), and a
   * volumetric part U(J) given by U'(J) and U''(J). Templated on the number
   * type so that automatic differentiation can run through the stresses;
   * scalar expressions are stored in Number first (Sacado's expression
   * templates do not multiply tensors).
   */
  namespace HyperelasticParts
  {
    /** J - 1 = det(I + H) - 1 from the invariants of the displacement
     * gradient H, tr H + ((tr H)^2 - tr H^2)/2 + det H, without the
     * cancellation of det(F) - 1 (at |H| = 1e-7 that keeps 9 digits, and the
     * pressure equation multiplies it by K >> G). */
    template <typename Number>
    Number
    jacobian_minus_one(const Tensor<2, 3, Number> &H)
    {
      const Number trace = H[0][0] + H[1][1] + H[2][2];
      const Number square = scalar_product(H, transpose(H));
      const Number det    = determinant(H);
      return trace + 0.5 * (trace * trace - square) + det;
    }

    /** d/dF of G/2 (J^{-2/3} tr C - 3): G J^{-2/3} (F - tr C/3 F^{-T}). */
    template <typename Number>
    Tensor<2, 3, Number>
    isochoric_stress(const double G, const Tensor<2, 3, Number> &F)
    {
      using std::pow;
      const Number               J       = determinant(F);
      const Number               g       = G * pow(J, -2. / 3.);
      const Number               third   = scalar_product(F, F) / 3.;
      const Tensor<2, 3, Number> F_inv_T = transpose(invert(F));
      return g * (F - third * F_inv_T);
    }

    /** d/dF of U(J): U'(J) J F^{-T}. */
    template <typename Number>
    Tensor<2, 3, Number>
    volumetric_stress(const Number &dU_dJ, const Tensor<2, 3, Number> &F)
    {
      const Number factor = dU_dJ * determinant(F);
      return factor * transpose(invert(F));
    }

    /** The tangent of isochoric_stress(). */
    inline Tensor<4, 3>
    isochoric_tangent(const double G, const Tensor<2, 3> &F)
    {
      const double       J     = determinant(F);
      const Tensor<2, 3> F_inv = invert(F);
      const double       I1    = scalar_product(F, F);
      const double       g     = G * std::pow(J, -2. / 3.);
      Tensor<4, 3>       A;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              A[i][j][k][l] =
                g * ((i == k && j == l ? 1. : 0.) -
                     2. / 3. * (F_inv[l][k] * F[i][j] + F[k][l] * F_inv[j][i]) +
                     2. / 9. * I1 * F_inv[l][k] * F_inv[j][i] +
                     I1 / 3. * F_inv[j][k] * F_inv[l][i]);
      return A;
    }

    /** The tangent of volumetric_stress():
     * U'' J^2 F^{-T} (x) F^{-T} + U' J (F^{-T} (x) F^{-T} - F^{-T} [x] F^{-1}). */
    inline Tensor<4, 3>
    volumetric_tangent(const double        dU_dJ,
                       const double        d2U_dJ2,
                       const Tensor<2, 3> &F)
    {
      const double       J     = determinant(F);
      const Tensor<2, 3> F_inv = invert(F);
      Tensor<4, 3>       A;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              A[i][j][k][l] =
                d2U_dJ2 * J * J * F_inv[j][i] * F_inv[l][k] +
                dU_dJ * J *
                  (F_inv[j][i] * F_inv[l][k] - F_inv[j][k] * F_inv[l][i]);
      return A;
    }
  } // namespace HyperelasticParts

  using HyperelasticParts::jacobian_minus_one;
} // namespace softopt

#endif
