// The condensed residual r(a, lambda) of the hyperelastic problem: its tangent
// K (stiffness, condensed pressure and follower-pressure load stiffness) and
// its load vector P = dr/dlambda against central finite differences, at a
// random deformed state of a cube clamped at x = 0 and pressurized at x = 1.
// With the element pressures at p~(u) (r_p = 0), the condensed tangent is
// the exact Jacobian of u -> r_u(u, p~(u)); and one Newton update (condensed
// solve plus the recovery of Eq. statCond1) solves the linearized uncondensed
// system, so a full Newton iteration converges quadratically.

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>

#include <softopt/physics/hyperelastic_problem.h>

#include "tests.h"

using namespace softopt_tests;
using PVector = softopt::HyperelasticProblem::Vector;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  parallel::fullydistributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  make_cube(triangulation, 2);
  softopt::Geometry geometry;
  geometry.dirichlet_boundaries  = {{0, {{true, true, true}}}};
  geometry.pressure_boundary_ids = {1};
  const MappingFE<3>             mapping(FE_SimplexP<3>(1));
  const auto                   material = neo_hookean(1.2, 0.49);
  softopt::HyperelasticProblem problem(triangulation, mapping, geometry, *material, 0.1);
  problem.setup_system();

  // Perturb only displacement DoFs that are not constrained: the element
  // pressures are condensed (identity rows) and the constraints fixed.
  const IndexSet pressure_dofs = DoFTools::extract_dofs(
    problem.get_dof_handler(), ComponentMask({false, false, false, true}));
  auto random_vector = [&](const double scale, const unsigned int seed) {
    PVector v = problem.create_vector();
    for (const auto i : v.locally_owned_elements())
      if (!pressure_dofs.is_element(i))
        v(i) = scale * random(i, seed);
    v.compress(VectorOperation::insert);
    problem.get_constraints().set_zero(v);
    return v;
  };

  PVector       a = random_vector(0.03, 1);
  const PVector direction = random_vector(1., 2);
  problem.store_pressure(a);
  const double lambda = 0.7;
  PVector       r, P, r_plus, r_minus, P_dummy;
  problem.assemble(a, lambda, r, P, true);
  deallog << "min J = " << problem.min_jacobian(a) << std::endl;

  PVector K_direction = problem.create_vector();
  problem.tangent().vmult(K_direction, direction);

  double previous = 0;
  for (const double h : {1e-3, 1e-4, 1e-5})
    {
      PVector a_plus = a, a_minus = a;
      a_plus.add(h, direction);
      a_minus.add(-h, direction);
      problem.store_pressure(a_plus);
      problem.store_pressure(a_minus);
      problem.assemble(a_plus, lambda, r_plus, P_dummy, false);
      problem.assemble(a_minus, lambda, r_minus, P_dummy, false);
      PVector fd = r_plus;
      fd -= r_minus;
      fd *= 1. / (2 * h);
      fd -= K_direction;
      // Central differences: the error falls as h^2 (about 20 h^2 here).
      const double e = fd.l2_norm() / K_direction.l2_norm();
      deallog << "h = " << h << ": |K d - FD| / |K d| = " << below(e, 100 * h * h);
      if (previous > 0)
        deallog << ", " << rate(previous, e, 10 * h, h);
      deallog << std::endl;
      previous = e;
    }

  // The load stiffness alone: the difference of tangents at two load factors.
  problem.assemble(a, 0., r_plus, P_dummy, true);
  PVector K0_direction = problem.create_vector();
  problem.tangent().vmult(K0_direction, direction);
  K_direction -= K0_direction;
  {
    const double h = 1e-5;
    PVector       a_plus = a, a_minus = a, P_plus, P_minus;
    a_plus.add(h, direction);
    a_minus.add(-h, direction);
    problem.assemble(a_plus, lambda, r_plus, P_plus, false);
    problem.assemble(a_minus, lambda, r_minus, P_minus, false);
    PVector fd = P_plus;
    fd -= P_minus;
    fd *= lambda / (2 * h);
    fd -= K_direction;
    deallog << "load stiffness: |lambda K^p d - FD| / |lambda K^p d| = "
            << below(fd.l2_norm() / K_direction.l2_norm(), 1e-9) << std::endl;
  }

  // P = dr/dlambda: r is affine in lambda.
  problem.assemble(a, lambda + 0.1, r_plus, P_dummy, false);
  problem.assemble(a, lambda - 0.1, r_minus, P_dummy, false);
  PVector fd = r_plus;
  fd -= r_minus;
  fd *= 1. / 0.2;
  fd -= P;
  deallog << "|P - FD| / |P| = " << below(fd.l2_norm() / P.l2_norm(), 1e-12)
          << std::endl;

  // Newton from the random state with its element pressures set to zero
  // (so r_p != 0) back to the unloaded state: the residual must fall
  // quadratically. (No load: the load stiffness of the cube's open face is
  // not symmetric; that of a closed cavity is, see follower_pressure.)
  PVector             state = random_vector(0.03, 1), increment;
  std::vector<double> norms;
  for (unsigned int it = 0; it < 6; ++it)
    {
      problem.assemble(state, 0., r, P, true);
      deallog << "Newton " << it << ": |r| = " << error(r.l2_norm())
              << std::endl;
      norms.push_back(r.l2_norm());
      if (r.l2_norm() < 1e-11)
        break;
      problem.factorize();
      r *= -1.;
      problem.solve(r, increment);
      problem.update(state, increment);
    }
  // Quadratic convergence: |r_k+1| <= C |r_k|^2 once in range.
  const unsigned int n = norms.size();
  deallog << "final |r| " << below(norms.back(), 1e-11) << ", |r_" << n - 2
          << "| / |r_" << n - 3 << "|^2 = "
          << below(norms[n - 2] / (norms[n - 3] * norms[n - 3]), 10.) << std::endl;
}
