#ifndef softopt_app_analysis_h
#define softopt_app_analysis_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <softopt/app/settings.h>
#include <softopt/path/path_following.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

namespace softopt
{
  /**
   * A body to analyze: the mesh @p mesh_file (empty: the settings' Mesh
   * file), its design configuration X = X_o as meshed, and the physics on
   * it, set up. Members in the order they depend on each other.
   */
  struct AnalysisBody
  {
    AnalysisBody(const Settings &settings, const MPI_Comm comm, const std::string &mesh_file = "");

    std::unique_ptr<parallel::fullydistributed::Triangulation<3>> triangulation;
    std::unique_ptr<DesignConfiguration>                          design;
    std::unique_ptr<HyperelasticProblem>                          problem;
  };

  /**
   * "softopt analyze CASE.prm": inflates the body along its load path and
   * writes, in the output directory, load_path.csv (one row per converged
   * step), solution.pvd with its VTU files, the expanded parameter file,
   * stop_reason.txt and, with "Tracked points", tracked_points.csv.
   * Returns the exit code: non-zero if a load step could not be solved.
   */
  int
  run_analysis(const Settings &settings, const MPI_Comm comm);

  /**
   * Follows the load path of @p settings on @p design, landing on every
   * load factor of @p targets, and writes into
   * @p directory load_path.csv (cavity volume, design-surface means and
   * every functional of @p functionals per converged step), solution.pvd
   * with its VTU files, stop_reason.txt and, if the settings name tracked
   * points, tracked_points.csv (their displacements per converged step).
   * Shared by "analyze" and the final analysis of "optimize".
   */
  PathFollowing::Result
  follow_load_path(HyperelasticProblem                   &problem,
                   const DesignConfiguration             &design,
                   const Settings                        &settings,
                   const std::vector<const Functional *> &functionals,
                   const std::vector<double>             &targets,
                   const std::string                     &directory,
                   const ConditionalOStream              &pcout);
} // namespace softopt

#endif
