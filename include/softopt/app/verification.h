#ifndef softopt_app_verification_h
#define softopt_app_verification_h

#include <deal.II/base/conditional_ostream.h>

#include <softopt/app/verification_parameters.h>
#include <softopt/functionals/functional.h>
#include <softopt/path/path_following.h>

#include <string>
#include <vector>

namespace softopt
{
  struct Settings;
  class OutputDirectory;

  /** One mesh of verification.csv: its size, cells and displacement DoFs,
   * and every functional's value at its targets. */
  struct VerificationRow
  {
    double              mesh_size_mm = 0;
    unsigned long       cells        = 0;
    unsigned long       dofs         = 0;
    std::vector<double> values;
  };

  /** Each functional's value on the states @p result reached at its load
   * factors (NaN if the path did not reach one of them). */
  std::vector<double>
  values_at_targets(const HyperelasticProblem             &problem,
                    const DesignConfiguration             &design,
                    const std::vector<const Functional *> &functionals,
                    const PathFollowing::Result           &result);

  /** The element size of the optimization mesh for verification.csv: the
   * Geometry's "Mesh size" for a .geo, else the mean boundary edge length
   * of @p design. Collective. */
  double
  optimization_mesh_size(const Settings &settings, const DesignConfiguration &design);

  /**
   * Verification on finer meshes: the design in @p design_mesh (a mesh
   * written by write_design_mesh()) is meshed anew at each of the
   * settings' "Mesh sizes", from a boundary triangulation refined on its
   * curved P2 surface (remesh_design()), and analyzed along the final
   * analysis's path in verification/<size>mm/. Writes verification.csv in
   * @p out, @p first (the optimization mesh) as its first row, and prints
   * each functional's change against it. Returns false if an analysis
   * failed (its row has the targets it reached).
   */
  bool
  verify_design(const Settings        &settings,
                const std::string     &design_mesh,
                const VerificationRow &first,
                const OutputDirectory &out,
                const ConditionalOStream &pcout);

  /**
   * "softopt verify CASE.prm": verify_design() for the finished run in the
   * case's output directory, without optimizing again. The first row is
   * the run's final analysis of its design (final_analysis/
   * load_path_summary.csv), or an analysis of its design.msh if that did
   * not reach the end of its path (final_analysis/stop_reason.txt), is not
   * newer than parameters.prm and design.msh, or lists other functionals.
   * Returns the exit code.
   */
  int
  run_verification(const Settings &settings, const MPI_Comm comm);
} // namespace softopt

#endif
