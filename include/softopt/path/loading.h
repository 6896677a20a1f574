#ifndef softopt_path_loading_h
#define softopt_path_loading_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/path/path_following.h>

#include <vector>

namespace softopt
{
  /**
   * Subsection "Loading": the cavity pressure at load factor 1, the load
   * factors where a state is needed, when a load path stops, and how it is
   * followed (PathFollowing declares and reads its own entries here).
   */
  struct Loading
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    /** Cavity pressure at load factor 1, in kPa. */
    double pressure_kPa = 15;

    /** Load factors at which a converged state is required. */
    std::vector<double> target_load_factors{1.};

    /** Stop once V_c / V_0 of the cavity exceeds this (0: no limit). */
    double maximum_volume_ratio = 0;

    /** Load control or arclength, and its step sizes. */
    PathFollowing::Parameters path;
  };
} // namespace softopt

#endif
