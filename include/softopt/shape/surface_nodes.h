#ifndef softopt_shape_surface_nodes_h
#define softopt_shape_surface_nodes_h

#include <deal.II/base/point.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include <array>
#include <vector>

namespace softopt
{
  /** A node of the quadratic mesh (vertex or midside node) on the body's
   * surface, with its degrees of freedom in both fields. */
  struct SurfaceNode
  {
    /** Where it is in the positions searched, in mm. */
    Point<3> position;
    /** Its distance from the point it was found for, in mm. */
    double distance = 0;
    /** The longest edge of its boundary face (of the largest such face). */
    double face_size = 0;
    /** Its three displacement DoFs and its three design DoFs. */
    std::array<types::global_dof_index, 3> displacement_dofs, design_dofs;
  };

  /**
   * For each of @p points (mm), the nearest node on a boundary face of the
   * mesh in @p positions (a ghosted vector on the design DoFs: the design
   * X, or the initial design X_o). Symmetry planes (Dirichlet boundaries
   * that fix only some components) cut through the body and are not
   * searched; their edges belong to surface faces as well. Each rank
   * searches its locally owned cells and the nearest node wins (the lowest
   * rank on a tie), so the result is the same on any number of ranks and on
   * every rank. Throws if the mesh has no surface face. Collective.
   */
  std::vector<SurfaceNode>
  nearest_surface_nodes(const HyperelasticProblem        &problem,
                        const DesignConfiguration        &design,
                        const PETScWrappers::MPI::Vector &positions,
                        const std::vector<Point<3>>      &points);

  /** The three entries @p dofs of @p v (owned by any rank), on every rank.
   * Collective. */
  Tensor<1, 3>
  nodal_value(const PETScWrappers::MPI::Vector             &v,
              const std::array<types::global_dof_index, 3> &dofs);
} // namespace softopt

#endif
