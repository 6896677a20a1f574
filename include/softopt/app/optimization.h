#ifndef softopt_app_optimization_h
#define softopt_app_optimization_h

#include <softopt/app/settings.h>

namespace softopt
{
  /** How "optimize" starts: in a folder without an earlier run, from its
   * last checkpoint (--restart), or after removing it (--start-over). */
  enum class Start
  {
    fresh,
    restart,
    start_over
  };

  /**
   * "softopt optimize CASE.prm [--restart | --start-over]": the design loop, then what a
   * designer takes away, in the output directory: history.csv, design.stl
   * (the optimized body, watertight, mm), VTU/PVD snapshots, the forward
   * analysis of the final design in final_analysis/ (load_path.csv as from
   * "analyze"), and PNG plots when python3-matplotlib is installed.
   * Returns the exit code.
   */
  int
  run_optimization(const Settings &settings, const Start start, const MPI_Comm comm);
} // namespace softopt

#endif
