// CellMatrixScatter against PETSc's MatSetValues: random cell matrices of a
// P2 vector field on the cube cut into tetrahedra, with the DoFs on x = 0
// constrained (row and column -1), added into two matrices with the same
// sparsity pattern, one each way. Twice, so that the second assembly runs
// on the positions found in the first. The matrices must agree to
// round-off (the sums run in another order), which also covers the rows
// another rank owns (mpirun=2). An entry outside the pattern is refused.

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <softopt/solvers/cell_matrix_scatter.h>

#include "tests.h"

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  parallel::fullydistributed::Triangulation<3> triangulation(comm);
  make_cube(triangulation, 3);
  const FESystem<3> fe(FE_SimplexP<3>(2), 3);
  DoFHandler<3>     dofs(triangulation);
  dofs.distribute_dofs(fe);
  const IndexSet owned = dofs.locally_owned_dofs();
  IndexSet       relevant;
  DoFTools::extract_locally_relevant_dofs(dofs, relevant);

  AffineConstraints<double> constraints(relevant);
  std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
  for (const auto &cell : dofs.active_cell_iterators())
    if (!cell->is_artificial())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 0)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (const auto i : face_dofs)
              if (relevant.is_element(i))
                constraints.add_line(i);
          }
  constraints.close();

  DynamicSparsityPattern dsp(relevant);
  DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
  SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
  PETScWrappers::MPI::SparseMatrix scattered, reference;
  scattered.reinit(owned, owned, dsp, comm);
  reference.reinit(owned, owned, dsp, comm);

  softopt::CellMatrixScatter scatter;
  scatter.reinit(triangulation.n_active_cells());
  const unsigned int                   n = fe.n_dofs_per_cell();
  std::vector<types::global_dof_index> dof_indices(n);
  std::vector<double>                  values(n * n);
  unsigned int                         n_remote_rows = 0;
  for (unsigned int assembly = 0; assembly < 2; ++assembly)
    {
      scattered = 0;
      reference = 0;
      scatter.begin(scattered);
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dof_indices);
            const std::vector<PetscInt> rows =
              softopt::petsc_rows(dof_indices, constraints);
            for (unsigned int k = 0; k < n * n; ++k)
              values[k] = random(cell->id().get_coarse_cell_id() * n * n + k,
                                 assembly + 1);
            scatter.add(cell->active_cell_index(), rows, values.data());
            AssertThrow(MatSetValues(reference.petsc_matrix(), n, rows.data(), n,
                                     rows.data(), values.data(), ADD_VALUES) == 0,
                        ExcInternalError());
            if (assembly == 0)
              for (const auto i : dof_indices)
                n_remote_rows += !owned.is_element(i);
          }
      scatter.end();
      scattered.compress(VectorOperation::add);
      reference.compress(VectorOperation::add);

      const double norm = reference.frobenius_norm();
      reference.add(-1., scattered);
      deallog << "assembly " << assembly + 1 << ": |A| = " << norm
              << ", |A_scattered - A_MatSetValues| / |A| below 1e-14: "
              << (reference.frobenius_norm() <= 1e-14 * norm ? "yes" : "no")
              << std::endl;
    }
  const unsigned int remote = Utilities::MPI::sum(n_remote_rows, comm);
  deallog << "rows added on a rank that does not own them: "
          << (Utilities::MPI::n_mpi_processes(comm) > 1 ? (remote > 0 ? "some" : "none") :
                                                          "none (one rank)")
          << std::endl;

  // An entry outside the pattern: a row of a cell at x > 2/3 with the
  // column of a constrained DoF (at x = 0) that this rank owns.
  bool                     refused = false;
  types::global_dof_index  fixed   = numbers::invalid_dof_index;
  for (const auto i : owned)
    if (constraints.is_constrained(i))
      {
        fixed = i;
        break;
      }
  for (const auto &cell : dofs.active_cell_iterators())
    if (fixed != numbers::invalid_dof_index && cell->is_locally_owned() &&
        cell->center()[0] > 2. / 3.)
      {
        softopt::CellMatrixScatter other;
        other.reinit(triangulation.n_active_cells());
        other.begin(scattered);
        cell->get_dof_indices(dof_indices);
        const std::vector<PetscInt> rows = {static_cast<PetscInt>(dof_indices[0]),
                                            static_cast<PetscInt>(fixed)};
        const std::vector<double>   ones(4, 1.);
        try
          {
            other.add(cell->active_cell_index(), rows, ones.data());
          }
        catch (const std::exception &e)
          {
            refused = std::string(e.what()).find("outside the sparsity pattern") !=
                      std::string::npos;
          }
        other.end();
        break;
      }
  deallog << "an entry outside the pattern is refused: "
          << (Utilities::MPI::logical_or(refused, comm) ? "yes" : "no") << std::endl;
}
