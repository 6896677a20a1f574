#ifndef softopt_app_mold_h
#define softopt_app_mold_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/shape/mold.h>

#include <mpi.h>

namespace softopt
{
  struct Settings;

  /** subsection "Mold": the dimensions of the mold parts. */
  struct MoldParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    MoldDimensions dimensions;
  };

  /**
   * "softopt mold CASE.prm": the mold parts (make_mold()) of the design
   * check-design would check (the run's design.msh, else the case's mesh),
   * as binary STL files in mm in the folder mold/ of the output directory,
   * with parts.csv (volume of each part, closed, manifold) and undercuts.csv
   * (rows like castability.csv's). A design whose surface intersects
   * itself or whose walls are thinner than Castability / Minimum wall
   * thickness gets a message naming the place and a non-zero exit, and an
   * earlier mold/ is left as it was: the parts are written aside and
   * renamed. Returns the exit code.
   */
  int
  run_mold(const Settings &settings, const MPI_Comm comm);
} // namespace softopt

#endif
