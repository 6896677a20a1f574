#ifndef softopt_optimization_shape_optimizer_h
#define softopt_optimization_shape_optimizer_h

#include <deal.II/base/conditional_ostream.h>

#include <softopt/io/csv_writer.h>
#include <softopt/io/output_directory.h>
#include <softopt/io/output_parameters.h>
#include <softopt/io/pvd_series.h>
#include <softopt/optimization/design_iterate.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/optimization/optimization_parameters.h>

#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * The design loop of Section 6 (problem opt): MMA in min-max form,
   *   minimize z  subject to  g_i(d) - z <= 0,  f_j(d) <= 0,  |d| <= d_max,
   * with the equilibrium of the physics and of the shape filter solved for
   * every design (staggered), and a mesh update X_o <- X_o + psi, d <- 0
   * every "Mesh update interval" iterations. The state of the run is one
   * DesignIterate; undo and checkpoints copy or write it whole. Writes
   * history.csv (one row per iteration), VTU snapshots and checkpoints into
   * the output directory.
   */
  class ShapeOptimizer
  {
  public:
    using Vector = DesignProblem::Vector;

    ShapeOptimizer(const OptimizationParameters &parameters,
                   const OutputParameters       &output,
                   DesignProblem                &problem,
                   const OutputDirectory        &out);

    /** Detaches paths.log from the problem. */
    ~ShapeOptimizer();

    /** The loop from the design at rest, or from the checkpoint with
     * @p restart. Returns why it stopped; failed() tells whether that was
     * an error. The problem then holds the last accepted design. */
    std::string
    run(const bool restart);

    /** Whether the last run() stopped on a refused design. */
    bool
    failed() const;

    /** Whether any design was accepted (false if the initial design was
     * refused): only then is there a design to write. */
    bool
    accepted_a_design() const;

  private:
    /** X_o <- X_o + psi(d), d <- 0 and a fresh MMA, at iteration @p k;
     * remeshes the design if its worst element quality is below "Remesh
     * below quality", or at @p mesh_size mm if > 0 (Mesh size schedule).
     * Returns the iterate before, to undo the update if the design it
     * moved the mesh to is refused (none if the filter refused psi(d) and
     * it was undone already, or after a new mesh). */
    std::optional<DesignIterate>
    update_mesh(const unsigned int k, DesignIterate &x, const double mesh_size = 0);

    /** The iteration whose update made the mesh @p x is on (its file
     * mesh-<k>.msh), -1 for the first mesh. */
    static long
    mesh_made_at(const DesignIterate &x);

    /** Whether the accepted design of @p x has flattened an element below
     * "Remesh below quality" since the last mesh update, on a mesh that
     * was above it: the mesh update then comes forward to iteration @p k
     * (and remeshes). Computed from X_o and psi, so a restart decides as
     * the uninterrupted run did. */
    bool
    elements_collapsing(const unsigned int k, const DesignIterate &x) const;

    /** The functional values at x.d into @p values; a refused d is halved
     * towards the accepted design (at most Step halvings times; a mesh
     * update to it is undone first); with @p check_from_rest, a design
     * whose path from rest fails is refused too. Returns why the run stops,
     * or "" once d is accepted. */
    std::string
    evaluate_or_halve(const unsigned int            k,
                      std::optional<DesignIterate> &before_update,
                      bool                          check_from_rest,
                      DesignIterate                &x,
                      std::vector<double>          &values);

    /** A fresh MMA on the design variables of @p x (start, mesh update). */
    void
    reset_mma(DesignIterate &x) const;

    /** Continues from the checkpoint: the iterate, and the history rows
     * before it. Returns the iteration to continue with. */
    unsigned int
    resume(DesignIterate &x);

    /** One MMA update of x.d from the values and gradients at x.d; returns
     * the largest change of a design variable in mm. */
    double
    mma_step(DesignIterate             &x,
             const std::vector<double> &values,
             const std::vector<Vector> &gradients) const;

    /** The row of history.csv and the line on screen. */
    void
    record(const unsigned int                               iteration,
           const std::vector<double>                       &values,
           const std::optional<DesignProblem::BranchCheck> &branch,
           const double                                     change,
           const double                                     wall_time);

    /** The design of @p x undeformed and deformed at each target (VTU/PVD),
     * and its surface as snapshots/design_<iteration>.stl. */
    void
    write_snapshot(const unsigned int iteration, const DesignIterate &x);

    const OptimizationParameters &parameters;
    const OutputParameters       &output;
    DesignProblem                &problem;
    const OutputDirectory        &out;
    const MPI_Comm                comm;
    ConditionalOStream            pcout;
    std::unique_ptr<CsvWriter>    history;
    std::ofstream                 path_log; // paths.log, on rank 0
    std::map<std::string, std::unique_ptr<PvdSeries>> snapshots;
    /** The iteration this run started at (a restart's). */
    unsigned int first_iteration = 0;
    bool                          stopped_on_error = false;
    bool                          any_accepted     = false;
    /** The last check switched branch: the design has several equilibria
     * at a target, and the next iteration is checked too. */
    bool                          switched_last_check = false;
  };
} // namespace softopt

#endif
