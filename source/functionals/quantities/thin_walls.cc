// A geometric quantity: how far the walls of the design fall below a
// minimum thickness.

#include <deal.II/base/mpi.h>

#include <softopt/functionals/quantity.h>
#include <softopt/shape/wall_thickness.h>

#include <cmath>

namespace softopt
{
  namespace
  {
    /** Whether node @p i of @p wall lies on a smooth part of the surface:
     * not on a symmetry plane, and no triangle around it turned more than
     * 30 degrees from their mean normal. At the part's edges and corners
     * the ray along the mean normal grazes the surface, and its length
     * jumps with the shape; the nodes next to them measure those walls. */
    bool
    smooth_at(const WallThickness &wall, const unsigned int i)
    {
      Tensor<1, 3> mean;
      for (const unsigned int t : wall.around[i])
        {
          if (wall.on_mirror[t])
            return false;
          mean += wall.unit_normal[t];
        }
      for (const unsigned int t : wall.around[i])
        if (wall.unit_normal[t] * mean < std::cos(numbers::PI / 6) * mean.norm())
          return false;
      return true;
    }

    /**
     * Q = 1/N sum_i max(0, 1 - t_i / t_min)^2 over the N nodes i where the
     * surface is smooth (smooth_at(); a node passing 30 degrees changes N,
     * a small jump that MMA takes as it comes), with t_i the wall
     * thickness at node i (the ray along the inward normal to the opposite
     * surface, castability's measure; the nodes: points of the curved
     * faces "Sampling size" apart, their corner and midside nodes by
     * default) and t_min the entry "Minimum
     * thickness". Nodes whose ray reflects at a symmetry plane add
     * nothing (their length has no derivative), nor those whose ray ends
     * at a corner (WallThickness::corner: on a face turned more than 60
     * degrees from facing it, as near a clamped base whose side the
     * design tilts, where the ray leaves through the base). Q is
     * 0 while every wall is at least t_min thick and grows smoothly
     * (continuous derivative) as walls thin below it; with a "Minimum
     * gap" g_min the same sum over the gaps g_i outside the part is
     * added. A mean, not a minimum: with Tolerance 1e-4 a few nodes may
     * fall well below t_min (1e-4 is one node 10 % short in 100). As a
     * constraint (Q <= Tolerance) it keeps the walls near t_min and a
     * mesh's elements across them, where the model converges
     * (doc/theory.md, "Walls the mesh resolves"). It reads no state: it
     * depends on the shape X = X_o + psi only.
     */
    class ThinWalls : public Quantity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Minimum thickness",
                          "1",
                          Patterns::Double(0),
                          "thin walls: the wall thickness t_min below which "
                          "a node counts (mm).");
        prm.declare_entry("Minimum gap",
                          "0",
                          Patterns::Double(0),
                          "thin walls: the gap g_min outside the part (along "
                          "the outward normal to the next surface: between "
                          "the folds of a bellows, a wall of the mold) below "
                          "which a node counts too (mm; 0: gaps are not "
                          "measured). Gaps that close make the surface "
                          "intersect itself, a design that is refused.");
        prm.declare_entry("Sampling size",
                          "0",
                          Patterns::Double(0),
                          "thin walls: how far apart (mm) the points are "
                          "where walls and gaps are measured: each quadratic "
                          "boundary face is split into k x k triangles on its "
                          "curved surface, k the mean boundary edge of the "
                          "mesh over this, rounded up, at least 2 (0: k = 2, "
                          "the faces' corner and midside nodes). A coarse "
                          "mesh's nodes lie a millimetre apart and miss the "
                          "narrow slots a fine mesh shows: sample at least as "
                          "finely as the nodes of the run's finest mesh (half "
                          "its element size apart).");
      }

      ThinWalls(ParameterHandler &prm, const InputFile &input, const std::string &subsection,
                const double)
        : Quantity({})
        , minimum(prm.get_double("Minimum thickness"))
        , minimum_gap(prm.get_double("Minimum gap"))
        , sampling_size(prm.get_double("Sampling size"))
      {
        AssertThrow(minimum > 0,
                    ExcMessage(input.where(subsection, "Minimum thickness") +
                               ": the minimum thickness must be positive (mm)."));
      }

      double
      value(const HyperelasticProblem &problem,
            const DesignConfiguration &design,
            const States &,
            Derivatives *derivatives) const override
      {
        const MPI_Comm comm    = problem.get_communicator();
        const auto     mirrors = problem.get_geometry().symmetry_planes();
        // A gap ray would cross a symmetry plane in the open, where the
        // mirrored part is not: gaps are not measured there.
        AssertThrow(minimum_gap == 0 || mirrors.empty(),
                    ExcMessage("thin walls: \"Minimum gap\" needs a whole part; "
                               "this one has symmetry planes (Dirichlet "
                               "boundaries fixing some components). Set it to 0."));
        // On rank 0, which holds the surface: Q and dQ/dX on the nodes.
        double                               Q = 0;
        std::vector<types::global_dof_index> dofs;
        std::vector<double>                  d_dX;
        const auto add = [&](const WallThickness &wall, const double at_least) {
          if (Utilities::MPI::this_mpi_process(comm) != 0)
            return;
          std::vector<unsigned int> smooth;
          for (unsigned int i = 0; i < wall.nodes.size(); ++i)
            if (smooth_at(wall, i))
              smooth.push_back(i);
          const unsigned int n = smooth.size();
          for (const unsigned int i : smooth)
            {
              const double shortfall = 1 - wall.thickness[i] / at_least;
              // (Nor a ray that ends at a corner: a corner is no wall.)
              if (!std::isfinite(wall.thickness[i]) || shortfall <= 0 || !wall.differentiable[i])
                continue;
              Q += shortfall * shortfall / n;
              if (derivatives == nullptr)
                continue;
              // dQ/dt_i = -2 shortfall / (n t_min)
              const double dQ_dt = -2 * shortfall / (n * at_least);
              // A sample point is sum_a N_a X_a of its face's nodes a.
              for (const auto &[node, dt_dx] : thickness_gradient(wall, i))
                for (const auto &[N_a, dofs_a] : wall.node_dofs[node])
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      dofs.push_back(dofs_a[c]);
                      d_dX.push_back(dQ_dt * N_a * dt_dx[c]);
                    }
            }
        };
        const unsigned int k = surface_subdivisions(design, sampling_size);
        if (minimum_gap > 0)
          {
            const auto [walls, gaps] = walls_and_gaps(design, k);
            add(walls, minimum);
            add(gaps, minimum_gap);
          }
        else
          add(wall_thickness(design, mirrors, false, k), minimum);
        if (derivatives != nullptr)
          {
            derivatives->d_da.clear();
            derivatives->d_dX = design.create_vector();
            if (!dofs.empty()) // rank 0 adds to every rank's entries
              derivatives->d_dX.add(dofs, d_dX);
            derivatives->d_dX.compress(VectorOperation::add);
          }
        return Utilities::MPI::broadcast(comm, Q, 0);
      }

    private:
      const double minimum;
      const double minimum_gap;
      const double sampling_size;
    };
  } // namespace

  SOFTOPT_REGISTER_QUANTITY(ThinWalls,
                            "thin walls",
                            "the mean over the smooth surface nodes of max(0, 1 - t / "
                            "t_min)^2, t the wall thickness there and t_min "
                            "\"Minimum thickness\" (plus the same of the gaps "
                            "outside the part with \"Minimum gap\"); of the "
                            "shape only, 0 while every wall is t_min thick "
                            "(dimensionless).")
} // namespace softopt
