#ifndef softopt_solvers_cell_matrix_scatter_h
#define softopt_solvers_cell_matrix_scatter_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>

#include <petscmat.h>

#include <utility>
#include <vector>

namespace softopt
{
  using namespace dealii;

  /**
   * Adds cell matrices into a PETSc AIJ matrix at positions found once per
   * cell and sparsity pattern. PETSc's MatSetValues searches every entry's
   * column in its row: about 30 ns an entry, half of the physics' tangent
   * assembly and 60 % of the shape filter's on the 4 mm gripper. With the
   * positions kept (4 bytes an entry) an entry is one indexed addition.
   *
   * Rows owned by another rank go through MatSetValues (PETSc's stash), so
   * the caller compresses the matrix afterwards as usual. Between begin()
   * and end() nothing else may write into the matrix.
   */
  class CellMatrixScatter
  {
  public:
    /** Forgets all positions: call whenever the matrix gets a new sparsity
     * pattern. @p n_cells bounds the cell numbers passed to add(). */
    void
    reinit(unsigned int n_cells);

    /** Starts adding into @p matrix (assembled, with its final pattern). */
    void
    begin(PETScWrappers::MPI::SparseMatrix &matrix);

    /** matrix(rows[i], rows[j]) += values[i * n + j], n = rows.size(); a
     * negative row number drops that row and column (as PETSc does). The
     * positions of cell @p cell are found on its first add() and must not
     * change their row numbers afterwards. */
    void
    add(unsigned int cell, const std::vector<PetscInt> &rows, const double *values);

    /** Ends adding: hands the values back to PETSc. */
    void
    end();

  private:
    /** Where the entries of a cell go: for each row, whether it is local
     * (then its n positions in the local values follow) or another
     * rank's. */
    void
    find_positions(unsigned int cell, const std::vector<PetscInt> &rows);

    static constexpr int not_found = -1;
    static constexpr int skipped   = -2;
    static constexpr int remote    = -3;

    std::vector<int> first_position; // per cell, into positions; -1: none
    std::vector<int> positions;

    Mat            matrix = nullptr;
    Mat            diagonal_block = nullptr, off_diagonal_block = nullptr;
    const PetscInt *off_diagonal_columns = nullptr; // global, ascending
    PetscInt        n_off_diagonal_columns = 0;
    PetscInt        row_begin = 0, row_end = 0, column_begin = 0, column_end = 0;
    /** The blocks' row starts and column numbers (local, ascending). */
    std::pair<const PetscInt *, const PetscInt *> diagonal_csr, off_diagonal_csr;
    PetscScalar    *diagonal_values = nullptr, *off_diagonal_values = nullptr;
    PetscInt        n_diagonal_values = 0;
  };

  /** PETSc row numbers of a cell's DoFs: -1 for a constrained one, so that
   * its row and column are dropped (homogeneous constraints only). */
  std::vector<PetscInt>
  petsc_rows(const std::vector<types::global_dof_index> &dof_indices,
             const AffineConstraints<double>            &constraints);

  /** The rows petsc_rows() dropped get a diagonal entry of the mean size of
   * all diagonal entries (@p abs_diagonal_sum: this rank's sum of
   * |cell matrix(i, i)|), so that the factorization sees a well-scaled
   * identity there. Before compressing @p matrix. */
  void
  add_constrained_diagonal(PETScWrappers::MPI::SparseMatrix &matrix,
                           const AffineConstraints<double>  &constraints,
                           const IndexSet                   &locally_owned,
                           double                            abs_diagonal_sum);
} // namespace softopt

#endif
