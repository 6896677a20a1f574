#include <softopt/physics/cell_kernels.h>
#include <softopt/shape/cell_nodes.h>
#include <softopt/shape/residual_shape_derivative.h>

#include <algorithm>

namespace softopt
{
  PETScWrappers::MPI::Vector
  residual_shape_derivative(const HyperelasticProblem        &problem,
                            const DesignConfiguration        &design,
                            const PETScWrappers::MPI::Vector &a,
                            const double                      load_factor,
                            const PETScWrappers::MPI::Vector &mu)
  {
    const ReferenceTetrahedron reference(problem.cell_quadrature(),
                                         problem.face_quadrature());
    const auto  a_ghost  = problem.ghosted(a);
    const auto  mu_ghost = problem.ghosted(mu);
    const auto &X        = design.positions();
    const auto &ids      = problem.get_geometry().pressure_boundary_ids;
    const double p_hat   = load_factor * problem.get_pressure();

    PETScWrappers::MPI::Vector result = design.create_vector();
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const CellNodes    nodes(cell, same_cell(cell, design.get_dof_handler()));
          const NodalVectors u   = nodes.displacement(a_ghost);
          const NodalVectors Xe  = nodes.design(X);
          const NodalVectors m   = nodes.displacement(mu_ghost);
          nodes.add_to_design(CellKernels::condensed_residual_shape_derivative(
                                reference, problem.get_material(), u, Xe, m),
                              result);
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) !=
                  ids.end())
              {
                NodalVectors x = Xe;
                for (unsigned int n = 0; n < 10; ++n)
                  x[n] += u[n];
                nodes.add_to_design(
                  CellKernels::follower_load_derivative(reference, f, p_hat, x, m),
                  result);
              }
        }
    result.compress(VectorOperation::add);
    return result;
  }
} // namespace softopt
