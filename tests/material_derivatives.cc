// Every material model in its mixed form: the stress P = dW~/dF and the
// tangent A = dP/dF against central finite differences, and dW~/dp~ against
// the pressure equation, at a few deformations with J far from and close
// to 1; and Hooke's law at small strain with the model's G_0 and K.
// A new model is added to the list in main().

#include <softopt/physics/hyperelastic_parts.h>
#include <softopt/physics/material.h>

#include "tests.h"

using namespace softopt_tests;

void
check(const softopt::Material &material)
{
  for (unsigned int sample = 0; sample < 4; ++sample)
    {
      Tensor<2, 3> F;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          F[i][j] = (i == j ? 1. : 0.) + 0.3 * (sample + 1) / 4. *
                                           random(3 * i + j, sample);
      const double p = 0.1 * random(100, sample);
      const double h = 1e-6;

      double P_error = 0, P_norm = 0, A_error = 0, A_norm = 0;
      const Tensor<2, 3> P = material.first_piola(F, p);
      const Tensor<4, 3> A = material.tangent(F, p);
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = 0; l < 3; ++l)
          {
            Tensor<2, 3> dF;
            dF[k][l] = h;
            const double dW = (material.energy(F + dF, p) -
                               material.energy(F - dF, p)) / (2 * h);
            P_error = std::max(P_error, std::abs(dW - P[k][l]));
            P_norm  = std::max(P_norm, std::abs(P[k][l]));
            const Tensor<2, 3> dP = (material.first_piola(F + dF, p) -
                                     material.first_piola(F - dF, p)) / (2 * h);
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                {
                  A_error = std::max(A_error, std::abs(dP[i][j] - A[i][j][k][l]));
                  A_norm  = std::max(A_norm, std::abs(A[i][j][k][l]));
                }
          }
      // dW~/dp~ = -(J - 1) - p~/K, and dP/dp~ = -J F^{-T}.
      const double dWdp = (material.energy(F, p + h) - material.energy(F, p - h)) /
                          (2 * h);
      const double J = determinant(F);
      const double pressure_error =
        std::abs(dWdp - (-(J - 1.) - p / material.bulk_modulus));
      const Tensor<2, 3> dPdp = (material.first_piola(F, p + h) -
                                 material.first_piola(F, p - h)) / (2 * h);
      const double coupling_error =
        (dPdp - material.pressure_coupling(F)).norm() / dPdp.norm();

      deallog << "J = " << J << ": relative error of P " << below(P_error / P_norm, 1e-8)
              << ", of A " << below(A_error / A_norm, 1e-8) << ", of dW/dp "
              << below(pressure_error, 1e-10) << ", of dP/dp "
              << below(coupling_error, 1e-10) << std::endl;
    }

  // At small strain the law reduces to Hooke's, sigma = 2G eps + lambda
  // tr(eps) I, with p~ = -K tr(eps) from the pressure equation.
  const double eps = 1e-7;
  Tensor<2, 3> F   = unit_symmetric_tensor<3>();
  F[0][0] += eps;
  const double       p     = -material.bulk_modulus * eps;
  const Tensor<2, 3> sigma = material.cauchy_stress(F, p);
  const double lame = material.bulk_modulus - 2. / 3. * material.shear_modulus;
  deallog << "uniaxial strain: sigma_xx / eps = " << sigma[0][0] / eps
          << " (expected " << 2 * material.shear_modulus + lame
          << "), sigma_yy / eps = " << sigma[1][1] / eps << " (expected "
          << lame << ")" << std::endl;
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  deallog << "neo-Hookean, E = 1.2, nu = 0.49" << std::endl;
  check(*neo_hookean(1.2, 0.49));
  deallog << "Yeoh, C = (0.2, 0.05, 0.01), nu = 0.49" << std::endl;
  check(*yeoh("0.2, 0.05, 0.01", 0.49));

  // J - 1 from the invariants of H keeps its digits where det(F) - 1 cannot.
  Tensor<2, 3> H;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      H[i][j] = 1e-7 * random(3 * i + j, 7);
  // The reference in long double (64-bit mantissa: good to about 1e-12 of
  // J - 1 here; det(F) - 1 in double keeps only about 1e-9).
  long double L[3][3];
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      L[i][j] = (i == j ? 1.L : 0.L) + static_cast<long double>(H[i][j]);
  const double exact =
    static_cast<double>(L[0][0] * (L[1][1] * L[2][2] - L[1][2] * L[2][1]) -
                        L[0][1] * (L[1][0] * L[2][2] - L[1][2] * L[2][0]) +
                        L[0][2] * (L[1][0] * L[2][1] - L[1][1] * L[2][0]) - 1.L);
  const double naive = determinant(unit_symmetric_tensor<3>() + H) - 1;
  const auto relative = [&](const double value) {
    return std::abs(value - exact) < 1e-11 * std::abs(exact) ? "below 1e-11" :
                                                               "above 1e-11";
  };
  deallog << "|H| = 1e-7: relative error of jacobian_minus_one "
          << relative(softopt::jacobian_minus_one(H)) << ", of det(F) - 1 "
          << relative(naive) << std::endl;
}
