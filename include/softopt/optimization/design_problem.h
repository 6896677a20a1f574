#ifndef softopt_optimization_design_problem_h
#define softopt_optimization_design_problem_h

#include <deal.II/base/timer.h>
#include <deal.II/distributed/fully_distributed_tria.h>

#include <softopt/functionals/functional.h>
#include <softopt/optimization/design_iterate.h>
#include <softopt/optimization/problem_parameters.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>
#include <softopt/shape/remesh.h>
#include <softopt/shape/shape_filter.h>

#include <map>
#include <ostream>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * Everything between a design iterate and the functionals with their
   * gradients dg/dd (Sections 3, 5 and 6.1): the shape filter psi(d), the
   * design X = X_o + psi driving the mapping, the equilibrium path to every
   * target load factor, the functionals there, and their adjoint
   * sensitivities. It owns the mesh, the physics and the filter of the
   * iterate it was last given (initial_iterate(), evaluate(), update_mesh(),
   * remesh(), restore()); the iterate itself, the state of the run, is the
   * caller's (DesignIterate).
   */
  class DesignProblem
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    /** Builds mesh (@p mesh_file, or the parameter file's Mesh file if
     * empty), design configuration, filter and physics from
     * @p parameters, which must outlive this. */
    DesignProblem(const ProblemParameters &parameters,
                  const MPI_Comm           comm,
                  const std::string       &mesh_file = "");

    /** The design at rest on the current mesh: X_o as meshed, d = accepted
     * = psi = 0, no states, no secant, no MMA. */
    DesignIterate
    initial_iterate() const;

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

    /** The load factors of the final analysis, the path a user follows on
     * the bench: the targets and "Final analysis steps" equal steps in
     * (0, 1]. */
    std::vector<double>
    final_analysis_path() const;

    /** The file's objectives and constraints (and "V" if added), in order. */
    const std::vector<const Functional *> &
    functionals() const;

    /**
     * The functional values at the design variables x.d: filters d
     * (Newton from x.psi), follows the path to every target load factor
     * (warm-started from x.states along x.secant, or from zero) and
     * evaluates the functionals. With @p check_from_rest, after a warm
     * start, also loads the design from rest and compares (check_branch(),
     * Branch tolerance; branch_check() says what it found). Then x.psi,
     * x.states and x.secant are those of x.d. Throws a message if the filter refuses the shape or the
     * path cannot reach a target; @p x and the mapping then stay as they
     * were. @p x must be the iterate this problem holds (see the class).
     */
    std::vector<double>
    evaluate(DesignIterate &x, bool check_from_rest = false);

    /** What check_branch() found. */
    struct BranchCheck
    {
      /** max over the functionals of |g_warm - g_rest| / |g_rest|. */
      double difference = 0;
      /** Whether the run goes on from the states from rest. */
      bool switched = false;
    };

    /** What the last evaluate() found when it checked the warm-started
     * states against those from rest (evaluate()'s @p check_from_rest,
     * after a warm start only), else empty. */
    const std::optional<BranchCheck> &
    branch_check() const;

    /**
     * Loads the design of @p x, just evaluated to @p values, from rest to
     * the targets (as a design without warm start is: Loading's path
     * following and increments) and compares the functionals there with
     * @p values. If one differs by more than @p tolerance (relative), the
     * warm-started states were on another branch than inflating the design
     * reaches: x.states and @p values become those from rest and the
     * secant forgets the design before (its states are on the other
     * branch). Throws a message if the path from rest does not reach
     * every target (with "Limit point below a target = refuse", also at a
     * maximum of the load below one). evaluate() does the same before it
     * accepts a design when asked to.
     */
    BranchCheck
    check_branch(DesignIterate &x, std::vector<double> &values, const double tolerance);

    /** dg/dd of every functional at @p x, just evaluated, by the adjoint
     * method (Eqs. sens01-sens06). */
    std::vector<Vector>
    gradients(const DesignIterate &x);

    /** The mesh update of Section 5: X_o <- X_o + psi(x.d), psi <- 0,
     * d <- 0, accepted <- 0; the states and the secant carry over (X is
     * continuous). Throws like evaluate() if the filter refuses x.d (then
     * restore() the iterate from before). */
    void
    update_mesh(DesignIterate &x);

    /** A new mesh of the current design X = X_o + psi (remesh_design(),
     * with its boundary refined to @p mesh_size mm if > 0), written to
     * @p msh_file and read from there; @p x becomes the new mesh's
     * initial_iterate() with the states of @p x carried over
     * (transfer_states()), so that the next evaluate() starts Newton from
     * them; if a new node lies outside the old body, none carry over and
     * it follows the path from zero. Returns how many new nodes were not
     * found. If it throws, the old mesh and @p x stay as they were. */
    unsigned long
    remesh(DesignIterate &x, const std::string &msh_file, const double mesh_size = 0);

    /** What the last remesh() made (remesh_design()). */
    const NewMesh &
    last_new_mesh() const;

    /** Makes @p x, an iterate on this problem's mesh (a snapshot, a
     * checkpoint read on the mesh it names), this problem's iterate: sets
     * X_o and psi and sets the filter up on X_o. */
    void
    restore(const DesignIterate &x);

    /** The filter's report of the last evaluate(). */
    const ShapeFilter::Result &
    filter_result() const;

    /** The worst element quality of the accepted design X_o + psi of @p x
     * and of its mesh X_o (psi = 0), on this problem's mesh. */
    std::pair<double, double>
    element_quality(const DesignIterate &x) const;

    const HyperelasticProblem &
    hyperelastic_problem() const;

    /** The physics on the current design (the final analysis follows its
     * load path). */
    HyperelasticProblem &
    hyperelastic_problem();

    /** The mapping of the last accepted design. */
    const DesignConfiguration &
    design_configuration() const;

    MPI_Comm
    get_communicator() const;

    /** The physics' counts and times over the run, on every mesh it had
     * (a new mesh builds a new HyperelasticProblem). */
    HyperelasticProblem::Statistics
    physics_statistics() const;

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
      /** Design substeps that took the states to the new design after
       * both warm starts failed (0: none were needed, or they failed too
       * and warm_start_failure says why). */
      unsigned int substeps = 0;
      std::string  substep_failure;
      /** Over all targets and starts (a start that failed counts the
       * targets where it converged). */
      unsigned int newton_iterations = 0;
    };

    const PathReport &
    path_report() const;

    /** Every path from zero or from rest of the design loop writes its
     * steps, halvings and switches to @p log, after a line "@p label:
     * path from ..." (nullptr: they are silent). @p log is written by the
     * rank that passes it; the others pass nullptr. */
    void
    log_paths(std::ostream *log, const std::string &label);

    /** Wall times of the stages (filter, path following, functionals,
     * adjoints), summed over the run. */
    TimerOutput &
    timer();

  private:
    /** check_branch() on @p states and @p values, the secant aside. */
    BranchCheck
    compare_from_rest(std::map<double, Vector> &states,
                      std::vector<double>      &values,
                      const double              tolerance);

    /** Mesh, design configuration, physics and filter on @p mesh_file
     * ("": the parameter file's). */
    void
    build(const std::string &mesh_file);

    /** psi(d), then the states at the targets of the design X_o + psi
     * (warm-started from @p x); the functional values there. */
    std::vector<double>
    evaluate_design(const DesignIterate      &x,
                    Vector                   &psi,
                    std::map<double, Vector> &states);

    /** Newton at each target from the secant prediction of its state,
     * else from the previous design's state there, else along design
     * substeps (substep_start()); false if all fail. */
    bool
    warm_start(const DesignIterate &x, std::map<double, Vector> &states);

    /** Moves the design from the accepted psi of @p x to the current one in
     * steps of t (halved on a failure, doubled after a success), Newton at
     * every target from the states of the step before; leaves the current
     * psi in place either way. */
    bool
    substep_start(const DesignIterate &x, std::map<double, Vector> &states);

    /** Newton at every target from @p start; true (and @p states the
     * converged ones) if it converged for all. */
    bool
    newton_at_targets(std::map<double, Vector>  start,
                      std::map<double, Vector> &states,
                      std::string              &failure);

    /** Runs path following from zero to the targets, logged as
     * log_paths() says under the heading @p why; @p newton_iterations
     * the iterations of its converged steps. */
    PathFollowing::Result
    path_from_zero(const std::string &why, unsigned int &newton_iterations);

    /** X = X_o + psi, the nodal positions of the current design (locally
     * owned entries). */
    Vector
    nodal_positions() const;

    const ProblemParameters                      &parameters;
    MPI_Comm                                      comm;
    /** The mesh file of the current mesh ("": the parameter file's). */
    std::string                                   mesh_file;
    /** What the last remesh() made. */
    NewMesh                                       new_mesh;
    std::unique_ptr<parallel::fullydistributed::Triangulation<3>> triangulation;
    std::unique_ptr<DesignConfiguration>          design;
    std::unique_ptr<HyperelasticProblem>          problem;
    ShapeFilter                                   filter;
    const PathFollowing                           path_following;
    std::optional<BranchCheck>                    last_check;
    /** The statistics of the physics on earlier meshes of the run. */
    HyperelasticProblem::Statistics               earlier_meshes_statistics;
    std::vector<const Functional *>               functionals_;
    std::unique_ptr<Functional>                   volume;
    std::vector<double>                           targets;
    ShapeFilter::Result                           last_filter_result;
    TimerOutput                                   timer_output;
    PathReport                                    report;
    std::ostream                                 *path_log = nullptr;
    std::string                                   path_label;
    /** The tangent of the last assemble() is at the state of the last
     * evaluate() at this load factor (negative: unknown). */
    double tangent_at = -1;
  };

  /** The case's target load factors: "Target load factors" and those of
   * every objective and constraint, sorted, each once. */
  std::vector<double>
  case_targets(const ProblemParameters &parameters);

  /** The load factors of the final analysis of a design of @p parameters:
   * every target of the loading and the functionals, and "Final analysis
   * steps" equal steps in (0, 1]. */
  std::vector<double>
  final_analysis_path(const ProblemParameters &parameters);
} // namespace softopt

#endif
