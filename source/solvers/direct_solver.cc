#include <deal.II/base/exceptions.h>

#include <softopt/base/step_failure.h>
#include <softopt/solvers/direct_solver.h>

#include <petscpc.h>

#include <string>

namespace softopt
{
  namespace
  {
    void
    check(const PetscErrorCode code, const char *call)
    {
      AssertThrow(code == 0,
                  ExcMessage(std::string("PETSc call ") + call +
                             " failed with error code " +
                             std::to_string(code) + "."));
    }
  } // namespace



  void
  DirectSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("MUMPS ordering",
                      "automatic",
                      Patterns::Selection("automatic|METIS|PORD|AMD"),
                      "The fill-reducing ordering of MUMPS' analysis "
                      "(ICNTL(7)); automatic lets MUMPS choose (PORD here). "
                      "doc/benchmarks.md compares them on the actuator.");
    prm.leave_subsection();
  }



  void
  DirectSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const std::string ordering = prm.get("MUMPS ordering");
    prm.leave_subsection();
    const char *icntl7 = ordering == "METIS" ? "5" :
                         ordering == "PORD"  ? "4" :
                         ordering == "AMD"   ? "0" :
                                               "7";
    check(PetscOptionsSetValue(nullptr, "-mat_mumps_icntl_7", icntl7),
          "PetscOptionsSetValue");
  }



  DirectSolver::DirectSolver(const MPI_Comm comm)
    : comm(comm)
  {}



  DirectSolver::~DirectSolver()
  {
    if (ksp != nullptr)
      KSPDestroy(&ksp);
  }



  void
  DirectSolver::factorize(const PETScWrappers::MPI::SparseMatrix &matrix)
  {
    const Mat A = static_cast<Mat>(matrix);
    // The tangent is symmetric (Eq. LinMat and the closed-cavity follower
    // load): MUMPS reads the upper triangle and factors LDL^T (SYM = 2).
    check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

    if (ksp == nullptr || A != analyzed_matrix)
      {
        if (ksp != nullptr)
          KSPDestroy(&ksp);
        check(KSPCreate(comm, &ksp), "KSPCreate");
        check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
        PC pc;
        check(KSPGetPC(ksp, &pc), "KSPGetPC");
        check(PCSetType(pc, PCCHOLESKY), "PCSetType");
        check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS),
              "PCFactorSetMatSolverType");
        check(KSPSetOperators(ksp, A, A), "KSPSetOperators");
        check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
        Mat F;
        check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
        // Working space: 50% above MUMPS' estimate; pivoting on the
        // indefinite tangents past limit points needs more than the default.
        check(MatMumpsSetIcntl(F, 14, 50), "MatMumpsSetIcntl");
        analyzed_matrix = A;
      }
    else
      check(KSPSetOperators(ksp, A, A), "KSPSetOperators");

    // KSPSolve would factorize again whenever the matrix changed since
    // (a new tangent assembled for a residual or an adjoint): only
    // factorize() does, so that a kept factorization is really kept.
    check(KSPSetReusePreconditioner(ksp, PETSC_FALSE), "KSPSetReusePreconditioner");
    check(KSPSetUp(ksp), "KSPSetUp");
    check(KSPSetReusePreconditioner(ksp, PETSC_TRUE), "KSPSetReusePreconditioner");
    ++factorizations;

    PC  pc;
    Mat F;
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    PetscInt info = 0, info2 = 0;
    check(MatMumpsGetInfog(F, 1, &info), "MatMumpsGetInfog");
    check(MatMumpsGetInfog(F, 2, &info2), "MatMumpsGetInfog");
    if (info < 0)
      throw StepFailure("the MUMPS factorization failed with INFOG(1) = " +
                        std::to_string(info) +
                        ", INFOG(2) = " + std::to_string(info2) +
                        (info == -10 ? " (the tangent is singular)" : "") +
                        (info == -9 || info == -8 ?
                           " (MUMPS ran out of working space)" :
                           ""));
  }



  void
  DirectSolver::solve(const PETScWrappers::MPI::Vector &b,
                      PETScWrappers::MPI::Vector       &x) const
  {
    Assert(ksp != nullptr, ExcMessage("solve() before factorize()"));
    check(KSPSolve(ksp, b, x), "KSPSolve");
    KSPConvergedReason reason;
    check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    if (reason < 0)
      throw StepFailure("the solve with the MUMPS factorization failed "
                        "(PETSc KSPConvergedReason " +
                        std::to_string(static_cast<int>(reason)) + ").");
  }



  unsigned int
  DirectSolver::solve_refined(const PETScWrappers::MPI::SparseMatrix &matrix,
                              const PETScWrappers::MPI::Vector       &b,
                              PETScWrappers::MPI::Vector             &x,
                              const double                            tolerance)
  {
    if (!has_factorization())
      factorize(matrix);
    PETScWrappers::MPI::Vector r = b, dx = b;
    x.reinit(b);
    const double goal = tolerance * b.l2_norm();
    for (unsigned int step = 1; step <= 10; ++step)
      {
        solve(r, dx);
        x += dx;
        matrix.vmult(r, x);
        r.sadd(-1., b); // r = b - K x
        if (r.l2_norm() <= goal)
          return step;
      }
    factorize(matrix);
    solve(b, x);
    return 11;
  }



  bool
  DirectSolver::has_factorization() const
  {
    return ksp != nullptr;
  }



  unsigned int
  DirectSolver::n_negative_pivots() const
  {
    PC  pc;
    Mat F;
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    PetscInt n = 0;
    check(MatMumpsGetInfog(F, 12, &n), "MatMumpsGetInfog");
    return n;
  }



  unsigned int
  DirectSolver::n_factorizations() const
  {
    return factorizations;
  }
} // namespace softopt
