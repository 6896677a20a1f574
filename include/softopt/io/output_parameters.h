#ifndef softopt_io_output_parameters_h
#define softopt_io_output_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>

#include <vector>

namespace softopt
{
  /** What a run writes besides its results (subsection "Output" and the
   * top-level "Print timings"). */
  struct OutputParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    /** Wall times at the end of a run (off in tests). */
    bool print_timings = true;

    /** Which converged states of a load path go to VTU files. */
    enum class VtuOutput
    {
      every_step,
      targets,
      none
    } vtu_output = VtuOutput::every_step;

    /** The surface points whose displacement history goes to
     * tracked_points.csv (none: no file). */
    std::vector<NamedPoint> tracked_points;

    /** Whether a load path writes its deformed surface at each target as
     * deformed_<p>kPa.stl. */
    bool deformed_stl = false;

    /** Whether a load path writes each state's lowest eigenvalue of the
     * tangent, relative to that at rest (load_path.csv's "stability"). */
    bool stability = false;
  };
} // namespace softopt

#endif
