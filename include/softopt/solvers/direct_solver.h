#ifndef softopt_solvers_direct_solver_h
#define softopt_solvers_direct_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscksp.h>

namespace softopt
{
  using namespace dealii;

  /**
   * A symmetric (LDL^T) MUMPS factorization through PETSc, kept between
   * solves: factorize() once, then solve() as often as needed (the two
   * arclength solves, the adjoint solves). The symbolic analysis is done
   * on the first factorization and reused for every later one, because the
   * sparsity pattern of a matrix object never changes.
   *
   * Every factorization is checked (MUMPS' INFOG(1)); a failure throws
   * StepFailure with MUMPS' error code instead of returning NaNs.
   */
  class DirectSolver
  {
  public:
    /** subsection "Linear solver": the fill-reducing ordering of MUMPS. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Sets the ordering for every factorization of the run (through
     * PETSc's options database, which MUMPS reads at its analysis). */
    static void
    parse_parameters(ParameterHandler &prm);

    explicit DirectSolver(const MPI_Comm comm);
    ~DirectSolver();

    DirectSolver(const DirectSolver &) = delete;
    DirectSolver &
    operator=(const DirectSolver &) = delete;

    /** Numerical factorization of @p matrix (symbolic analysis once). */
    void
    factorize(const PETScWrappers::MPI::SparseMatrix &matrix);

    /** x = K^{-1} b with the last factorization. */
    void
    solve(const PETScWrappers::MPI::Vector &b,
          PETScWrappers::MPI::Vector       &x) const;

    /**
     * x = K^{-1} b for a @p matrix whose values changed since the last
     * factorization (a nearby tangent: the last Newton step's, the previous
     * design's), by iterative refinement x <- x + F^{-1}(b - K x) to a
     * relative residual of @p tolerance; factorizes @p matrix if there is
     * no factorization or ten refinements do not get there. Returns the
     * number of solves with the factorization.
     */
    unsigned int
    solve_refined(const PETScWrappers::MPI::SparseMatrix &matrix,
                  const PETScWrappers::MPI::Vector       &b,
                  PETScWrappers::MPI::Vector             &x,
                  const double                            tolerance = 1e-12);

    /** Whether a factorization is held. */
    bool
    has_factorization() const;

    /** Negative pivots of the last factorization (MUMPS' INFOG(12)). */
    unsigned int
    n_negative_pivots() const;

    /** How many numerical factorizations were done so far. */
    unsigned int
    n_factorizations() const;

  private:
    MPI_Comm     comm;
    KSP          ksp = nullptr;
    Mat          analyzed_matrix = nullptr;
    unsigned int factorizations = 0;
  };
} // namespace softopt

#endif
