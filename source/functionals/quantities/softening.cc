// How soft the softest mode of the body has become at a target: a
// constraint that keeps a limit point (a snap-through) away from the target
// pressure by the tangent itself (doc/theory.md, "Keeping every mode stiff").

#include <softopt/base/step_failure.h>
#include <softopt/functionals/quantity.h>
#include <softopt/physics/stability.h>
#include <softopt/shape/residual_shape_derivative.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <iostream>

namespace softopt
{
  namespace
  {
    /** Whether @p kept has the layout of @p v on every rank (a vector of
     * another mesh may have the same size, and its owned ranges may agree
     * on some ranks only): collective, so every rank takes the same branch. */
    bool
    same_layout(const PETScWrappers::MPI::Vector &kept, const PETScWrappers::MPI::Vector &v)
    {
      const bool here = kept.size() == v.size() &&
                        kept.locally_owned_elements() == v.locally_owned_elements();
      return Utilities::MPI::min(here ? 1 : 0, v.get_mpi_communicator()) == 1;
    }

    /** Whether @p kept holds the design's positions X (same layout and
     * values). */
    bool
    same_positions(const DesignConfiguration::Vector &kept, const DesignConfiguration &design)
    {
      const auto &X = design.positions();
      if (!same_layout(kept, X))
        return false;
      auto difference = design.create_vector();
      for (const auto i : difference.locally_owned_elements())
        difference(i) = X(i) - kept(i);
      difference.compress(VectorOperation::insert);
      return difference.linfty_norm() == 0;
    }

    /** A copy of the design's positions X. */
    DesignConfiguration::Vector
    copy_positions(const DesignConfiguration &design)
    {
      auto X = design.create_vector();
      for (const auto i : X.locally_owned_elements())
        X(i) = design.positions()(i);
      X.compress(VectorOperation::insert);
      return X;
    }

    /** The set-up that does not change with the design: softening's own
     * tangent (lowest_eigenvalue() factorizes it; the design problem's
     * factorization is kept for its Newton steps and adjoints) and the
     * metric's body at rest, on the same mesh, mapping and DoF numbering
     * as the design problem; kept with it (HyperelasticProblem::companion). */
    struct Workspace
    {
      Workspace(const HyperelasticProblem &problem, const DesignConfiguration &design)
        : tangent(problem.get_dof_handler().get_triangulation(),
                  problem.get_mapping(),
                  problem.get_geometry(),
                  problem.get_material(),
                  problem.get_pressure())
      {
        tangent.setup_system();
        AssertThrow(tangent.get_dof_handler().locally_owned_dofs() ==
                      problem.get_dof_handler().locally_owned_dofs(),
                    ExcInternalError("softening: its tangent numbers the DoFs differently"));
        metric    = std::make_unique<StabilityMetric>(tangent);
        metric_at = copy_positions(design);
      }

      HyperelasticProblem              tangent;
      std::unique_ptr<StabilityMetric> metric;
      /** The positions X of the design whose K_0 the metric holds. */
      DesignConfiguration::Vector metric_at;
    };

    /**
     * Q = 1 / mu for the smallest mu of K(a) phi = mu K_0 phi at the
     * subsection's "Load factor": K the condensed tangent with the follower
     * load, K_0 the StabilityMetric (the shear stiffness at rest). Q is 1 at
     * rest for a volume-preserving mode and grows without bound towards a
     * limit point (mu -> 0), so "Q <= Tolerance" keeps every mode at least
     * 1 / Tolerance as stiff as at rest. A state past a limit point (mu < 0,
     * the factorization has negative pivots) is refused like an inverted
     * design.
     *
     * Its derivatives, for a simple eigenvalue and phi^T K_0 phi = 1:
     *   dmu = phi^T dK phi - mu phi^T dK_0 phi,
     * with K = dR/da of the condensed residual R(a, X), K_0 = dR_0/da at
     * a = 0, by central differences along the mode (step h, |h phi| = 1e-6
     * of the diagonal of the body's bounding box; errors near 1e-7
     * relative, tests/softening):
     *   d/da (phi^T K phi) = [K(a + h phi) - K(a - h phi)] phi / 2h, since
     *     K is symmetric (R is the gradient of the condensed potential, the
     *     follower pressure on the closed cavity included), with the element
     *     pressures p~(u) at a +- h phi (K depends on them, R does not);
     *     a second difference of R instead loses half the digits to rounding;
     *   d/dX (phi^T K phi) = phi^T [dR/dX(a + h phi) - dR/dX(a - h phi)] / 2h
     *     (residual_shape_derivative()), and the same at rest for K_0.
     * The differences need the mode to about 1e-12 (Lanczos to that bound:
     * 40 to 100 steps on the sphere); with 1e-8 the gradient is off by
     * 1e-4. An eigenvalue of multiplicity two (an axisymmetric design) has
     * no derivative: MMA then sees the one Lanczos finds.
     *
     * Cost per design: one more assembly and factorization with 20 to 50
     * Lanczos solves (started from the last design's mode), K_0 assembled
     * again, and for the gradient two more assemblies and four shape
     * derivatives; per mesh, the set-up of a second problem (DoFs,
     * sparsity, the MUMPS analysis) and of K_0's, kept with the design
     * problem (Workspace); memory for a second tangent and its
     * factorization.
     *
     * What it does not do: with "Limit point below a target = follow" a
     * target reached after a snap-through lies on a branch that is stable
     * again, with a finite Q there; the fold below the target is the
     * business of that entry ("refuse"), not of this quantity.
     */
    class Softening : public Quantity
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      Softening(ParameterHandler &, const InputFile &, const std::string &, const double load_factor)
        : Quantity({load_factor})
      {}

      bool
      along_load_path() const override
      {
        return false;
      }

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States              &states,
            Derivatives               *derivatives) const override
      {
        const double load_factor = load_factors()[0];
        Vector       a           = problem.create_vector();
        for (const auto i : a.locally_owned_elements())
          a(i) = (*states[0])(i);
        a.compress(VectorOperation::insert);
        const bool cached = is_cached(a, design);
        if (cached && derivatives == nullptr)
          return 1. / mu;

        auto &workspace = problem.companion<Workspace>(
          [&]() { return std::make_unique<Workspace>(problem, design); });
        HyperelasticProblem &tangent = workspace.tangent;
        const StabilityMetric &metric = *workspace.metric;
        if (!same_positions(workspace.metric_at, design))
          {
            workspace.metric->reassemble();
            workspace.metric_at = copy_positions(design);
          }
        // The element pressures p~(u) of the state, as the differences below
        // use them (Newton leaves them to its tolerance).
        Vector a_p = a;
        tangent.store_pressure(a_p);
        if (!cached)
          {
            // From the last design's mode where the DoFs are the same.
            const bool same_dofs = same_layout(phi, a);
            const auto mode = lowest_eigenvalue(tangent,
                                                a_p,
                                                load_factor,
                                                1e-12,
                                                300,
                                                &metric.matrix(),
                                                same_dofs ? &phi : nullptr);
            AssertThrow(mode.residual < 1e-6,
                        ExcMessage("softening: the softest mode at load factor " +
                                   std::to_string(load_factor) + " did not converge in " +
                                   std::to_string(mode.iterations) +
                                   " Lanczos steps (relative error bound " +
                                   std::to_string(mode.residual) + ")."));
            if (!(mode.value > 0))
              throw StepFailure("softening: the state at load factor " +
                                std::to_string(load_factor) +
                                " is past a limit point (its softest mode has mu = " +
                                std::to_string(mode.value) + " < 0): unstable under pressure.");
            cache(a, design, mode, metric);
          }
        // The differences below need the mode to about 1e-12; one to 1e-8
        // puts the gradient off by 1e-4 (tests/softening).
        if (derivatives != nullptr && mode_residual > 1e-10 &&
            Utilities::MPI::this_mpi_process(a.get_mpi_communicator()) == 0)
          std::cout << "  warning: softening's mode at load factor " << load_factor
                    << " has an error bound of " << mode_residual
                    << " after 300 Lanczos steps; its gradient is approximate" << std::endl;
        if (derivatives == nullptr)
          return 1. / mu;

        // |h phi| = 1e-6 of the body's size.
        const double h = 1e-6 * body_size(problem.get_dof_handler().get_triangulation()) /
                         phi.linfty_norm();
        Vector       shifted = problem.create_vector(), K_phi_plus = problem.create_vector(),
               K_phi_minus = problem.create_vector(), R, P;
        const auto tangent_along = [&](const double s, Vector &K_phi) {
          shifted = a_p;
          shifted.add(s, phi);
          // K(a) is the Hessian of the condensed potential only with the
          // element pressures p~(u) (K_uu depends on them, R does not).
          tangent.store_pressure(shifted);
          tangent.assemble(shifted, load_factor, R, P, true);
          tangent.tangent().vmult(K_phi, phi);
          return residual_shape_derivative(problem, design, shifted, load_factor, phi);
        };
        const Vector dKphi_plus  = tangent_along(h, K_phi_plus);
        const Vector dKphi_minus = tangent_along(-h, K_phi_minus);
        const auto &at_rest        = metric.at_rest_problem();
        const auto  rest_along     = [&](const double s) {
          shifted = 0;
          shifted.add(s, phi);
          return residual_shape_derivative(at_rest, design, shifted, 0., phi);
        };
        const Vector dK0phi_plus  = rest_along(h);
        const Vector dK0phi_minus = rest_along(-h);

        // dQ = -dmu / mu^2.
        const double c = -1. / (mu * mu);
        derivatives->d_da = {K_phi_plus};
        derivatives->d_da[0] -= K_phi_minus;
        derivatives->d_da[0] *= c / (2 * h);
        problem.zero_condensed(derivatives->d_da[0]);
        derivatives->d_dX = dKphi_plus;
        derivatives->d_dX.add(-1., dKphi_minus, -mu, dK0phi_plus);
        derivatives->d_dX.add(mu, dK0phi_minus);
        derivatives->d_dX *= c / (2 * h);
        return 1. / mu;
      }

    private:
      /** Whether the softest mode of the state @p a on the design's
       * positions X is the one of the last evaluation (gradients() follows
       * evaluate() on the same state). */
      bool
      is_cached(const Vector &a, const DesignConfiguration &design) const
      {
        if (!same_layout(cached_a, a))
          return false;
        Vector difference = a;
        difference -= cached_a;
        return difference.linfty_norm() == 0 && same_positions(cached_X, design);
      }

      /** Keeps the mode, normalized to phi^T K_0 phi = 1. */
      void
      cache(const Vector                &a,
            const DesignConfiguration &design,
            const LowestEigenvalue    &mode,
            const StabilityMetric     &metric) const
      {
        cached_a = a;
        cached_X = copy_positions(design);
        mu            = mode.value;
        mode_residual = mode.residual;
        phi           = mode.vector;
        Vector K_0_phi = phi;
        metric.matrix().vmult(K_0_phi, phi);
        phi /= std::sqrt(K_0_phi * phi);
      }

      mutable Vector                      cached_a, phi;
      mutable DesignConfiguration::Vector cached_X;
      mutable double mu = 0, mode_residual = 0;

      /** The diagonal of the bounding box of the mesh's vertices (a scale
       * for the step; the design moves them by at most the design bound). */
      static double
      body_size(const Triangulation<3> &triangulation)
      {
        const auto [lower, upper] =
          GridTools::compute_bounding_box(triangulation).get_boundary_points();
        const MPI_Comm comm = triangulation.get_communicator();
        Point<3>       global_lower, global_upper;
        for (unsigned int d = 0; d < 3; ++d)
          {
            global_lower[d] = Utilities::MPI::min(lower[d], comm);
            global_upper[d] = Utilities::MPI::max(upper[d], comm);
          }
        return global_upper.distance(global_lower);
      }
    };
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(Softening,
                            "softening",
                            "1 / mu for the softest mode phi of K phi = mu K_0 phi at "
                            "\"Load factor\": its shear stiffness at rest (K_0, "
                            "the isochoric metric) over its stiffness there "
                            "(dimensionless; 1 at rest, infinite at a limit "
                            "point; a state past one is refused).")
} // namespace softopt
