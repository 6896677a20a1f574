// A volume quantity: a smooth maximum of the stretch over the body.

#include <deal.II/base/mpi.h>

#include <softopt/functionals/quantity.h>
#include <softopt/physics/nodal_ad.h>
#include <softopt/shape/mesh_loops.h>

#include <cmath>

namespace softopt
{
  namespace
  {
    using namespace NodalAD;

    /**
     * Q = (1/|Omega| int_Omega s^k dV)^(1/k) with the isochoric stretch
     * s = sqrt(I1_bar / 3), I1_bar = J^(-2/3) tr(F^T F), in the design
     * configuration: 1 at rest, sqrt((l^2 + 2/l)/3) in uniaxial stretch l,
     * and tending to max s as the exponent k grows (the p-norm). As a
     * constraint, Q <= Tolerance keeps the elastomer below a stretch at
     * which it tears.
     */
    class MaximumStretch : public Quantity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Exponent",
                          "8",
                          Patterns::Double(1),
                          "maximum stretch: the exponent k of the p-norm "
                          "(dimensionless; larger values come closer to the "
                          "largest stretch and are less smooth).");
      }

      MaximumStretch(ParameterHandler &prm,
                     const InputFile &,
                     const std::string &,
                     const double load_factor)
        : Quantity({load_factor})
        , exponent(prm.get_double("Exponent"))
      {}

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States              &states,
            Derivatives               *derivatives) const override
      {
        const ReferenceTetrahedron reference(problem.cell_quadrature(),
                                             problem.face_quadrature());
        const auto  a = problem.ghosted(*states[0]);
        const auto &X = design.positions();
        Vector      dI_du, dI_dX, dV_dX;
        if (derivatives != nullptr)
          {
            dI_du = problem.create_vector();
            dI_dX = design.create_vector();
            dV_dX = design.create_vector();
          }
        // I = int s^k dV and V = int dV, each cell with AD in (u, X).
        double I = 0, V = 0;
        for_each_cell(problem, design, [&](const CellNodes &nodes) {
          const Nodes<AD> u = independent(nodes.displacement(a), 60, 0);
          const Nodes<AD> Xe = independent(nodes.design(X), 60, 30);
          AD              I_e = 0, V_e = 0;
          for (const auto &point : reference.cell_points)
            {
              const Tensor<2, 3, AD> dX_dxi = jacobian(point, Xe);
              const AD               dV     = determinant(dX_dxi) * point.weight;
              const Tensor<2, 3, AD> inverse = invert(dX_dxi);
              Tensor<2, 3, AD>       F;
              for (unsigned int i = 0; i < 3; ++i)
                F[i][i] = 1.;
              for (unsigned int n = 0; n < 10; ++n)
                {
                  const Tensor<1, 3, AD> grad_N = transpose(inverse) * point.gradients[n];
                  F += outer_product(u[n], grad_N);
                }
              const AD I1_bar = trace(transpose(F) * F) * pow(determinant(F), -2. / 3.);
              I_e += pow(I1_bar / 3., exponent / 2.) * dV;
              V_e += dV;
            }
          I += I_e.val();
          V += V_e.val();
          if (derivatives == nullptr)
            return;
          nodes.add_to_displacement(NodalAD::derivatives(I_e, 0), dI_du);
          nodes.add_to_design(NodalAD::derivatives(I_e, 30), dI_dX);
          nodes.add_to_design(NodalAD::derivatives(V_e, 30), dV_dX);
        });
        const MPI_Comm comm = problem.get_communicator();
        I                   = Utilities::MPI::sum(I, comm);
        V                   = Utilities::MPI::sum(V, comm);
        const double Q      = std::pow(I / V, 1. / exponent);
        if (derivatives != nullptr)
          {
            // dQ = Q/k (dI/I - dV/V)
            for (auto *w : {&dI_du, &dI_dX, &dV_dX})
              w->compress(VectorOperation::add);
            derivatives->d_da = {dI_du};
            derivatives->d_da[0] *= Q / (exponent * I);
            derivatives->d_dX = dI_dX;
            derivatives->d_dX *= Q / (exponent * I);
            derivatives->d_dX.add(-Q / (exponent * V), dV_dX);
          }
        return Q;
      }

    private:
      const double exponent;
    };
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(MaximumStretch,
                            "maximum stretch",
                            "a p-norm over the body of the isochoric stretch "
                            "sqrt(I1_bar / 3), 1 at rest (dimensionless; "
                            "\"Exponent\" k).")
} // namespace softopt
