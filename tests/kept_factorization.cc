// Newton steps by GMRES on a kept factorization (subsection "Linear solver",
// Newton steps = kept factorization) against a fresh factorization per step,
// on the inflated sphere octant at nu = 0.4999 (the stiffest material of the
// tests), p = 0.5 mu:
// 1. the load path from zero: the target states of both agree to 1e-8
//    relative, and both match the closed-form stretch;
// 2. a warm start at p = 0.51 mu from the converged state at 0.5 mu (a
//    change of the state like that of a design iteration): GMRES on the
//    factorization kept from the path converges without a new
//    factorization, to the state a fresh factorization per step reaches;
//    then the adjoint solve there (solve_kept, with the tangent at the
//    converged state) gives the solution of a fresh factorization, with
//    |b - K x| <= 1e-10 |b| (a direct solve: 2e-11);
// 3. the fallback: a warm start at 0.55 mu with one GMRES iteration
//    allowed factorizes and lands on the state of fresh factorizations.

#include "sphere.h"

using namespace softopt_tests;

namespace
{
  using State = softopt::HyperelasticProblem::Vector;

  double
  relative_difference(const State &a, const State &b)
  {
    State d = a;
    d -= b;
    return d.l2_norm() / b.l2_norm();
  }

  softopt::DirectSolver::Parameters
  kept(const unsigned int max_iterations)
  {
    softopt::DirectSolver::Parameters p;
    p.keep_factorization = true;
    p.max_iterations     = max_iterations;
    return p;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::PathFollowing path;
  softopt::NewtonSolver  newton;
  ConditionalOStream     quiet(std::cout, false);
  const auto             no_output =
    [](const softopt::PathFollowing::PathPoint &, const auto &) { return std::string(); };

  // 1. The path from zero, each way.
  Sphere direct(1., 2., 0.5, 3., 0.4999, 0.5);
  Sphere krylov(1., 2., 0.5, 3., 0.4999, 0.5);
  krylov.problem->set_linear_solver(kept(20));
  const State a_direct = path.run(*direct.problem, newton, {1.}, no_output, quiet).target_states[0];
  const State a_krylov = path.run(*krylov.problem, newton, {1.}, no_output, quiet).target_states[0];
  const double exact = closed_form_stretch(0.5, 0.5);
  for (const auto *s : {&direct, &krylov})
    {
      const double lambda_a = s->stretch(s == &direct ? a_direct : a_krylov);
      const double error    = std::abs(lambda_a - exact) / (exact - 1);
      deallog << (s == &direct ? "factorize:" : "kept factorization:")
              << " lambda_a = " << lambda_a << ", closed form " << exact
              << (error < 2e-3 ? " (within 0.2%)" : " TOO FAR") << std::endl;
    }
  const double difference = relative_difference(a_krylov, a_direct);
  deallog << "path from zero, kept against factorize: "
          << (difference < 1e-8 ? "agree to 1e-8" : "DIFFER") << std::endl;
  const unsigned int path_factorizations = krylov.problem->get_statistics().n_factorizations;
  deallog << "fewer factorizations on the kept path: "
          << (path_factorizations < direct.problem->get_statistics().n_factorizations ?
                "yes" :
                "NO")
          << std::endl;

  // 2. A warm start at 0.51 mu from the state at 0.5 mu, and an adjoint.
  State warm_direct = a_direct, warm_krylov = a_krylov;
  newton.solve(*direct.problem, warm_direct, 1.02);
  const auto result = newton.solve(*krylov.problem, warm_krylov, 1.02);
  deallog << "warm start: " << result.iterations << " Newton iterations, "
          << krylov.problem->get_statistics().n_factorizations - path_factorizations
          << " factorizations, against factorize: "
          << (relative_difference(warm_krylov, warm_direct) < 1e-8 ? "agree to 1e-8" :
                                                                      "DIFFER")
          << std::endl;

  // The adjoint solve against a fresh factorization of the same tangent.
  State P = krylov.problem->create_vector(), r = P, x = P, x_direct = P;
  krylov.problem->assemble(warm_krylov, 1.02, r, P, true);
  const unsigned int before_adjoint = krylov.problem->get_statistics().n_factorizations;
  krylov.problem->solve_kept(P, x);
  const bool adjoint_kept = krylov.problem->get_statistics().n_factorizations == before_adjoint;
  direct.problem->assemble(warm_krylov, 1.02, r, P, true);
  direct.problem->factorize();
  direct.problem->solve(P, x_direct);
  const auto residual = [&](const State &y) {
    State Ky = P;
    direct.problem->tangent().vmult(Ky, y);
    Ky -= P;
    return Ky.l2_norm() / P.l2_norm();
  };
  deallog << "adjoint solve " << (adjoint_kept ? "on the kept factorization" : "FACTORIZED")
          << ", against a fresh factorization: "
          << (relative_difference(x, x_direct) < 1e-8 ? "agree to 1e-8" : "DIFFER")
          << ", residual "
          << (residual(x) <= 1e-10 ? "<= 1e-10" : "ABOVE 1e-10")
          << std::endl;


  // 3. One GMRES iteration allowed: the steps fall back to factorizing.
  State far_direct = a_direct;
  newton.solve(*direct.problem, far_direct, 1.1);
  krylov.problem->set_linear_solver(kept(1));
  const unsigned int before = krylov.problem->get_statistics().n_factorizations;
  State              fallback = a_krylov;
  newton.solve(*krylov.problem, fallback, 1.1);
  deallog << "fallback: "
          << (krylov.problem->get_statistics().n_factorizations > before ?
                "factorized" :
                "DID NOT FACTORIZE")
          << ", against factorize: "
          << (relative_difference(fallback, far_direct) < 1e-8 ? "agree to 1e-8" : "DIFFER")
          << std::endl;
}
