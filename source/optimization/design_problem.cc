#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>

#include <softopt/base/step_failure.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/physics/state_transfer.h>
#include <softopt/shape/remesh.h>
#include <softopt/shape/residual_shape_derivative.h>
#include <softopt/shape/self_intersection.h>

#include <algorithm>
#include <sstream>

namespace softopt
{
  namespace
  {
    /** The states at @p load_factors, in their order. */
    Functional::States
    states_at(const std::map<double, DesignProblem::Vector> &states,
              const std::vector<double>                     &load_factors)
    {
      Functional::States at;
      for (const double load_factor : load_factors)
        at.push_back(&states.at(load_factor));
      return at;
    }

    /** Loading's path, for the paths from rest of the design loop: with
     * "Limit point below a target = refuse", arclength (its step control
     * keeps it on the branch from rest: a load step can jump over a fold)
     * stopping at a maximum of the load. */
    PathFollowing::Parameters
    design_loop_path(const ProblemParameters &parameters)
    {
      PathFollowing::Parameters path = parameters.loading.path;
      if (parameters.optimization.refuse_limit_points)
        {
          path.method              = PathFollowing::Method::arclength;
          path.stop_at_limit_point = true;
        }
      return path;
    }

    /** After a path stopped at a limit point: how to optimize anyway. */
    std::string
    snap_hint(const PathFollowing::Result &result)
    {
      return result.stopped_at_limit_point ?
               " (Such designs are refused by \"Limit point below a target = "
               "refuse\", subsection Optimization; \"follow\" optimizes the "
               "state the part snaps to.)" :
               "";
    }
  } // namespace



  DesignProblem::DesignProblem(const ProblemParameters &parameters,
                               const MPI_Comm           comm,
                               const std::string       &mesh_file)
    : parameters(parameters)
    , comm(comm)
    , filter(parameters.shape_filter)
    , path_following(design_loop_path(parameters))
    , timer_output(comm, std::cout, TimerOutput::never, TimerOutput::wall_times)
  {
    build(mesh_file);
    for (const auto &f : parameters.functionals)
      functionals_.push_back(f.get());
    targets = case_targets(parameters);
  }



  void
  DesignProblem::build(const std::string &file)
  {
    triangulation = std::make_unique<parallel::fullydistributed::Triangulation<3>>(comm);
    const EdgeMidpoints midpoints =
      parameters.geometry.create_triangulation(*triangulation, file);
    design  = std::make_unique<DesignConfiguration>(*triangulation, midpoints);
    problem = std::make_unique<HyperelasticProblem>(*triangulation,
                                                    design->get_mapping(),
                                                    parameters.geometry,
                                                    *parameters.material,
                                                    parameters.loading.pressure_kPa * 1e-3);
    problem->setup_system();
    problem->set_linear_solver(parameters.linear_solver);
    filter.setup(*design, parameters.geometry);
    filter.set_linear_solver(parameters.linear_solver);
    mesh_file = file;
  }



  DesignIterate
  DesignProblem::initial_iterate() const
  {
    DesignIterate x;
    x.mesh_file = mesh_file;
    x.X_o       = design->initial_coordinates();
    x.d         = design->create_vector();
    x.accepted  = x.d;
    x.psi       = x.d;
    return x;
  }



  DesignProblem::Vector
  DesignProblem::create_design_vector() const
  {
    return design->create_vector();
  }



  void
  DesignProblem::add_cavity_volume()
  {
    volume = Functionals::cavity_volume(targets.back());
    functionals_.push_back(volume.get());
  }



  const std::vector<double> &
  DesignProblem::target_load_factors() const
  {
    return targets;
  }



  const std::vector<const Functional *> &
  DesignProblem::functionals() const
  {
    return functionals_;
  }



  std::vector<double>
  DesignProblem::evaluate(DesignIterate &x, const bool check_from_rest)
  {
    Vector                   psi = x.psi;
    std::map<double, Vector> states;
    std::vector<double>      values;
    last_check.reset();
    try
      {
        values = evaluate_design(x, psi, states);
        if (check_from_rest && report.warm_started)
          last_check =
            compare_from_rest(states, values, parameters.optimization.branch_tolerance);
      }
    catch (...)
      {
        // A refused design leaves the accepted one in place.
        design->set_shape_field(x.psi);
        filter.forget_factorization();
        throw;
      }
    const auto &warm = parameters.optimization;
    if (warm.warm_start && warm.secant_predictor)
      x.secant.accept(nodal_positions(), x.states);
    x.psi    = std::move(psi);
    x.states = std::move(states);
    if (last_check && last_check->switched) // the design before is on the other branch
      x.secant.restore(x.secant.last_positions(), SecantPredictor::Design());
    return values;
  }



  const std::optional<DesignProblem::BranchCheck> &
  DesignProblem::branch_check() const
  {
    return last_check;
  }



  std::vector<double>
  DesignProblem::evaluate_design(const DesignIterate      &x,
                                 Vector                   &psi,
                                 std::map<double, Vector> &states)
  {
    // Eq. PDEpot02 for psi(d), starting from the last psi; then the mapping.
    {
      TimerOutput::Scope scope(timer_output, "shape filter");
      last_filter_result = filter.solve(x.d, psi);
      design->set_shape_field(psi);
    }
    if (parameters.optimization.refuse_self_intersections)
      {
        TimerOutput::Scope scope(timer_output, "self-intersection test");
        const auto         found = design_self_intersections(*design);
        std::ostringstream where;
        where << found.where;
        AssertThrow(found.pairs == 0,
                    ExcMessage("The design surface intersects itself (" +
                               std::to_string(found.pairs) +
                               " pairs of triangles, one near (" + where.str() +
                               ") mm); the shape is refused."));
      }

    {
      TimerOutput::Scope scope(timer_output, "path following");
      report     = PathReport();
      tangent_at = -1;
      if (parameters.optimization.warm_start && warm_start(x, states))
        {
          report.warm_started = true;
          tangent_at          = targets.back();
        }
      else
        {
          unsigned int iterations = 0;
          const auto   result     = path_from_zero(
            "path from zero (" +
              (report.warm_start_failure.empty() ? std::string("no warm start") :
                                                   "the warm start failed") +
              ")",
            iterations);
          report.newton_iterations += iterations;
          AssertThrow(result.target_states.size() == targets.size(),
                      ExcMessage("The load path of this design did not reach "
                                 "every target load factor: " +
                                 result.stop_reason + snap_hint(result)));
          states.clear();
          for (unsigned int i = 0; i < targets.size(); ++i)
            states.emplace(result.target_load_factors[i], result.target_states[i]);
        }
    }

    TimerOutput::Scope  scope(timer_output, "functionals");
    std::vector<double> values;
    for (const auto *f : functionals_)
      values.push_back(
        f->evaluate(*problem, *design, states_at(states, f->load_factors()), nullptr));
    return values;
  }



  std::vector<double>
  DesignProblem::final_analysis_path() const
  {
    return softopt::final_analysis_path(parameters);
  }



  std::vector<double>
  case_targets(const ProblemParameters &parameters)
  {
    std::vector<double> targets = parameters.loading.target_load_factors;
    for (const auto &f : parameters.functionals)
      targets.insert(targets.end(), f->load_factors().begin(), f->load_factors().end());
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    return targets;
  }



  std::vector<double>
  final_analysis_path(const ProblemParameters &parameters)
  {
    std::vector<double> path = case_targets(parameters);
    const unsigned int n = parameters.optimization.final_analysis_steps;
    for (unsigned int i = 1; i <= n; ++i)
      path.push_back(double(i) / n);
    return path; // PathFollowing sorts and merges repeats
  }



  DesignProblem::BranchCheck
  DesignProblem::check_branch(DesignIterate       &x,
                              std::vector<double> &values,
                              const double         tolerance)
  {
    const BranchCheck check = compare_from_rest(x.states, values, tolerance);
    if (check.switched)
      x.secant.restore(x.secant.last_positions(), SecantPredictor::Design());
    return check;
  }



  DesignProblem::BranchCheck
  DesignProblem::compare_from_rest(std::map<double, Vector> &states,
                                   std::vector<double>      &values,
                                   const double              tolerance)
  {
    TimerOutput::Scope scope(timer_output, "path from rest");
    BranchCheck        check;
    unsigned int       iterations = 0; // not the design's: the check's
    const auto result = path_from_zero("path from rest (the branch check)", iterations);
    tangent_at = -1; // the path assembled other states
    std::map<double, Vector> from_rest;
    for (unsigned int i = 0; i < result.target_states.size(); ++i)
      if (std::find(targets.begin(), targets.end(), result.target_load_factors[i]) !=
          targets.end())
        from_rest.emplace(result.target_load_factors[i], result.target_states[i]);
    // A design the warm start reached but inflating it from rest does not:
    // its states are not the part's.
    AssertThrow(from_rest.size() == targets.size(),
                ExcMessage("The warm start reached the targets, but loading the "
                           "design from rest does not: " +
                           result.stop_reason + snap_hint(result)));

    std::vector<double> rest_values;
    for (unsigned int i = 0; i < functionals_.size(); ++i)
      {
        const auto &f = *functionals_[i];
        rest_values.push_back(
          f.evaluate(*problem, *design, states_at(from_rest, f.load_factors()), nullptr));
        // Relative to the quantity, not to the constraint's distance from
        // its tolerance: an active constraint is near 0, and a
        // difference at Lanczos' or Newton's accuracy would count as
        // another branch (the contractor's softening at 300-304).
        check.difference =
          std::max(check.difference,
                   std::abs(values[i] - rest_values[i]) /
                     std::max(f.magnitude(rest_values[i]), 1e-12));
      }
    if (check.difference > tolerance)
      {
        check.switched = true;
        states         = std::move(from_rest);
        values         = std::move(rest_values);
      }
    return check;
  }



  std::vector<DesignProblem::Vector>
  DesignProblem::gradients(const DesignIterate &x)
  {
    const unsigned int                   n = functionals_.size();
    std::vector<Vector>                  result(n);
    std::vector<Functional::Derivatives> partials(n);
    // The states of each functional still to be done; at the last, its
    // dg/dX holds every shape term and the filter adjoint follows.
    std::vector<unsigned int> remaining(n);
    for (unsigned int i = 0; i < n; ++i)
      remaining[i] = functionals_[i]->load_factors().size();
    Vector r, P, mu_a, mu_psi;
    // Eq. adj3 with every shape term in dg/dX: (dr_psi/dpsi)^T mu_psi = dg/dpsi,
    // then Eq. sens06: dg/dd = -mu_psi^T dr_psi/dd.
    const auto through_filter = [&](const unsigned int i) {
      TimerOutput::Scope scope(timer_output, "adjoint: filter");
      filter.solve_adjoint(partials[i].d_dX, mu_psi);
      result[i] = filter.design_gradient(mu_psi);
    };
    // A functional of the shape alone (no state) goes through the filter only.
    for (unsigned int i = 0; i < n; ++i)
      if (remaining[i] == 0)
        {
          functionals_[i]->evaluate(*problem, *design, {}, &partials[i]);
          through_filter(i);
        }
    // The last target first: after a warm start its tangent is assembled.
    for (auto target = x.states.rbegin(); target != x.states.rend(); ++target)
      {
        const double  load_factor = target->first;
        const Vector &a           = target->second;
        // The adjoint of the condensed system shares the tangent at the
        // target state (symmetric, Eq. adj2). After a warm start the last
        // target's tangent is assembled (Newton's final residual check) and
        // solved by GMRES on the factorization held (a nearby tangent);
        // other targets assemble and factorize.
        const bool assembled  = load_factor == tangent_at;
        bool       factorized = assembled;
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto &load_factors = functionals_[i]->load_factors();
            for (unsigned int j = 0; j < load_factors.size(); ++j)
              {
                if (load_factors[j] != load_factor)
                  continue;
                if (!factorized)
                  {
                    TimerOutput::Scope scope(timer_output, "adjoint: tangent");
                    problem->assemble(a, load_factor, r, P, true);
                    problem->factorize();
                    factorized = true;
                    tangent_at = -1;
                  }
                if (partials[i].d_da.empty()) // dg/da^j and dg/dX
                  {
                    TimerOutput::Scope scope(timer_output, "adjoint: functional derivatives");
                    functionals_[i]->evaluate(*problem,
                                              *design,
                                              states_at(x.states, load_factors),
                                              &partials[i]);
                  }
                {
                  TimerOutput::Scope scope(timer_output, "adjoint: solve");
                  if (assembled)
                    problem->solve_kept(partials[i].d_da[j], mu_a);
                  else
                    problem->solve(partials[i].d_da[j], mu_a);
                }
                // Eq. adj3: (dr_psi/dpsi)^T mu_psi = dg/dpsi - (dr_a/dpsi)^T mu_a
                TimerOutput::Scope scope(timer_output, "adjoint: shape derivatives");
                partials[i].d_dX -=
                  residual_shape_derivative(*problem, *design, a, load_factor, mu_a);
                --remaining[i];
              }
            if (remaining[i] == 0 && result[i].size() == 0)
              through_filter(i);
          }
      }
    return result;
  }



  void
  DesignProblem::update_mesh(DesignIterate &x)
  {
    last_filter_result = filter.solve(x.d, x.psi);
    design->set_shape_field(x.psi);
    design->update_mesh();
    x.X_o = design->initial_coordinates();
    x.psi = 0;
    x.d   = 0;
    x.accepted = 0;
    // Omega_o changed: the filter's matrices and |Omega_o| with it.
    filter.setup(*design, parameters.geometry);
  }



  const NewMesh &
  DesignProblem::last_new_mesh() const
  {
    return new_mesh;
  }



  unsigned long
  DesignProblem::remesh(DesignIterate &x, const std::string &msh_file, const double mesh_size)
  {
    new_mesh = remesh_design(*design, msh_file, mesh_size);
    // Built beside the old mesh, which stays if anything fails.
    auto old_triangulation = std::move(triangulation);
    auto old_design        = std::move(design);
    auto old_problem       = std::move(problem);
    const std::string old_file = mesh_file;
    StateTransfer     transfer;
    try
      {
        build(msh_file);
        // The states carry over as Newton's start on the new mesh; psi, d
        // and MMA start afresh (X_o is the design), the secant has no
        // history.
        transfer = transfer_states(*old_problem, x.states, *problem, design->get_mapping());
      }
    catch (...)
      {
        problem       = std::move(old_problem);
        design        = std::move(old_design);
        triangulation = std::move(old_triangulation);
        mesh_file     = old_file;
        filter.setup(*design, parameters.geometry);
        throw;
      }
    earlier_meshes_statistics += old_problem->get_statistics();
    old_problem.reset(); // before the DoFs and the mesh it lives on
    old_design.reset();
    x                  = initial_iterate();
    x.states           = std::move(transfer.states);
    tangent_at         = -1;
    last_filter_result = ShapeFilter::Result();
    return transfer.n_not_found;
  }



  void
  DesignProblem::restore(const DesignIterate &x)
  {
    Assert(x.mesh_file == mesh_file,
           ExcMessage("An iterate is restored on its own mesh: build the "
                      "DesignProblem on the checkpoint's mesh file."));
    design->set_configuration(x.X_o, x.psi);
    filter.setup(*design, parameters.geometry);
    tangent_at = -1;
  }



  HyperelasticProblem &
  DesignProblem::hyperelastic_problem()
  {
    return *problem;
  }



  const ShapeFilter::Result &
  DesignProblem::filter_result() const
  {
    return last_filter_result;
  }



  std::pair<double, double>
  DesignProblem::element_quality(const DesignIterate &x) const
  {
    return {filter.mesh_health(x.psi).worst_quality,
            filter.mesh_health(design->create_vector()).worst_quality};
  }



  const HyperelasticProblem &
  DesignProblem::hyperelastic_problem() const
  {
    return *problem;
  }



  HyperelasticProblem::Statistics
  DesignProblem::physics_statistics() const
  {
    HyperelasticProblem::Statistics all = earlier_meshes_statistics;
    all += problem->get_statistics();
    return all;
  }



  const DesignConfiguration &
  DesignProblem::design_configuration() const
  {
    return *design;
  }



  MPI_Comm
  DesignProblem::get_communicator() const
  {
    return comm;
  }



  bool
  DesignProblem::warm_start(const DesignIterate &x, std::map<double, Vector> &states)
  {
    if (x.states.size() != targets.size())
      return false;
    if (parameters.optimization.secant_predictor)
      if (auto prediction = x.secant.predict(nodal_positions(), x.states);
          prediction &&
          newton_at_targets(std::move(prediction->states), states, report.secant_failure))
        {
          report.secant_alpha = prediction->alpha;
          return true;
        }
    if (newton_at_targets(x.states, states, report.warm_start_failure))
      return true;
    return parameters.optimization.warm_start_substeps > 0 && substep_start(x, states);
  }



  bool
  DesignProblem::substep_start(const DesignIterate &x, std::map<double, Vector> &states)
  {
    // A homotopy in the design: near a fold of the design's own path the
    // new state is too far from the old one for Newton, but the states of
    // the designs in between connect them (the extender's bellows at 18 mm,
    // doc/theory.md). Intermediate psi need not solve the filter.
    const Vector psi = design->shape_field();
    const double smallest =
      std::ldexp(0.5, -static_cast<int>(parameters.optimization.warm_start_substeps));
    std::map<double, Vector> current = x.states;
    double                   t = 0, dt = 0.5;
    while (t < 1 && dt >= smallest)
      {
        const double t_next = std::min(1., t + dt);
        Vector       psi_t  = x.psi;
        psi_t.sadd(1. - t_next, t_next, psi);
        design->set_shape_field(psi_t);
        std::map<double, Vector> next;
        if (newton_at_targets(current, next, report.substep_failure))
          {
            current = std::move(next);
            t       = t_next;
            dt      = std::min(2 * dt, 0.5);
            ++report.substeps;
          }
        else
          dt /= 2;
      }
    design->set_shape_field(psi);
    if (t < 1)
      {
        report.substeps = 0;
        return false;
      }
    states = std::move(current);
    report.substep_failure.clear();
    return true;
  }



  bool
  DesignProblem::newton_at_targets(std::map<double, Vector>  start,
                                   std::map<double, Vector> &states,
                                   std::string              &failure)
  {
    try
      {
        for (auto &[load_factor, a] : start) // ascending
          report.newton_iterations +=
            parameters.newton.solve(*problem, a, load_factor).iterations;
        states = std::move(start);
        return true;
      }
    catch (const StepFailure &step_failure)
      {
        failure = step_failure.what();
        return false;
      }
  }



  PathFollowing::Result
  DesignProblem::path_from_zero(const std::string &why, unsigned int &newton_iterations)
  {
    ConditionalOStream log(path_log != nullptr ? *path_log : std::cout, path_log != nullptr);
    log << path_label << ": " << why << std::endl;
    unsigned int steps = 0;
    newton_iterations  = 0;
    const auto   result = path_following.run(
      *problem,
      parameters.newton,
      targets,
      [&](const PathFollowing::PathPoint &point, const Vector &) {
        ++steps;
        newton_iterations += point.newton_iterations;
        log << "  step " << point.step << "  lambda " << point.load_factor
            << "  Newton " << point.newton_iterations
            << (point.limit_point ? "  (limit point)" : "") << std::endl;
        return std::string();
      },
      log);
    log << "  " << steps << " steps, " << newton_iterations
        << " Newton iterations in converged steps: " << result.stop_reason << std::endl;
    return result;
  }



  void
  DesignProblem::log_paths(std::ostream *log, const std::string &label)
  {
    path_log   = log;
    path_label = label;
  }



  DesignProblem::Vector
  DesignProblem::nodal_positions() const
  {
    Vector X = design->initial_coordinates();
    X += design->shape_field();
    return X;
  }



  const DesignProblem::PathReport &
  DesignProblem::path_report() const
  {
    return report;
  }



  TimerOutput &
  DesignProblem::timer()
  {
    return timer_output;
  }
} // namespace softopt
