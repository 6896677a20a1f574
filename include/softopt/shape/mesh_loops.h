#ifndef softopt_shape_mesh_loops_h
#define softopt_shape_mesh_loops_h

#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/cell_nodes.h>
#include <softopt/shape/design_configuration.h>

#include <functional>
#include <vector>

namespace softopt
{
  /**
   * The two loops every integral over the body or its boundary in the
   * design configuration is made of (functionals, shape derivatives): over
   * this rank's cells, and over their faces on given boundaries, each seen
   * by both fields (CellNodes: the displacement of @p problem and the
   * positions of @p design). Collect into vectors with CellNodes'
   * add_to_...() and compress(add) afterwards; sum numbers over the ranks.
   */
  void
  for_each_cell(const HyperelasticProblem                    &problem,
                const DesignConfiguration                    &design,
                const std::function<void(const CellNodes &)> &f);

  /** f(nodes, face) for each face of this rank's cells on a boundary with
   * an id in @p boundary_ids. */
  void
  for_each_boundary_face(const HyperelasticProblem             &problem,
                         const DesignConfiguration             &design,
                         const std::vector<types::boundary_id> &boundary_ids,
                         const std::function<void(const CellNodes &, unsigned int)> &f);
} // namespace softopt

#endif
