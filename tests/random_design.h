// A design of the small design problem (inputs/sphere_design.prm) away from
// its initial one, for tests of what happens to a design: d = s r with r
// pseudo-random per DoF and s 0.3 of the design bound.
#ifndef softopt_tests_random_design_h
#define softopt_tests_random_design_h

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "tests.h"

namespace softopt_tests
{
  /** The initial iterate of @p problem with d = 0.3 (design bound) r. */
  inline softopt::DesignIterate
  random_design(const softopt::DesignProblem &problem, const softopt::Settings &settings)
  {
    softopt::DesignIterate x = problem.initial_iterate();
    for (const auto i : x.d.locally_owned_elements())
      x.d(i) = 0.3 * settings.optimization.design_bound * random(i, 5);
    x.d.compress(VectorOperation::insert);
    return x;
  }
} // namespace softopt_tests

#endif
