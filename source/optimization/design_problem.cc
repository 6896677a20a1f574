#include <deal.II/base/exceptions.h>

#include <softopt/optimization/design_problem.h>
#include <softopt/base/step_failure.h>
#include <softopt/shape/remesh.h>
#include <softopt/shape/residual_shape_derivative.h>

#include <algorithm>

namespace softopt
{
  DesignProblem::DesignProblem(Settings &settings)
    : settings(settings)
    , comm(MPI_COMM_WORLD)
    , timer_output(comm, std::cout, TimerOutput::never, TimerOutput::wall_times)
  {
    build();
    for (const auto &f : settings.functionals)
      functionals_.push_back(f.get());
    targets = settings.loading.target_load_factors;
    for (const auto *f : functionals_)
      targets.push_back(f->load_factor());
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
  }



  void
  DesignProblem::build()
  {
    triangulation = std::make_unique<parallel::fullydistributed::Triangulation<3>>(comm);
    settings.geometry.create_triangulation(*triangulation);
    design   = std::make_unique<DesignConfiguration>(*triangulation, settings.geometry);
    problem  = std::make_unique<HyperelasticProblem>(*triangulation,
                                                    design->get_mapping(),
                                                    settings.geometry,
                                                    *settings.material,
                                                    settings.loading.pressure_kPa * 1e-3);
    problem->setup_system();
    problem->set_linear_solver(settings.linear_solver);
    settings.shape_filter.setup(*design, settings.geometry);
    psi.reinit(design->create_vector()); // the new mesh's layout
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
  DesignProblem::evaluate(const Vector &d)
  {
    // A refused design leaves the accepted one in place (its psi, and its
    // states for the next warm start).
    const Vector                   psi_accepted    = psi;
    const std::map<double, Vector> states_accepted = states;
    try
      {
        const std::vector<double> values = evaluate_design(d);
        if (settings.optimization.warm_start && settings.optimization.secant_predictor)
          predictor.accept(nodal_positions(), states_accepted);
        return values;
      }
    catch (...)
      {
        psi    = psi_accepted;
        states = states_accepted;
        design->set_shape_field(psi);
        settings.shape_filter.forget_factorization();
        throw;
      }
  }



  std::vector<double>
  DesignProblem::evaluate_design(const Vector &d)
  {
    // Eq. PDEpot02 for psi(d), starting from the last psi; then the mapping.
    {
      TimerOutput::Scope scope(timer_output, "shape filter");
      last_filter_result = settings.shape_filter.solve(d, psi);
      design->set_shape_field(psi);
    }

    TimerOutput::Scope scope(timer_output, "path following");
    report     = PathReport();
    tangent_at = -1;
    if (settings.optimization.warm_start && warm_start())
      {
        report.warm_started = true;
        tangent_at          = targets.back();
      }
    else
      {
        ConditionalOStream quiet(std::cout, false);
        const auto         result = settings.loading.run(
          *problem,
          settings.newton,
          targets,
          [this](const PathFollowing::PathPoint &point, const Vector &) {
            report.newton_iterations += point.newton_iterations;
            return std::string();
          },
          quiet);
        AssertThrow(result.target_states.size() == targets.size(),
                    ExcMessage("The load path of this design did not reach "
                               "every target load factor: " +
                               result.stop_reason));
        states.clear();
        for (unsigned int i = 0; i < targets.size(); ++i)
          states.emplace(result.target_load_factors[i], result.target_states[i]);
      }

    std::vector<double> values;
    for (const auto *f : functionals_)
      values.push_back(
        f->evaluate(*problem, *design, states.at(f->load_factor()), nullptr, nullptr));
    return values;
  }



  std::vector<DesignProblem::Vector>
  DesignProblem::gradients()
  {
    std::vector<Vector> result(functionals_.size());
    Vector              r, P, dg_da, dg_dX, mu_a, mu_psi;
    // The last target first: after a warm start its tangent is assembled.
    for (auto target = states.rbegin(); target != states.rend(); ++target)
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
        for (unsigned int i = 0; i < functionals_.size(); ++i)
          {
            if (functionals_[i]->load_factor() != load_factor)
              continue;
            if (!factorized)
              {
                TimerOutput::Scope scope(timer_output, "adjoint: tangent");
                problem->assemble(a, load_factor, r, P, true);
                problem->factorize();
                factorized = true;
                tangent_at = -1;
              }
            {
              TimerOutput::Scope scope(timer_output, "adjoint: solve");
              functionals_[i]->evaluate(*problem, *design, a, &dg_da, &dg_dX);
              if (assembled)
                problem->solve_kept(dg_da, mu_a);
              else
                problem->solve(dg_da, mu_a);
            }
            // Eq. adj3: (dr_psi/dpsi)^T mu_psi = dg/dpsi - (dr_a/dpsi)^T mu_a
            {
              TimerOutput::Scope scope(timer_output, "adjoint: shape derivatives");
              dg_dX -= residual_shape_derivative(*problem, *design, a, load_factor, mu_a);
            }
            TimerOutput::Scope scope(timer_output, "adjoint: filter");
            settings.shape_filter.solve_adjoint(dg_dX, mu_psi);
            // Eq. sens06: dg/dd = -mu_psi^T dr_psi/dd
            result[i] = settings.shape_filter.design_gradient(mu_psi);
          }
      }
    return result;
  }



  void
  DesignProblem::update_mesh(const Vector &d)
  {
    last_filter_result = settings.shape_filter.solve(d, psi);
    design->set_shape_field(psi);
    design->update_mesh();
    psi = 0;
    // Omega_o changed: the filter's matrices and |Omega_o| with it.
    settings.shape_filter.setup(*design, settings.geometry);
  }



  void
  DesignProblem::remesh(const std::string &msh_file)
  {
    remesh_design(*design, msh_file);
    // Built beside the old mesh, which stays if anything fails.
    auto old_triangulation = std::move(triangulation);
    auto old_design        = std::move(design);
    auto old_problem       = std::move(problem);
    const std::string old_file = settings.geometry.mesh_file;
    try
      {
        settings.geometry.mesh_file = msh_file;
        build();
      }
    catch (...)
      {
        problem       = std::move(old_problem);
        design        = std::move(old_design);
        triangulation = std::move(old_triangulation);
        settings.geometry.mesh_file = old_file;
        // psi is untouched: build() sets it up last.
        settings.shape_filter.setup(*design, settings.geometry);
        throw;
      }
    earlier_meshes_statistics += old_problem->get_statistics();
    old_problem.reset(); // before the DoFs and the mesh it lives on
    old_design.reset();
    // Nothing carries over: the next evaluate() follows the path from zero.
    states.clear();
    predictor          = SecantPredictor();
    tangent_at         = -1;
    last_filter_result = ShapeFilter::Result();
  }



  const DesignProblem::Vector &
  DesignProblem::shape_field() const
  {
    return psi;
  }



  void
  DesignProblem::restore(const Vector &initial_coordinates, const Vector &shape_field)
  {
    design->set_configuration(initial_coordinates, shape_field);
    psi = shape_field;
    settings.shape_filter.setup(*design, settings.geometry);
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



  bool
  DesignProblem::warm_start()
  {
    if (states.size() != targets.size())
      return false;
    if (settings.optimization.secant_predictor)
      if (auto prediction = predictor.predict(nodal_positions(), states);
          prediction &&
          newton_at_targets(std::move(prediction->states), report.secant_failure))
        {
          report.secant_alpha = prediction->alpha;
          return true;
        }
    if (newton_at_targets(states, report.warm_start_failure))
      return true;
    states.clear();
    return false;
  }



  bool
  DesignProblem::newton_at_targets(std::map<double, Vector> start,
                                   std::string             &failure)
  {
    try
      {
        for (auto &[load_factor, a] : start) // ascending
          report.newton_iterations +=
            settings.newton.solve(*problem, a, load_factor).iterations;
        states = std::move(start);
        return true;
      }
    catch (const StepFailure &step_failure)
      {
        failure = step_failure.what();
        return false;
      }
  }



  DesignProblem::Vector
  DesignProblem::nodal_positions() const
  {
    Vector X = design->initial_coordinates();
    X += psi;
    return X;
  }



  void
  DesignProblem::set_target_states(const std::map<double, Vector> &new_states,
                                   const SecantPredictor          &secant)
  {
    states     = new_states;
    tangent_at = -1;
    predictor  = secant;
  }



  const SecantPredictor &
  DesignProblem::secant_predictor() const
  {
    return predictor;
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



  const std::map<double, DesignProblem::Vector> &
  DesignProblem::target_states() const
  {
    return states;
  }
} // namespace softopt
