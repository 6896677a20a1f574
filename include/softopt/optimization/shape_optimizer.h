#ifndef softopt_optimization_shape_optimizer_h
#define softopt_optimization_shape_optimizer_h

#include <deal.II/base/conditional_ostream.h>

#include <softopt/app/output_directory.h>
#include <softopt/io/csv_writer.h>
#include <softopt/io/pvd_series.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/optimization/mma.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * The design loop of Section 6 (problem opt): MMA in min-max form,
   *   minimize z  subject to  g_i(d) - z <= 0,  f_j(d) <= 0,  |d| <= d_max,
   * with the equilibrium of the physics and of the shape filter solved for
   * every design (staggered), and a mesh update X_o <- X_o + psi, d <- 0
   * every "Mesh update interval" iterations. Writes history.csv (one row
   * per iteration), VTU snapshots and checkpoints into the output
   * directory.
   */
  class ShapeOptimizer
  {
  public:
    using Vector = DesignProblem::Vector;

    ShapeOptimizer(Settings              &settings,
                   DesignProblem         &problem,
                   const OutputDirectory &out);

    /** The loop from d = 0, or from the checkpoint with @p restart. Returns
     * why it stopped; failed() tells whether that was an error. */
    std::string
    run(const bool restart);

    /** Whether the last run() stopped on a refused design. */
    bool
    failed() const;

  private:
    /** What a mesh update changes, to undo it when the design it moved
     * the mesh to is refused. */
    struct MeshBeforeUpdate
    {
      Vector initial_coordinates, shape_field, d, accepted;
      /** MMA with its asymptotes and history on the old mesh's d. */
      std::unique_ptr<MMA> mma;
    };

    /** X_o <- X_o + psi(d), d <- 0 and a fresh MMA, at iteration @p k;
     * remeshes the design if its worst element quality is below "Remesh
     * below quality". Returns what it changed, to undo (nothing if the
     * filter refused psi(d) and it was undone already, or after a new
     * mesh). */
    std::unique_ptr<MeshBeforeUpdate>
    update_mesh(const unsigned int k);

    /** The functional values at d into @p values; a refused d is halved
     * towards the accepted design (if @p may_halve, at most Step halvings
     * times; a mesh update to it is undone first). Returns why the run
     * stops, or "" once d is accepted. */
    std::string
    evaluate_or_halve(const unsigned int                 k,
                      const bool                         may_halve,
                      std::unique_ptr<MeshBeforeUpdate> &before_update,
                      std::vector<double>               &values);

    /** Moves the mesh back (if @p before is set) and clears @p before; MMA
     * keeps its fresh start. */
    void
    undo_mesh_update(std::unique_ptr<MeshBeforeUpdate> &before);

    /** A fresh MMA on the current design variables (start, mesh update). */
    void
    reset_mma();

    /** Continues from the checkpoint: state, MMA, history rows before it. */
    unsigned int
    resume();

    /** One MMA update of d from the values and gradients at d; returns the
     * largest change of a design variable in mm. */
    double
    mma_step(const std::vector<double> &values, const std::vector<Vector> &gradients);

    /** The row of history.csv and the line on screen. */
    void
    record(const unsigned int         iteration,
           const std::vector<double> &values,
           const double               change,
           const double               wall_time);

    /** The design undeformed and deformed at each target (VTU/PVD). */
    void
    write_snapshot(const unsigned int iteration);

    Settings                  &settings;
    DesignProblem             &problem;
    const OutputDirectory     &out;
    ConditionalOStream         pcout;
    Vector                     d, accepted;
    std::unique_ptr<MMA>       mma;
    std::unique_ptr<CsvWriter> history;
    std::map<std::string, std::unique_ptr<PvdSeries>> snapshots;
    bool                       stopped_on_error = false;
    /** The mesh file of the last remesh, for the checkpoint ("": the
     * parameter file's mesh). */
    std::string                mesh_file;
  };
} // namespace softopt

#endif
