// States carried to a new mesh (transfer_states, through
// DesignProblem::remesh at a finer size), on the small design problem
// (inputs/sphere_design.prm) with a moved design d = s r (r pseudo-random),
// so that the old cells are curved and X = X_o + psi differs from the mesh
// as read. The old state is set to u = A X with A diagonal (it meets the
// octant's symmetry constraints), with p~ = -K (det(I + A) - 1): isoparametric
// P2 holds u exactly and p~ is constant, so at every new node the carried u
// must equal A X, and every new cell's p~ that constant, to round-off. Then Newton from the carried
// equilibrium states must reach the path from zero's states on the new mesh.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "random_design.h"
#include "tests.h"

using namespace softopt_tests;

namespace
{
  const Tensor<2, 3> A = [] {
    Tensor<2, 3> a;
    a[0][0] = 0.01;
    a[1][1] = -0.02;
    a[2][2] = 0.03;
    return a;
  }();

  /** The nodes of the physics' mesh in the design configuration, with the
   * x, y, z displacement DoFs of each. */
  template <typename F>
  void
  for_each_node(const softopt::HyperelasticProblem &physics, const F &f)
  {
    const auto &fe    = physics.get_fe();
    const auto &nodes = fe.base_element(0).get_unit_support_points();
    FEValues<3> fe_values(physics.get_mapping(), fe, Quadrature<3>(nodes), update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : physics.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int n = 0; n < nodes.size(); ++n)
            f(fe_values.quadrature_point(n),
              std::array<types::global_dof_index, 3>{dofs[fe.component_to_system_index(0, n)],
                                                     dofs[fe.component_to_system_index(1, n)],
                                                     dofs[fe.component_to_system_index(2, n)]});
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_design.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  softopt::DesignIterate x = random_design(problem, settings);
  problem.evaluate(x);
  const auto equilibrium = x.states;
  const auto cells_before =
    problem.hyperelastic_problem().get_dof_handler().get_triangulation().n_global_active_cells();

  // 1. u = A X on the old mesh, carried to a finer one.
  {
    auto &physics = problem.hyperelastic_problem();
    auto  u       = physics.create_vector();
    for_each_node(physics, [&](const Point<3> &X, const std::array<types::global_dof_index, 3> &d) {
      const Tensor<1, 3> value = A * X;
      for (unsigned int c = 0; c < 3; ++c)
        if (u.in_local_range(d[c]))
          u(d[c]) = value[c];
    });
    u.compress(VectorOperation::insert);
    physics.store_pressure(u); // p~ = -K (det(I + A) - 1), carried as it is
    x.states = {{1., u}};
  }
  softopt::DesignIterate linear = x;
  const auto n_outside = problem.remesh(linear, "finer.msh", 0.2);
  const auto &physics   = problem.hyperelastic_problem();
  const auto  cells_after = physics.get_dof_handler().get_triangulation().n_global_active_cells();
  deallog << "new mesh at 0.2 mm: " << (cells_after > 1.5 * cells_before ? "finer" : "NOT FINER")
          << ", " << n_outside << " new points outside the old body" << std::endl;
  const auto u = physics.ghosted(linear.states.at(1.));
  double     largest = 0;
  for_each_node(physics, [&](const Point<3> &X, const std::array<types::global_dof_index, 3> &d) {
    const Tensor<1, 3> value = A * X;
    for (unsigned int c = 0; c < 3; ++c)
      largest = std::max(largest, std::abs(u(d[c]) - value[c]));
  });
  largest = Utilities::MPI::max(largest, MPI_COMM_WORLD);
  deallog << "u = A X at the new nodes: largest error " << below(largest, 1e-10) << " mm"
          << std::endl;
  // p~ = -K (J - 1), J = det(I + A), in every cell.
  const double K = physics.get_material().bulk_modulus;
  const double p = -K * (determinant(unit_symmetric_tensor<3>() + A) - 1);
  double       pressure_error = 0;
  std::vector<types::global_dof_index> dofs(physics.get_fe().n_dofs_per_cell());
  for (const auto &cell : physics.get_dof_handler().active_cell_iterators())
    if (cell->is_locally_owned())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (physics.get_fe().system_to_component_index(i).first == 3)
            pressure_error = std::max(pressure_error, std::abs(u(dofs[i]) - p) / std::abs(p));
      }
  pressure_error = Utilities::MPI::max(pressure_error, MPI_COMM_WORLD);
  deallog << "p~ = -K (det(I + A) - 1) in every cell: largest relative error "
          << below(pressure_error, 1e-10) << std::endl;

  // 2. The equilibrium states carried to a finer mesh: Newton from them
  // reaches the states of the path from zero there (the check from rest).
  softopt::DesignProblem again(settings, MPI_COMM_WORLD);
  softopt::DesignIterate y = again.initial_iterate();
  y.d                      = x.d;
  again.evaluate(y);
  again.remesh(y, "finer_again.msh", 0.2);
  const auto values = again.evaluate(y, true);
  deallog << "Newton from the carried states: "
          << (again.path_report().warm_started ? "converged" : "FAILED") << std::endl;
  const auto &check = again.branch_check();
  deallog << "against the path from zero on the new mesh: "
          << (check ? "largest relative difference " + below(check->difference, 1e-7) :
                      std::string("NOT CHECKED"))
          << std::endl;
  deallog << "functionals on the new mesh: " << (values.size() == 3 ? "three" : "NOT THREE")
          << std::endl;

  // 3. Where each point is found: p~ of every old cell set to the x of its
  // centroid; a new cell's carried p~ must then be the x of a cell around
  // its own centroid, within one old cell's size (0.5 mm at most here).
  {
    softopt::DesignProblem third(settings, MPI_COMM_WORLD);
    softopt::DesignIterate z = third.initial_iterate();
    auto &old_physics        = third.hyperelastic_problem();
    auto  p_tilde            = old_physics.create_vector();
    FEValues<3> centroid(old_physics.get_mapping(), old_physics.get_fe(),
                         Quadrature<3>(Point<3>(0.25, 0.25, 0.25)), update_quadrature_points);
    std::vector<types::global_dof_index> old_dofs(old_physics.get_fe().n_dofs_per_cell());
    for (const auto &cell : old_physics.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          centroid.reinit(cell);
          cell->get_dof_indices(old_dofs);
          p_tilde(old_dofs[old_physics.get_fe().component_to_system_index(3, 0)]) =
            centroid.quadrature_point(0)[0];
        }
    p_tilde.compress(VectorOperation::insert);
    z.states = {{1., p_tilde}};
    third.remesh(z, "finer_third.msh", 0.2);
    const auto &physics = third.hyperelastic_problem();
    const auto  carried = physics.ghosted(z.states.at(1.));
    FEValues<3> new_centroid(physics.get_mapping(), physics.get_fe(),
                             Quadrature<3>(Point<3>(0.25, 0.25, 0.25)), update_quadrature_points);
    std::vector<types::global_dof_index> new_dofs(physics.get_fe().n_dofs_per_cell());
    double worst = 0;
    for (const auto &cell : physics.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          new_centroid.reinit(cell);
          cell->get_dof_indices(new_dofs);
          worst = std::max(worst,
                           std::abs(carried(new_dofs[physics.get_fe().component_to_system_index(3, 0)]) -
                                    new_centroid.quadrature_point(0)[0]));
        }
    worst = Utilities::MPI::max(worst, MPI_COMM_WORLD);
    deallog << "p~ = x of the old cell's centroid, at the new centroids: largest distance "
            << below(worst, 0.5) << " mm" << std::endl;
  }
  return 0;
}
