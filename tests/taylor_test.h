#ifndef softopt_tests_taylor_test_h
#define softopt_tests_taylor_test_h

#include <softopt/optimization/design_problem.h>

#include "tests.h"

#include <cmath>
#include <iomanip>

namespace softopt_tests
{
  /**
   * The Taylor test of the adjoint gradients of every functional of
   * @p problem at the design @p x (evaluated, with @p values and
   * @p gradients there): the remainder |g(d + h s e) - g(d) - h s grad g . e|
   * along the seeded random direction e (seed @p seed) for h = @p steps
   * (default 1e-1 ... 1e-4) times @p scale (mm) must fall as h^2. Prints per functional its value
   * and the rates with the verdict "(all >= 1.9)". Leaves @p x at the last
   * design evaluated.
   */
  inline void
  taylor_test(softopt::DesignProblem                           &problem,
              softopt::DesignIterate                           &x,
              const std::vector<double>                        &values,
              const std::vector<softopt::DesignProblem::Vector> &gradients,
              const double                                      scale,
              const unsigned int                                seed,
              const std::vector<double> &steps = {1e-1, 1e-2, 1e-3, 1e-4})
  {
    const auto &functionals = problem.functionals();
    auto        direction   = problem.create_design_vector();
    for (const auto i : direction.locally_owned_elements())
      direction(i) = random(i, seed);
    direction.compress(VectorOperation::insert);

    const auto                       d0 = x.d;
    std::vector<std::vector<double>> taylor(functionals.size());
    for (const double h : steps)
      {
        x.d = d0;
        x.d.add(h * scale, direction);
        const auto at = problem.evaluate(x);
        for (unsigned int k = 0; k < functionals.size(); ++k)
          taylor[k].push_back(
            std::abs(at[k] - values[k] - h * scale * (gradients[k] * direction)));
      }
    for (unsigned int k = 0; k < functionals.size(); ++k)
      {
        deallog << functionals[k]->name() << " = " << values[k] << ": rates";
        bool pass = true;
        for (unsigned int i = 0; i + 1 < steps.size(); ++i)
          {
            const double rate =
              std::log(taylor[k][i] / taylor[k][i + 1]) / std::log(steps[i] / steps[i + 1]);
            pass &= rate >= 1.9;
            deallog << " " << std::fixed << std::setprecision(1) << rate;
          }
        deallog << std::defaultfloat << std::setprecision(8)
                << (pass ? " (all >= 1.9)" : " (BELOW 1.9)") << std::endl;
      }
  }
} // namespace softopt_tests

#endif
