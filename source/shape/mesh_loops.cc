#include <softopt/shape/mesh_loops.h>

namespace softopt
{
  void
  for_each_cell(const HyperelasticProblem                    &problem,
                const DesignConfiguration                    &design,
                const std::function<void(const CellNodes &)> &f)
  {
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        f(CellNodes(cell, same_cell(cell, design.get_dof_handler())));
  }



  void
  for_each_boundary_face(const HyperelasticProblem             &problem,
                         const DesignConfiguration             &design,
                         const std::vector<types::boundary_id> &boundary_ids,
                         const std::function<void(const CellNodes &, unsigned int)> &f)
  {
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              is_in(boundary_ids, cell->face(face)->boundary_id()))
            f(CellNodes(cell, same_cell(cell, design.get_dof_handler())), face);
  }
} // namespace softopt
