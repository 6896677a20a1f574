#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <softopt/solvers/cell_matrix_scatter.h>
#include <softopt/solvers/petsc_check.h>

#include <algorithm>

namespace softopt
{
  namespace
  {
    /** Index of @p column in the sorted columns of row @p row of a CSR
     * block, or -1. */
    int
    find_in_row(const PetscInt *ia, const PetscInt *ja, const PetscInt row,
                const PetscInt column)
    {
      const PetscInt *begin = ja + ia[row], *end = ja + ia[row + 1];
      const PetscInt *it    = std::lower_bound(begin, end, column);
      return (it != end && *it == column) ? static_cast<int>(it - ja) : -1;
    }
  } // namespace



  void
  CellMatrixScatter::reinit(const unsigned int n_cells)
  {
    first_position.assign(n_cells, -1);
    positions.clear();
  }



  void
  CellMatrixScatter::begin(PETScWrappers::MPI::SparseMatrix &m)
  {
    if (matrix != nullptr) // an assembly left by an exception
      end();
    matrix = m.petsc_matrix();
    // A new nonzero (through the stash of another rank's rows) would shift
    // the kept positions: make it an error instead.
    check_petsc(MatSetOption(matrix, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE),
                "MatSetOption");
    PetscBool assembled = PETSC_FALSE;
    check_petsc(MatAssembled(matrix, &assembled), "MatAssembled");
    if (!assembled)
      {
        check_petsc(MatAssemblyBegin(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
        check_petsc(MatAssemblyEnd(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
      }
    PetscBool is_mpi = PETSC_FALSE, is_seq = PETSC_FALSE;
    check_petsc(PetscObjectTypeCompare((PetscObject)matrix, MATMPIAIJ, &is_mpi),
                "PetscObjectTypeCompare");
    check_petsc(PetscObjectTypeCompare((PetscObject)matrix, MATSEQAIJ, &is_seq),
                "PetscObjectTypeCompare");
    AssertThrow(is_mpi || is_seq,
                ExcMessage("CellMatrixScatter needs an AIJ matrix."));
    if (is_mpi)
      {
        check_petsc(MatMPIAIJGetSeqAIJ(matrix,
                                       &diagonal_block,
                                       &off_diagonal_block,
                                       &off_diagonal_columns),
                    "MatMPIAIJGetSeqAIJ");
        check_petsc(MatGetLocalSize(off_diagonal_block, nullptr, &n_off_diagonal_columns),
                    "MatGetLocalSize");
      }
    else
      {
        diagonal_block     = matrix;
        off_diagonal_block = nullptr;
      }
    check_petsc(MatGetOwnershipRange(matrix, &row_begin, &row_end), "MatGetOwnershipRange");
    check_petsc(MatGetOwnershipRangeColumn(matrix, &column_begin, &column_end),
                "MatGetOwnershipRangeColumn");
    for (const Mat block : {diagonal_block, off_diagonal_block})
      if (block != nullptr)
        {
          PetscInt        n_rows;
          const PetscInt *ia, *ja;
          PetscBool       done = PETSC_FALSE;
          check_petsc(MatGetRowIJ(block, 0, PETSC_FALSE, PETSC_FALSE, &n_rows, &ia, &ja, &done),
                      "MatGetRowIJ");
          AssertThrow(done, ExcMessage("CellMatrixScatter: no CSR structure."));
          (block == diagonal_block ? diagonal_csr : off_diagonal_csr) = {ia, ja};
        }
    n_diagonal_values = diagonal_csr.first[row_end - row_begin];
    check_petsc(MatSeqAIJGetArray(diagonal_block, &diagonal_values), "MatSeqAIJGetArray");
    if (off_diagonal_block != nullptr)
      check_petsc(MatSeqAIJGetArray(off_diagonal_block, &off_diagonal_values),
                  "MatSeqAIJGetArray");
  }



  void
  CellMatrixScatter::find_positions(const unsigned int           cell,
                                    const std::vector<PetscInt> &rows)
  {
    const unsigned int n = rows.size();
    AssertThrow(positions.size() + n * (n + 1) < std::size_t(1) << 31,
                ExcMessage("CellMatrixScatter: too many entries for int."));
    first_position[cell] = positions.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const PetscInt row = rows[i];
        if (row < 0 || row < row_begin || row >= row_end)
          {
            positions.push_back(row < 0 ? skipped : remote);
            positions.insert(positions.end(), n, skipped);
            continue;
          }
        positions.push_back(0); // local
        const PetscInt local_row = row - row_begin;
        for (unsigned int j = 0; j < n; ++j)
          {
            const PetscInt column   = rows[j];
            int            position = not_found;
            if (column < 0)
              position = skipped;
            else if (column >= column_begin && column < column_end)
              position = find_in_row(diagonal_csr.first,
                                     diagonal_csr.second,
                                     local_row,
                                     column - column_begin);
            else if (off_diagonal_block != nullptr)
              {
                const PetscInt *end = off_diagonal_columns + n_off_diagonal_columns;
                const PetscInt *it =
                  std::lower_bound(off_diagonal_columns, end, column);
                if (it != end && *it == column)
                  {
                    position = find_in_row(off_diagonal_csr.first,
                                           off_diagonal_csr.second,
                                           local_row,
                                           it - off_diagonal_columns);
                    if (position >= 0)
                      position += n_diagonal_values;
                  }
              }
            AssertThrow(position != not_found,
                        ExcMessage("CellMatrixScatter: entry (" +
                                   std::to_string(row) + ", " +
                                   std::to_string(column) +
                                   ") is outside the sparsity pattern."));
            positions.push_back(position);
          }
      }
  }



  void
  CellMatrixScatter::add(const unsigned int           cell,
                         const std::vector<PetscInt> &rows,
                         const double                *values)
  {
    Assert(matrix != nullptr, ExcMessage("add() outside begin() and end()"));
    AssertIndexRange(cell, first_position.size());
    if (first_position[cell] < 0)
      find_positions(cell, rows);
    const unsigned int n = rows.size();
    const int         *p = positions.data() + first_position[cell];
    for (unsigned int i = 0; i < n; ++i, p += n + 1, values += n)
      if (p[0] == 0)
        for (unsigned int j = 0; j < n; ++j)
          {
            const int k = p[j + 1];
            if (k >= n_diagonal_values)
              off_diagonal_values[k - n_diagonal_values] += values[j];
            else if (k >= 0)
              diagonal_values[k] += values[j];
          }
      else if (p[0] == remote)
        check_petsc(MatSetValues(matrix, 1, &rows[i], n, rows.data(), values, ADD_VALUES),
                    "MatSetValues");
  }



  void
  CellMatrixScatter::end()
  {
    check_petsc(MatSeqAIJRestoreArray(diagonal_block, &diagonal_values),
                "MatSeqAIJRestoreArray");
    if (off_diagonal_block != nullptr)
      check_petsc(MatSeqAIJRestoreArray(off_diagonal_block, &off_diagonal_values),
                  "MatSeqAIJRestoreArray");
    for (const Mat block : {diagonal_block, off_diagonal_block})
      if (block != nullptr)
        {
          auto     &csr = block == diagonal_block ? diagonal_csr : off_diagonal_csr;
          PetscInt  n_rows;
          PetscBool done;
          check_petsc(MatRestoreRowIJ(block, 0, PETSC_FALSE, PETSC_FALSE, &n_rows,
                                      &csr.first, &csr.second, &done),
                      "MatRestoreRowIJ");
        }
    matrix = diagonal_block = off_diagonal_block = nullptr;
  }



  std::vector<PetscInt>
  petsc_rows(const std::vector<types::global_dof_index> &dof_indices,
             const AffineConstraints<double>            &constraints)
  {
    std::vector<PetscInt> rows(dof_indices.size());
    for (unsigned int i = 0; i < rows.size(); ++i)
      rows[i] = constraints.is_constrained(dof_indices[i]) ?
                  -1 :
                  static_cast<PetscInt>(dof_indices[i]);
    return rows;
  }



  void
  add_constrained_diagonal(PETScWrappers::MPI::SparseMatrix &matrix,
                           const AffineConstraints<double>  &constraints,
                           const IndexSet                   &locally_owned,
                           const double                      abs_diagonal_sum)
  {
    const double diagonal =
      Utilities::MPI::sum(abs_diagonal_sum, matrix.get_mpi_communicator()) /
      matrix.m();
    for (const auto i : locally_owned)
      if (constraints.is_constrained(i))
        check_petsc(MatSetValue(matrix.petsc_matrix(), i, i, diagonal, ADD_VALUES),
                    "MatSetValue");
  }
} // namespace softopt
