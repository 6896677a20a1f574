#ifndef softopt_shape_cell_nodes_h
#define softopt_shape_cell_nodes_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/physics/cell_kernels.h>

namespace softopt
{
  /**
   * One cell seen by both fields on the mesh: the displacement of the
   * hyperelastic problem (the first three components of its FESystem) and
   * the design positions X = X_o + psi. Gathers their nodal vectors, in the
   * node order of the P2 base element, and scatters nodal derivatives back
   * into global vectors.
   */
  class CellNodes
  {
  public:
    /** @p displacement_cell and @p design_cell are the same cell of one
     * triangulation on the two DoFHandlers. */
    CellNodes(const DoFHandler<3>::active_cell_iterator &displacement_cell,
              const DoFHandler<3>::active_cell_iterator &design_cell);

    /** Nodal values of a (ghosted) vector on the displacement DoFs. */
    NodalVectors
    displacement(const PETScWrappers::MPI::Vector &a) const;

    /** Nodal values of a (ghosted) vector on the design DoFs. */
    NodalVectors
    design(const PETScWrappers::MPI::Vector &X) const;

    /** The deformed positions x = X + u of the nodes, from (ghosted)
     * vectors on the displacement DoFs (@p a) and design DoFs (@p X). */
    NodalVectors
    deformed(const PETScWrappers::MPI::Vector &a, const PETScWrappers::MPI::Vector &X) const;

    /** Adds nodal values to a vector on the displacement DoFs
     * (compress(add) afterwards). */
    void
    add_to_displacement(const NodalVectors &values,
                        PETScWrappers::MPI::Vector &v) const;

    /** Adds nodal values to a vector on the design DoFs. */
    void
    add_to_design(const NodalVectors &values, PETScWrappers::MPI::Vector &v) const;

    /** The three displacement DoFs of node @p node. */
    const std::array<types::global_dof_index, 3> &
    displacement_dofs(const unsigned int node) const;

    /** The three design DoFs of node @p node. */
    const std::array<types::global_dof_index, 3> &
    design_dofs(const unsigned int node) const;

    /** The cell on the displacement DoFHandler. */
    const DoFHandler<3>::active_cell_iterator &
    cell() const;

  private:
    DoFHandler<3>::active_cell_iterator                   displacement_cell;
    std::array<std::array<types::global_dof_index, 3>, 10> u_dofs, X_dofs;
  };

  /** The cell of @p other on the same triangulation as @p cell. */
  DoFHandler<3>::active_cell_iterator
  same_cell(const DoFHandler<3>::active_cell_iterator &cell,
            const DoFHandler<3>                       &other);
} // namespace softopt

#endif
