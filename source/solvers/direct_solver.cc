#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <softopt/base/step_failure.h>
#include <softopt/solvers/direct_solver.h>
#include <softopt/solvers/petsc_check.h>

#include <deal.II/base/mpi.h>

#include <petscpc.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace softopt
{
  namespace
  {
    /** MUMPS' ICNTL(7) / INFOG(7) code of a fill-reducing ordering. */
    std::string
    ordering_name(const PetscInt code)
    {
      switch (code)
        {
          case 0:
            return "AMD";
          case 2:
            return "AMF";
          case 3:
            return "SCOTCH";
          case 4:
            return "PORD";
          case 5:
            return "METIS";
          case 6:
            return "QAMD";
          default:
            return "ordering " + std::to_string(code);
        }
    }



    /**
     * Says what MUMPS did with the subsection's settings, from the factor
     * @p F of a solver's first factorization: whether its factors go out
     * of core and where ("Out-of-core factors" and "Out-of-core factors
     * above cells" of subsection Linear solver, or Verification; ICNTL(22)
     * read back, so the log shows that the option reached MUMPS, and the
     * system's size, so it shows which factorization: the physics' or the
     * shape filter's), and, once per run, if it used another ordering than
     * "MUMPS ordering" (it falls back to its default, silently, when it was
     * built without the one asked for; Debian's MUMPS has neither METIS nor
     * SCOTCH).
     */
    void
    report_mumps_settings(const Mat F, const MPI_Comm comm)
    {
      const bool root        = Utilities::MPI::this_mpi_process(comm) == 0;
      PetscInt   out_of_core = 0, rows = 0, columns = 0;
      check_petsc(MatMumpsGetIcntl(F, 22, &out_of_core), "MatMumpsGetIcntl");
      check_petsc(MatGetSize(F, &rows, &columns), "MatGetSize");
      const char *directory = std::getenv("MUMPS_OOC_TMPDIR");
      if (root && out_of_core != 0)
        std::cout << "MUMPS writes the factors of a system of " << rows
                  << " unknowns out of core, to "
                  << (directory != nullptr ? directory : "/tmp")
                  << " (MUMPS_OOC_TMPDIR)." << std::endl;

      static bool reported = false;
      if (reported)
        return;
      reported = true;

      PetscInt  requested = 7;
      PetscBool set       = PETSC_FALSE;
      check_petsc(PetscOptionsGetInt(nullptr, nullptr, "-mat_mumps_icntl_7", &requested, &set),
                  "PetscOptionsGetInt");
      PetscInt used = requested;
      check_petsc(MatMumpsGetInfog(F, 7, &used), "MatMumpsGetInfog");
      if (root && set && requested != 7 && used != requested)
        std::cout << "Warning: subsection \"Linear solver\", \"MUMPS ordering\": this "
                  << "MUMPS cannot use " << ordering_name(requested) << " and uses "
                  << ordering_name(used) << " instead." << std::endl;
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
                      "METIS needs a MUMPS built with it (Debian's is not: "
                      "MUMPS then uses PORD, and softopt says so). "
                      "doc/benchmarks.md compares them on the actuator.");
    prm.declare_entry(
      "Newton steps",
      "factorize",
      Patterns::Selection("factorize|kept factorization"),
      "How a Newton step of the physics solves with its tangent. factorize: "
      "a MUMPS factorization of the tangent, except in Newton's quadratic "
      "phase (|r| < 1e-2 |lambda P| after a first step), where GMRES "
      "preconditioned with the last step's factorization replaces it (a "
      "nearby tangent: a few solves instead of a factorization; it factorizes "
      "if GMRES needs more than 'GMRES iterations'). kept factorization: GMRES "
      "preconditioned with the last factorization (of an earlier step, load "
      "step or design), which is replaced only when GMRES needs more than "
      "'GMRES iterations'; it pays where a factorization costs many solves, "
      "on large meshes (doc/benchmarks.md says where each wins). Arclength "
      "steps always factorize (they need the sign of det K); adjoint solves "
      "always use GMRES on the kept factorization.");
    prm.declare_entry("Out-of-core factors",
                      "false",
                      Patterns::Bool(),
                      "MUMPS keeps the factors on disk instead of in memory "
                      "(ICNTL(22) = 1; the physics' and the shape filter's), "
                      "in the directory of the environment "
                      "variable MUMPS_OOC_TMPDIR (default /tmp), and removes "
                      "them at the end (a killed run leaves its mumps_* files "
                      "there). For meshes whose factors do not fit "
                      "in memory, e.g. a verification at 0.8 mm: on the 1.2 mm "
                      "actuator the peak memory fell from 1.16 to 0.73 GB at "
                      "the same speed (doc/benchmarks.md).");
    prm.declare_entry("Out-of-core factors above cells",
                      "0",
                      Patterns::Integer(0),
                      "The factors on disk, as with \"Out-of-core factors = "
                      "true\", on every mesh of more tetrahedra than this (0: "
                      "never by size). For a mesh-size schedule that ends on a "
                      "fine mesh: the coarse meshes keep their factors in "
                      "memory (faster), the fine one writes them to disk "
                      "(on two ranks the contractor's 127,000-tetrahedron "
                      "mesh held over 21 GB with its factors in memory, and "
                      "still 20.6 GB with the physics' on disk: the shape "
                      "filter's are as large). Applies to every "
                      "factorization on such a mesh: the physics' (the "
                      "optimization's, the final analysis's, the "
                      "verification's) and the shape filter's.");
    prm.declare_entry("GMRES tolerance",
                      "1e-6",
                      Patterns::Double(1e-14, 1e-1),
                      "The relative residual |b - K x| / |b| of a Newton "
                      "step's linear solve by GMRES "
                      "(an inexact Newton step; well below Newton's own "
                      "reduction per step, so Newton converges as with a "
                      "factorization).");
    prm.declare_entry("GMRES iterations",
                      "20",
                      Patterns::Integer(1, 500),
                      "GMRES iterations of a Newton step after which the "
                      "kept factorization counts as too far from the "
                      "tangent and the tangent is factorized.");
    prm.leave_subsection();
  }



  DirectSolver::Parameters
  DirectSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const std::string ordering    = prm.get("MUMPS ordering");
    Parameters        parameters;
    parameters.keep_factorization = prm.get("Newton steps") == "kept factorization";
    parameters.tolerance          = prm.get_double("GMRES tolerance");
    parameters.max_iterations     = prm.get_integer("GMRES iterations");
    parameters.out_of_core        = prm.get_bool("Out-of-core factors");
    parameters.out_of_core_above_cells = prm.get_integer("Out-of-core factors above cells");
    prm.leave_subsection();
    const char *icntl7 = ordering == "METIS" ? "5" :
                         ordering == "PORD"  ? "4" :
                         ordering == "AMD"   ? "0" :
                                               "7";
    check_petsc(PetscOptionsSetValue(nullptr, "-mat_mumps_icntl_7", icntl7),
                "PetscOptionsSetValue");
    return parameters;
  }



  void
  DirectSolver::set_out_of_core(const bool on_disk)
  {
    out_of_core = on_disk;
  }



  DirectSolver::DirectSolver(const MPI_Comm comm)
    : comm(comm)
  {}



  DirectSolver::~DirectSolver()
  {
    if (krylov != nullptr)
      KSPDestroy(&krylov);
    if (ksp != nullptr)
      KSPDestroy(&ksp);
  }



  void
  DirectSolver::factorize(const PETScWrappers::MPI::SparseMatrix &matrix)
  {
    const Mat A = static_cast<Mat>(matrix);
    // The tangent is symmetric (Eq. LinMat and the closed-cavity follower
    // load): MUMPS reads the upper triangle and factors LDL^T (SYM = 2).
    check_petsc(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

    if (ksp == nullptr || A != analyzed_matrix)
      {
        if (ksp != nullptr)
          KSPDestroy(&ksp);
        if (krylov != nullptr) // its operators had the old matrix's sizes
          KSPDestroy(&krylov);
        check_petsc(KSPCreate(comm, &ksp), "KSPCreate");
        check_petsc(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
        PC pc;
        check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
        check_petsc(PCSetType(pc, PCCHOLESKY), "PCSetType");
        check_petsc(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS),
                    "PCFactorSetMatSolverType");
        check_petsc(KSPSetOperators(ksp, A, A), "KSPSetOperators");
        check_petsc(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
        Mat F;
        check_petsc(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
        // Working space: 50% above MUMPS' estimate; pivoting on the
        // indefinite tangents past limit points needs more than the default.
        check_petsc(MatMumpsSetIcntl(F, 14, 50), "MatMumpsSetIcntl");
        check_petsc(MatMumpsSetIcntl(F, 22, out_of_core ? 1 : 0), "MatMumpsSetIcntl");
        analyzed_matrix = A;
      }
    else
      check_petsc(KSPSetOperators(ksp, A, A), "KSPSetOperators");

    // KSPSolve would factorize again whenever the matrix changed since
    // (a new tangent assembled for a residual or an adjoint): only
    // factorize() does, so that a kept factorization is really kept.
    check_petsc(KSPSetReusePreconditioner(ksp, PETSC_FALSE), "KSPSetReusePreconditioner");
    check_petsc(KSPSetUp(ksp), "KSPSetUp");
    check_petsc(KSPSetReusePreconditioner(ksp, PETSC_TRUE), "KSPSetReusePreconditioner");
    ++factorizations;

    PC  pc;
    Mat F;
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    if (factorizations == 1)
      report_mumps_settings(F, comm);
    PetscInt info = 0, info2 = 0;
    check_petsc(MatMumpsGetInfog(F, 1, &info), "MatMumpsGetInfog");
    check_petsc(MatMumpsGetInfog(F, 2, &info2), "MatMumpsGetInfog");
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
    check_petsc(KSPSolve(ksp, b, x), "KSPSolve");
    KSPConvergedReason reason;
    check_petsc(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    if (reason < 0)
      throw StepFailure("the solve with the MUMPS factorization failed "
                        "(PETSc KSPConvergedReason " +
                        std::to_string(static_cast<int>(reason)) + ").");
  }



  namespace
  {
    // The preconditioner of the GMRES in solve_krylov: one solve with the
    // kept factorization (the preonly KSP in the shell's context).
    PetscErrorCode
    apply_factorization(PC pc, Vec x, Vec y)
    {
      void *context = nullptr;
      PetscErrorCode code = PCShellGetContext(pc, &context);
      if (code != 0)
        return code;
      return KSPSolve(static_cast<KSP>(context), x, y);
    }
  } // namespace



  DirectSolver::KrylovResult
  DirectSolver::solve_krylov(const PETScWrappers::MPI::SparseMatrix &matrix,
                             const PETScWrappers::MPI::Vector       &b,
                             PETScWrappers::MPI::Vector             &x,
                             const double                            tolerance,
                             const unsigned int                      max_iterations)
  {
    x.reinit(b);
    const auto factorize_and_solve = [&](const unsigned int iterations) {
      Timer timer;
      factorize(matrix);
      const double time = timer.wall_time();
      solve(b, x);
      return KrylovResult{iterations, true, time};
    };
    if (!has_factorization())
      return factorize_and_solve(0);
    if (krylov == nullptr)
      {
        check_petsc(KSPCreate(comm, &krylov), "KSPCreate");
        // Flexible GMRES: right-preconditioned, so it minimizes the true
        // residual b - K x, and it keeps the preconditioned basis, so
        // forming x takes no further solve with the factorization (plain
        // right-preconditioned GMRES spends one more per cycle on it).
        check_petsc(KSPSetType(krylov, KSPFGMRES), "KSPSetType");
        check_petsc(KSPSetPCSide(krylov, PC_RIGHT), "KSPSetPCSide");
        check_petsc(KSPGMRESSetOrthogonalization(krylov,
                                                 KSPGMRESModifiedGramSchmidtOrthogonalization),
                    "KSPGMRESSetOrthogonalization");
        PC pc;
        check_petsc(KSPGetPC(krylov, &pc), "KSPGetPC");
        check_petsc(PCSetType(pc, PCSHELL), "PCSetType");
        check_petsc(PCShellSetApply(pc, apply_factorization), "PCShellSetApply");
      }
    PC pc;
    check_petsc(KSPGetPC(krylov, &pc), "KSPGetPC");
    check_petsc(PCShellSetContext(pc, ksp), "PCShellSetContext");
    const Mat A = static_cast<Mat>(matrix);
    check_petsc(KSPSetOperators(krylov, A, A), "KSPSetOperators");
    // GMRES's residual is a recurrence that drifts from the true b - K x on
    // ill-conditioned tangents (nu near 0.5); a converged solve is checked
    // and, if need be, continued from its result, which recomputes the
    // residual. No restarts within a cycle: GMRES either converges within
    // max_iterations in all or the factorization is replaced.
    const double               goal       = tolerance * b.l2_norm();
    unsigned int               iterations = 0;
    PETScWrappers::MPI::Vector residual(b);
    check_petsc(KSPSetInitialGuessNonzero(krylov, PETSC_FALSE), "KSPSetInitialGuessNonzero");
    for (unsigned int cycle = 0; cycle < 3 && iterations < max_iterations; ++cycle)
      {
        const unsigned int remaining = max_iterations - iterations;
        check_petsc(KSPGMRESSetRestart(krylov, remaining), "KSPGMRESSetRestart");
        check_petsc(KSPSetTolerances(krylov, 0., goal, PETSC_DEFAULT, remaining),
                    "KSPSetTolerances");
        check_petsc(KSPSolve(krylov, b, x), "KSPSolve");
        KSPConvergedReason reason;
        PetscInt           cycle_iterations = 0;
        check_petsc(KSPGetConvergedReason(krylov, &reason), "KSPGetConvergedReason");
        check_petsc(KSPGetIterationNumber(krylov, &cycle_iterations), "KSPGetIterationNumber");
        iterations += cycle_iterations;
        if (reason <= 0)
          break;
        matrix.vmult(residual, x);
        residual.sadd(-1., b);
        if (residual.l2_norm() <= goal)
          return {iterations, false, 0.};
        check_petsc(KSPSetInitialGuessNonzero(krylov, PETSC_TRUE), "KSPSetInitialGuessNonzero");
      }
    return factorize_and_solve(iterations);
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
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    PetscInt n = 0;
    check_petsc(MatMumpsGetInfog(F, 12, &n), "MatMumpsGetInfog");
    return n;
  }



  unsigned int
  DirectSolver::n_factorizations() const
  {
    return factorizations;
  }
} // namespace softopt
