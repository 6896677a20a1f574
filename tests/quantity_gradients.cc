// The quantities "point displacement" and "maximum stretch" (plugins of
// softopt/functionals/quantities/) on the sphere octant
// (inputs/sphere_quantities.prm):
// - against closed forms in the affine state u = (F - I) X of a uniaxial
//   isochoric stretch l = 1.2 along y (F = diag(1/sqrt(l), l, 1/sqrt(l))),
//   which the P2 field holds exactly: the maximum stretch is
//   sqrt((l^2 + 2/l)/3) for any exponent, the point displacement
//   u(X_node) . v(X_node) at the surface node TrackedPoints chooses;
// - their adjoint gradients through filter, physics and mesh against a
//   Taylor expansion along a random design direction (rates 2).

#include <deal.II/base/mpi.h>

#include <softopt/app/settings.h>
#include <softopt/functionals/direction_field.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/shape/mesh_loops.h>
#include <softopt/shape/surface_nodes.h>

#include "taylor_test.h"

#include <cmath>

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_quantities.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  const auto            &functionals = problem.functionals();
  const auto            &physics     = problem.hyperelastic_problem();
  const auto            &design      = problem.design_configuration();

  // The affine state: each node's displacement DoFs from its position.
  const double       l = 1.2;
  const Tensor<2, 3> F_minus_I({{1 / std::sqrt(l) - 1, 0, 0},
                                {0, l - 1, 0},
                                {0, 0, 1 / std::sqrt(l) - 1}});
  auto               a = physics.create_vector();
  softopt::for_each_cell(physics, design, [&](const softopt::CellNodes &nodes) {
    const auto X = nodes.design(design.positions());
    for (unsigned int n = 0; n < 10; ++n)
      for (unsigned int c = 0; c < 3; ++c)
        if (a.in_local_range(nodes.displacement_dofs(n)[c]))
          a(nodes.displacement_dofs(n)[c]) = (F_minus_I * X[n])[c];
  });
  a.compress(VectorOperation::insert);

  const double stretch = std::sqrt((l * l + 2 / l) / 3);
  for (const unsigned int k : {1u, 2u})
    {
      // g_2 = Q, f_1 = Q - 1.05
      const double Q = functionals[k]->evaluate_at(physics, design, a) + (k == 2 ? 1.05 : 0.);
      deallog << functionals[k]->name() << " in uniaxial stretch " << l
              << ": |Q - sqrt((l^2 + 2/l)/3)| " << below(Q - stretch, 1e-12) << std::endl;
    }
  const double at_rest = functionals[1]->evaluate_at(physics, design, physics.create_vector());
  deallog << "maximum stretch at rest: |Q - 1| " << below(at_rest - 1, 1e-12) << std::endl;

  const auto node = softopt::nearest_surface_nodes(
    physics, design, design.positions(), {Point<3>(1.2, 1.2, 1.0)})[0];
  const Tensor<1, 3> v = softopt::DirectionFields::create_default("inward radial")
                           ->value(node.position);
  const double expected = (F_minus_I * node.position) * v;
  const double Q        = functionals[0]->evaluate_at(physics, design, a);
  deallog << "point displacement at the node " << node.position << ": |Q - u . v| "
          << below(Q - expected, 1e-12) << std::endl;

  // Taylor test of the adjoint gradients at the initial design.
  softopt::DesignIterate x         = problem.initial_iterate();
  const auto             values    = problem.evaluate(x);
  const auto             gradients = problem.gradients(x);
  taylor_test(problem, x, values, gradients, settings.optimization.design_bound, 7);
}
