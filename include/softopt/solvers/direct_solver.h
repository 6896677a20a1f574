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
   * Nearby matrices are solved by GMRES preconditioned with a kept
   * factorization (solve_krylov), the iterative alternative of subsection
   * "Linear solver".
   *
   * Every factorization is checked (MUMPS' INFOG(1)); a failure throws
   * StepFailure with MUMPS' error code instead of returning NaNs.
   */
  class DirectSolver
  {
  public:
    /** subsection "Linear solver": the fill-reducing ordering of MUMPS and
     * how Newton steps solve with their tangent. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** How the Newton steps of the physics solve with their tangent. */
    struct Parameters
    {
      /** false: each step factorizes its tangent; true: GMRES on the kept
       * factorization (solve_krylov). */
      bool keep_factorization = false;
      /** GMRES's relative residual for a Newton step. */
      double tolerance = 1e-6;
      /** GMRES iterations before the kept factorization is replaced. */
      unsigned int max_iterations = 20;
      /** The factors on disk ("Out-of-core factors"). */
      bool out_of_core = false;
      /** The factors on disk on meshes of more tetrahedra than this
       * ("Out-of-core factors above cells"; 0: by out_of_core alone). */
      unsigned long long out_of_core_above_cells = 0;

      /** Whether the factors of a mesh of @p n_cells tetrahedra go on disk. */
      bool
      out_of_core_for(const unsigned long long n_cells) const
      {
        return out_of_core || (out_of_core_above_cells > 0 && n_cells > out_of_core_above_cells);
      }
    };

    /** Reads the subsection; sets the ordering for every factorization of
     * the run (through PETSc's options database, which MUMPS reads at its
     * analysis). */
    static Parameters
    parse_parameters(ParameterHandler &prm);

    /** Whether this solver's factors go out of core (MUMPS' ICNTL(22)),
     * from its next analysis on. */
    void
    set_out_of_core(const bool out_of_core);

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

    /** What solve_krylov() did. */
    struct KrylovResult
    {
      /** GMRES iterations (solves with the factorization). */
      unsigned int iterations = 0;
      /** Whether it factorized @p matrix (no factorization held, or GMRES
       * did not reach the tolerance). */
      bool factorized = false;
      /** Wall time of that factorization, s. */
      double factorization_time = 0;
    };

    /**
     * x = K^{-1} b for a @p matrix whose values changed since the last
     * factorization (a nearby tangent: the last Newton step's, the previous
     * design's) by GMRES preconditioned with the factorization held, to
     * |b - K x| <= @p tolerance |b|. If there is no factorization, or GMRES
     * has not converged after @p max_iterations, factorizes @p matrix and
     * solves with it: a kept factorization serves until the tangents have
     * moved too far from it, and is then replaced.
     */
    KrylovResult
    solve_krylov(const PETScWrappers::MPI::SparseMatrix &matrix,
                 const PETScWrappers::MPI::Vector       &b,
                 PETScWrappers::MPI::Vector             &x,
                 const double                            tolerance = adjoint_tolerance,
                 const unsigned int max_iterations = adjoint_iterations);

    /** The accuracy of adjoint solves (physics and filter): 1e-10, about
     * that of a direct solve at nu = 0.4999 (2e-11), in at most 50 GMRES
     * iterations. */
    static constexpr double       adjoint_tolerance  = 1e-10;
    static constexpr unsigned int adjoint_iterations = 50;

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
    bool         out_of_core     = false;
    unsigned int factorizations = 0;
    /** GMRES on the current matrix, preconditioned by ksp (a PCSHELL). */
    KSP krylov = nullptr;
  };
} // namespace softopt

#endif
