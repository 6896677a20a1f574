#ifndef softopt_optimization_design_problem_h
#define softopt_optimization_design_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <softopt/app/settings.h>
#include <softopt/functionals/functional.h>
#include <softopt/optimization/secant_predictor.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>
#include <softopt/shape/shape_filter.h>

#include <map>
#include <string>
#include <memory>
#include <vector>

namespace softopt
{
  /**
   * Everything between a design vector d and the functionals with their
   * gradients dg/dd (Sections 3, 5 and 6.1): the shape filter psi(d), the
   * design X = X_o + psi driving the mapping, the equilibrium path to every
   * target load factor, the functionals there, and their adjoint
   * sensitivities. d, psi and X are P2 vector fields on the same mesh, in mm.
   */
  class DesignProblem
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    /** Builds mesh, design configuration, filter and physics from
     * @p settings, which must outlive this. */
    explicit DesignProblem(Settings &settings);

    /** A zero design vector. */
    Vector
    create_design_vector() const;

    /** Adds the cavity volume at the last target load factor ("V") to the
     * functionals (the gradient check tests it too). */
    void
    add_cavity_volume();

    /** The union of "Target load factors" and the functionals' load
     * factors, ascending. */
    const std::vector<double> &
    target_load_factors() const;

    /** The file's objectives and constraints (and "V" if added), in order. */
    const std::vector<const Functional *> &
    functionals() const;

    /**
     * The functional values at design @p d: filters d, follows the path to
     * every target load factor (the union of "Target load factors" and the
     * functionals' load factors) and evaluates the functionals. Throws a
     * message if the filter refuses the shape or the path cannot reach a
     * target; the accepted design (psi and the states at the targets) then
     * stays in place.
     */
    std::vector<double>
    evaluate(const Vector &d);

    /** dg/dd of every functional at the last evaluate(), by the adjoint
     * method (Eqs. sens01-sens06). */
    std::vector<Vector>
    gradients();

    /** The mesh update of Section 5: X_o <- X_o + psi(@p d), psi <- 0; the
     * caller sets d <- 0. The geometry and every functional stay unchanged.
     * Throws like evaluate() if the filter refuses @p d. */
    void
    update_mesh(const Vector &d);

    /** A new mesh of the current design X = X_o + psi (remesh_design()),
     * written to @p msh_file and read from there, with X_o the new mesh,
     * psi = 0 and no states (the next evaluate() follows the path from
     * zero). The caller starts d and MMA afresh. If it throws, the old
     * mesh and design stay in place. */
    void
    remesh(const std::string &msh_file);

    /** psi of the last filter solve. */
    const Vector &
    shape_field() const;

    /** Sets X_o and psi (a restart from a checkpoint). */
    void
    restore(const Vector &initial_coordinates, const Vector &psi);

    /** The filter's report of the last evaluate(). */
    const ShapeFilter::Result &
    filter_result() const;

    const HyperelasticProblem &
    hyperelastic_problem() const;

    /** The physics on the current design (the final analysis follows its
     * load path). */
    HyperelasticProblem &
    hyperelastic_problem();

    const DesignConfiguration &
    design_configuration() const;

    /** The physics' counts and times over the run, on every mesh it had
     * (a new mesh builds a new HyperelasticProblem). */
    HyperelasticProblem::Statistics
    physics_statistics() const;

    /** Sets the states at the targets and the warm start's secant (a
     * restart: the next evaluate() warm-starts from them like an
     * uninterrupted run). */
    void
    set_target_states(const std::map<double, Vector> &states,
                      const SecantPredictor          &secant);

    /** The warm start's secant through the last two accepted designs (for
     * a checkpoint). */
    const SecantPredictor &
    secant_predictor() const;

    /** What the last evaluate() did: whether it warm-started (else why
     * the warm start failed, if it was tried), and the Newton iterations
     * over all targets. */
    struct PathReport
    {
      bool         warm_started      = false;
      /** The secant's alpha if Newton converged from its prediction (0: it
       * did not start there or failed from there). */
      double       secant_alpha      = 0;
      /** Why Newton failed from the secant start (then it started from
       * the last design's states). */
      std::string  secant_failure;
      std::string  warm_start_failure;
      /** Over all targets and starts (a start that failed counts the
       * targets where it converged). */
      unsigned int newton_iterations = 0;
    };

    const PathReport &
    path_report() const;

    /** Wall times of the stages (filter, path following, functionals,
     * adjoints), summed over the run. */
    TimerOutput &
    timer();

    /** The converged states at the target load factors of the last
     * evaluate(). */
    const std::map<double, Vector> &
    target_states() const;

  private:
    /** Mesh, design configuration, physics and filter from the geometry
     * of the settings. */
    void
    build();

    /** evaluate() without the restore on failure. */
    std::vector<double>
    evaluate_design(const Vector &d);

    /** Newton at each target from the secant prediction of its state,
     * else from the previous design's state there; false (and the states
     * are void) if Newton fails from both for one of them. */
    bool
    warm_start();

    /** Newton at every target from @p states; true if it converged for
     * all (then they are the new states). */
    bool
    newton_at_targets(std::map<double, Vector> start, std::string &failure);

    /** X = X_o + psi, the nodal positions of the current design (locally
     * owned entries). */
    Vector
    nodal_positions() const;

    Settings                                     &settings;
    MPI_Comm                                      comm;
    std::unique_ptr<parallel::fullydistributed::Triangulation<3>> triangulation;
    std::unique_ptr<DesignConfiguration>          design;
    std::unique_ptr<HyperelasticProblem>          problem;
    /** The statistics of the physics on earlier meshes of the run. */
    HyperelasticProblem::Statistics               earlier_meshes_statistics;
    std::vector<const Functional *>               functionals_;
    std::unique_ptr<Functional>                   volume;
    std::vector<double>                           targets;
    Vector                                        psi;
    ShapeFilter::Result                           last_filter_result;
    std::map<double, Vector>                      states;
    SecantPredictor                               predictor;
    TimerOutput                                   timer_output;
    PathReport                                    report;
    /** The tangent of the last assemble() is at states[load factor]
     * (negative: unknown). */
    double tangent_at = -1;
  };
} // namespace softopt

#endif
