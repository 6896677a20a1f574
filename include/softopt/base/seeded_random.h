#ifndef softopt_base_seeded_random_h
#define softopt_base_seeded_random_h

#include <cmath>

namespace softopt
{
  /** A reproducible pseudo-random number in [-1, 1] for a global index @p i
   * (a design variable, a DoF), the same on any number of MPI ranks: the
   * random directions of gradient checks. */
  inline double
  seeded_random(const unsigned long i, const unsigned int seed = 1)
  {
    const double x = std::sin(12.9898 * (i + 1) + 78.233 * seed) * 43758.5453;
    return 2. * (x - std::floor(x)) - 1.;
  }
} // namespace softopt

#endif
