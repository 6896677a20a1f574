// The follower pressure on the closed cavity of the actuator (Table I,
// coarse mesh): the assembled tangent is symmetric at a deformed state (the
// paper's claim for a uniform pressure on a closed surface), and the load
// vector is the derivative of the cavity volume, P = -p^ dV/du, so the
// pressure load is conservative with potential -lambda p^ V.

#include <deal.II/dofs/dof_tools.h>

#include <softopt/functionals/design_surface.h>
#include <softopt/physics/hyperelastic_problem.h>
#include <softopt/shape/design_configuration.h>

#include "tests.h"

using namespace softopt_tests;
using PVector = softopt::HyperelasticProblem::Vector;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  parallel::fullydistributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  softopt::Geometry                            geometry;
  geometry.mesh_file             = SOURCE_DIR "/../meshes/actuator.geo";
  geometry.mesh_size             = 5;
  geometry.dirichlet_boundaries  = {{1, {{true, true, true}}}};
  geometry.pressure_boundary_ids = {2};
  geometry.design_boundary_ids   = {3};
  const softopt::DesignConfiguration design(triangulation,
                                           geometry.create_triangulation(triangulation));
  const auto material = neo_hookean(1.2, 0.49);
  const double                       p_hat = 0.015;
  softopt::HyperelasticProblem       problem(
    triangulation, design.get_mapping(), geometry, *material, p_hat);
  problem.setup_system();

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
  PVector       a  = random_vector(0.05, 3);
  const PVector d1 = random_vector(1., 4), d2 = random_vector(1., 5);
  problem.store_pressure(a);

  PVector r, P, K_d1 = problem.create_vector(), K_d2 = problem.create_vector();
  problem.assemble(a, 1., r, P, true);
  problem.tangent().vmult(K_d1, d1);
  problem.tangent().vmult(K_d2, d2);
  deallog << "|d2.K d1 - d1.K d2| / |d2.K d1| = "
          << below(std::abs(d2 * K_d1 - d1 * K_d2) / std::abs(d2 * K_d1), 1e-12)
          << std::endl;

  // The load stiffness alone (tangent at lambda = 1 minus at lambda = 0).
  PVector K0_d1 = problem.create_vector(), K0_d2 = problem.create_vector();
  problem.assemble(a, 0., r, P, true);
  problem.tangent().vmult(K0_d1, d1);
  problem.tangent().vmult(K0_d2, d2);
  K_d1 -= K0_d1;
  K_d2 -= K0_d2;
  deallog << "load stiffness alone: |d2.Kp d1 - d1.Kp d2| / |d2.Kp d1| = "
          << below(std::abs(d2 * K_d1 - d1 * K_d2) / std::abs(d2 * K_d1), 1e-10)
          << std::endl;

  // V is a cubic polynomial of u along d1 (P2 surface, exact quadrature), so
  // the five-point stencil is exact up to round-off even for a large step.
  const double h = 1e-2;
  auto         V = [&](const double t) {
    PVector b = a;
    b.add(t, d1);
    return softopt::cavity_volume(problem, design, b);
  };
  const double dV = (8 * (V(h) - V(-h)) - (V(2 * h) - V(-2 * h))) / (12 * h);
  deallog << "P.d = " << P * d1 << ", -p dV/du.d = " << -p_hat * dV
          << ", relative difference "
          << below(std::abs(P * d1 + p_hat * dV) / std::abs(P * d1), 1e-9)
          << std::endl;
  // The kernel's derivative of V (used by the cavity-volume functional).
  PETScWrappers::MPI::Vector dV_da;
  softopt::cavity_volume(problem, design, a, &dV_da);
  deallog << "|dV/du.d - FD| / |FD| = " << below(std::abs(dV_da * d1 - dV) / std::abs(dV), 1e-9)
          << std::endl;
  deallog << "cavity volume at rest: "
          << softopt::cavity_volume(problem, design, problem.create_vector())
          << " mm^3 (cylinder pi r^2 H1 = " << M_PI * 100 * 47 << ")" << std::endl;
}
