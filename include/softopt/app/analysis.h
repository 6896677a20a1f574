#ifndef softopt_app_analysis_h
#define softopt_app_analysis_h

#include <softopt/app/settings.h>

namespace softopt
{
  /**
   * "softopt analyze CASE.prm": inflates the body along its load path and
   * writes, in the output directory, load_path.csv (one row per converged
   * step), solution.pvd with its VTU files, the expanded parameter file and
   * stop_reason.txt. Returns the exit code: non-zero if a load step could
   * not be solved.
   */
  int
  run_analysis(Settings &settings);
} // namespace softopt

#endif
