// How far the pressure-volume curve has bent over at its target: a
// constraint that keeps a pressure maximum (a snap-through) away from the
// target pressure without locating it.

#include <softopt/base/step_failure.h>
#include <softopt/functionals/design_surface.h>
#include <softopt/functionals/quantity.h>

namespace softopt
{
  namespace
  {
    /**
     * The cavity's compliance over the top of the load path relative to its
     * mean compliance from rest,
     *
     *   Q = [dV(l) - dV(l_0)] / (l - l_0)  /  [dV(l) / l],  dV = V_c - V_c(rest),
     *
     * with l the subsection's "Load factor" and l_0 its "Lower load factor"
     * (pressure is proportional to l). Q = 1 for a linear response, Q > 1
     * where the curve softens. Towards a pressure maximum dV grows like the
     * square root of the pressure's distance to it, so Q rises steeply but
     * stays finite: for an incompressible neo-Hookean sphere with A/B = 1/2
     * and l_0 = 0.9 l, Q = 1.5, 2.0, 3.0 and 4.3 at 0.5, 0.7, 0.9 and 0.98 of
     * the maximum pressure (doc/theory.md). As a constraint Q <= Tolerance
     * the optimizer sees the snap coming and stays below it, where "Limit
     * point below a target = refuse" only refuses the step that crossed it.
     */
    class ComplianceRatio : public Quantity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Lower load factor",
                          "0.9",
                          Patterns::Double(0),
                          "compliance ratio: the load factor l_0 below "
                          "\"Load factor\" from which the compliance at the "
                          "top of the load path is measured (a target state "
                          "of its own: one more Newton solve and adjoint per "
                          "design).");
      }

      ComplianceRatio(ParameterHandler  &prm,
                      const InputFile   &input,
                      const std::string &subsection,
                      const double       load_factor)
        : Quantity({prm.get_double("Lower load factor"), load_factor})
      {
        const double lower = load_factors()[0];
        AssertThrow(lower > 0 && lower < load_factor,
                    ExcMessage(input.where(subsection, "Lower load factor") +
                               ": must lie between 0 and \"Load factor\" (" +
                               std::to_string(load_factor) + "), not " +
                               std::to_string(lower) + "."));
      }

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States              &states,
            Derivatives               *derivatives) const override
      {
        const double l_0 = load_factors()[0], l = load_factors()[1];
        const double c   = l / (l - l_0);
        const Vector rest = problem.create_vector();
        // Q = c A / B with A = V_1 - V_0, B = V_1 - V_r: the chain rule
        // through the three volumes, each a function of x = X + u.
        Vector dVr_dX, dV0_dX, dV1_dX;
        if (derivatives != nullptr)
          derivatives->d_da.resize(2);
        const auto d_da = [&](const unsigned int i) {
          return derivatives ? &derivatives->d_da[i] : nullptr;
        };
        const auto d_dX = [&](Vector &v) { return derivatives ? &v : nullptr; };
        const double V_r = cavity_volume(problem, design, rest, nullptr, d_dX(dVr_dX));
        const double V_0 = cavity_volume(problem, design, *states[0], d_da(0), d_dX(dV0_dX));
        const double V_1 = cavity_volume(problem, design, *states[1], d_da(1), d_dX(dV1_dX));
        const double A = V_1 - V_0, B = V_1 - V_r;
        // A design whose cavity shrinks under pressure has no such ratio:
        // refused like an inverted one.
        if (!(B > 0))
          throw StepFailure("compliance ratio: the cavity did not grow under "
                            "pressure (dV = " + std::to_string(B) + " mm^3).");
        if (derivatives == nullptr)
          return c * A / B;
        const double dQ_dV0 = -c / B;
        const double dQ_dV1 = c * (V_0 - V_r) / (B * B);
        const double dQ_dVr = c * A / (B * B);
        derivatives->d_da[0] *= dQ_dV0;
        derivatives->d_da[1] *= dQ_dV1;
        derivatives->d_dX = dV1_dX;
        derivatives->d_dX *= dQ_dV1;
        derivatives->d_dX.add(dQ_dV0, dV0_dX, dQ_dVr, dVr_dX);
        return c * A / B;
      }
    };
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(ComplianceRatio,
                            "compliance ratio",
                            "the cavity's compliance dV/dp between \"Lower load "
                            "factor\" and \"Load factor\" over its mean from "
                            "rest (dimensionless; 1 for a linear response, "
                            "rising towards a pressure maximum).")
} // namespace softopt
