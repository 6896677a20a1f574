#include <deal.II/fe/fe.h>

#include <softopt/shape/cell_nodes.h>

namespace softopt
{
  namespace
  {
    std::array<std::array<types::global_dof_index, 3>, 10>
    nodal_dofs(const DoFHandler<3>::active_cell_iterator &cell)
    {
      const FiniteElement<3> &fe = cell->get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      cell->get_dof_indices(dofs);
      std::array<std::array<types::global_dof_index, 3>, 10> result;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto [component, node] = fe.system_to_component_index(i);
          if (component < 3)
            result[node][component] = dofs[i];
        }
      return result;
    }

    NodalVectors
    gather(const std::array<std::array<types::global_dof_index, 3>, 10> &dofs,
           const PETScWrappers::MPI::Vector                             &v)
    {
      NodalVectors values;
      for (unsigned int n = 0; n < 10; ++n)
        for (unsigned int c = 0; c < 3; ++c)
          values[n][c] = v(dofs[n][c]);
      return values;
    }

    void
    scatter_add(const std::array<std::array<types::global_dof_index, 3>, 10> &dofs,
                const NodalVectors                                           &values,
                PETScWrappers::MPI::Vector                                   &v)
    {
      for (unsigned int n = 0; n < 10; ++n)
        for (unsigned int c = 0; c < 3; ++c)
          v(dofs[n][c]) += values[n][c];
    }
  } // namespace



  CellNodes::CellNodes(const DoFHandler<3>::active_cell_iterator &displacement_cell,
                       const DoFHandler<3>::active_cell_iterator &design_cell)
    : displacement_cell(displacement_cell)
    , u_dofs(nodal_dofs(displacement_cell))
    , X_dofs(nodal_dofs(design_cell))
  {}



  NodalVectors
  CellNodes::displacement(const PETScWrappers::MPI::Vector &a) const
  {
    return gather(u_dofs, a);
  }



  NodalVectors
  CellNodes::design(const PETScWrappers::MPI::Vector &X) const
  {
    return gather(X_dofs, X);
  }



  NodalVectors
  CellNodes::deformed(const PETScWrappers::MPI::Vector &a,
                      const PETScWrappers::MPI::Vector &X) const
  {
    NodalVectors       x = design(X);
    const NodalVectors u = displacement(a);
    for (unsigned int n = 0; n < 10; ++n)
      x[n] += u[n];
    return x;
  }



  void
  CellNodes::add_to_displacement(const NodalVectors         &values,
                                 PETScWrappers::MPI::Vector &v) const
  {
    scatter_add(u_dofs, values, v);
  }



  void
  CellNodes::add_to_design(const NodalVectors         &values,
                           PETScWrappers::MPI::Vector &v) const
  {
    scatter_add(X_dofs, values, v);
  }



  const std::array<types::global_dof_index, 3> &
  CellNodes::design_dofs(const unsigned int node) const
  {
    return X_dofs[node];
  }



  const std::array<types::global_dof_index, 3> &
  CellNodes::displacement_dofs(const unsigned int node) const
  {
    return u_dofs[node];
  }



  const DoFHandler<3>::active_cell_iterator &
  CellNodes::cell() const
  {
    return displacement_cell;
  }



  DoFHandler<3>::active_cell_iterator
  same_cell(const DoFHandler<3>::active_cell_iterator &cell,
            const DoFHandler<3>                       &other)
  {
    return DoFHandler<3>::active_cell_iterator(&cell->get_triangulation(),
                                               cell->level(),
                                               cell->index(),
                                               &other);
  }
} // namespace softopt
