#include <softopt/physics/cell_kernels.h>
#include <softopt/shape/mesh_loops.h>
#include <softopt/shape/residual_shape_derivative.h>

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
    const auto   a_ghost  = problem.ghosted(a);
    const auto   mu_ghost = problem.ghosted(mu);
    const auto  &X        = design.positions();
    const double p_hat    = load_factor * problem.get_pressure();

    PETScWrappers::MPI::Vector result = design.create_vector();
    // The condensed element residual (Eq. statCond2) ...
    for_each_cell(problem, design, [&](const CellNodes &nodes) {
      nodes.add_to_design(CellKernels::condensed_residual_shape_derivative(
                            reference,
                            problem.get_material(),
                            nodes.displacement(a_ghost),
                            nodes.design(X),
                            nodes.displacement(mu_ghost)),
                          result);
    });
    // ... and the follower load, a function of x = X + u only.
    for_each_boundary_face(
      problem,
      design,
      problem.get_geometry().pressure_boundary_ids,
      [&](const CellNodes &nodes, const unsigned int face) {
        nodes.add_to_design(CellKernels::follower_load_derivative(reference,
                                                                  face,
                                                                  p_hat,
                                                                  nodes.deformed(a_ghost, X),
                                                                  nodes.displacement(mu_ghost)),
                            result);
      });
    result.compress(VectorOperation::add);
    return result;
  }
} // namespace softopt
