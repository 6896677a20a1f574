#ifndef softopt_base_step_failure_h
#define softopt_base_step_failure_h

#include <stdexcept>
#include <string>

namespace softopt
{
  /**
   * A failure that a smaller load step may cure: an inverted element
   * (J <= 0 at a quadrature point), a singular or failed factorization, a NaN,
   * or a Newton iteration that diverges. Path following catches it and cuts
   * the step back; anything else is a real error. Thrown on every MPI rank
   * alike (the conditions are reduced over all ranks first).
   */
  class StepFailure : public std::runtime_error
  {
  public:
    explicit StepFailure(const std::string &what)
      : std::runtime_error(what)
    {}
  };
} // namespace softopt

#endif
