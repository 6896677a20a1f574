#ifndef softopt_io_tracked_points_h
#define softopt_io_tracked_points_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/point.h>

#include <softopt/base/input.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>
#include <softopt/shape/surface_nodes.h>

#include <array>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * Named points of the body's surface whose displacement is recorded along
   * the load path ("Tracked points" of subsection Output), for comparison
   * with markers tracked on video at the bench.
   *
   * Each requested point is replaced by the nearest node of the quadratic
   * mesh (vertex or midside node) on a boundary face, in the design
   * configuration X = X_o + psi at construction. Symmetry planes (Dirichlet
   * boundaries that fix only some components) cut through the body and are
   * not searched; their edges belong to surface faces as well. At a node the
   * P2 displacement is its nodal value, so nothing is interpolated. Under
   * MPI each rank searches its locally owned cells and the nearest node
   * wins (the lowest rank on a tie); every rank then knows its DoFs.
   */
  class TrackedPoints
  {
  public:
    /** Finds the surface node of each point of @p requested (mm).
     * Collective. */
    TrackedPoints(const HyperelasticProblem     &problem,
                  const DesignConfiguration     &design,
                  const std::vector<NamedPoint> &requested);

    /** A requested point and the surface node chosen for it (mm). */
    struct TrackedNode
    {
      std::string name;
      Point<3>    requested;
      /** The node, at X, with its distance, face size and DoFs. */
      SurfaceNode node;

      /** Whether the node is so far from the requested point that the point
       * is probably not on the surface: farther than half the longest edge
       * of its face (a point on a face is never farther than about 0.3 of
       * that from the face's nearest node) or 1 mm, whichever is larger. */
      bool
      far() const;
    };

    /** One line per point: the node chosen and its distance, with a warning
     * for a far() one. */
    void
    print(const ConditionalOStream &out) const;

    /** The columns of tracked_points.csv after step, load_factor and
     * pressure_kPa: per name <name>_X_mm, _Y_mm, _Z_mm (the node) and
     * <name>_ux_mm, _uy_mm, _uz_mm (its displacement). */
    std::vector<std::string>
    csv_columns() const;

    /** The entries of those columns for the state @p a. Collective. */
    std::vector<std::string>
    csv_entries(const HyperelasticProblem::Vector &a) const;

  private:
    std::vector<TrackedNode> nodes;

    /** Per point, the node's three displacement DoFs (on every rank). */
    std::vector<std::array<types::global_dof_index, 3>> dofs;

    /** The displacement u in mm at each node for the state @p a, on every
     * rank. Collective. */
    std::vector<Tensor<1, 3>>
    displacements(const HyperelasticProblem::Vector &a) const;
  };
} // namespace softopt

#endif
