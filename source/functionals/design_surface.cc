#include <deal.II/base/mpi.h>

#include <softopt/functionals/design_surface.h>
#include <softopt/shape/cell_nodes.h>

#include <algorithm>

namespace softopt
{
  namespace
  {
    bool
    is_in(const std::vector<types::boundary_id> &ids, const types::boundary_id id)
    {
      return std::find(ids.begin(), ids.end(), id) != ids.end();
    }
  } // namespace



  DesignSurfaceIntegrals
  integrate_over_design_surface(const HyperelasticProblem            &problem,
                                const DesignConfiguration            &design,
                                const PETScWrappers::MPI::Vector     &a,
                                const CellKernels::DirectionFunction &v,
                                const bool                            derivatives)
  {
    const ReferenceTetrahedron reference(problem.cell_quadrature(),
                                         problem.face_quadrature());
    const auto  a_ghost = problem.ghosted(a);
    const auto &X       = design.positions();
    const auto &ids     = problem.get_geometry().design_boundary_ids;
    const MPI_Comm comm = problem.get_communicator();

    DesignSurfaceIntegrals result;
    if (derivatives)
      {
        for (auto *w : {&result.d_area_dX, &result.d_linear_dX, &result.d_quadratic_dX})
          w->reinit(design.create_vector());
        for (auto *w : {&result.d_linear_da, &result.d_quadratic_da})
          w->reinit(problem.create_vector());
      }
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && is_in(ids, cell->face(f)->boundary_id()))
            {
              const CellNodes nodes(cell, same_cell(cell, design.get_dof_handler()));
              const auto      m = CellKernels::face_moments(
                reference, f, nodes.displacement(a_ghost), nodes.design(X), v);
              result.area += m.area;
              result.linear += m.linear;
              result.quadratic += m.quadratic;
              if (!derivatives)
                continue;
              nodes.add_to_design(m.d_area_dX, result.d_area_dX);
              nodes.add_to_design(m.d_linear_dX, result.d_linear_dX);
              nodes.add_to_design(m.d_quadratic_dX, result.d_quadratic_dX);
              nodes.add_to_displacement(m.d_linear_du, result.d_linear_da);
              nodes.add_to_displacement(m.d_quadratic_du, result.d_quadratic_da);
            }
    result.area      = Utilities::MPI::sum(result.area, comm);
    result.linear    = Utilities::MPI::sum(result.linear, comm);
    result.quadratic = Utilities::MPI::sum(result.quadratic, comm);
    if (derivatives)
      for (auto *w : {&result.d_area_dX, &result.d_linear_dX, &result.d_quadratic_dX,
                      &result.d_linear_da, &result.d_quadratic_da})
        w->compress(VectorOperation::add);
    return result;
  }



  double
  cavity_volume(const HyperelasticProblem        &problem,
                const DesignConfiguration        &design,
                const PETScWrappers::MPI::Vector &a,
                PETScWrappers::MPI::Vector       *d_da,
                PETScWrappers::MPI::Vector       *d_dX)
  {
    const ReferenceTetrahedron reference(problem.cell_quadrature(),
                                         problem.face_quadrature());
    const auto  a_ghost = problem.ghosted(a);
    const auto &X       = design.positions();
    const auto &ids     = problem.get_geometry().pressure_boundary_ids;
    if (d_da != nullptr)
      d_da->reinit(problem.create_vector());
    if (d_dX != nullptr)
      d_dX->reinit(design.create_vector());

    double       volume = 0;
    NodalVectors d_dx;
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && is_in(ids, cell->face(f)->boundary_id()))
            {
              const CellNodes nodes(cell, same_cell(cell, design.get_dof_handler()));
              NodalVectors    x = nodes.design(X);
              const auto      u = nodes.displacement(a_ghost);
              for (unsigned int n = 0; n < 10; ++n)
                x[n] += u[n];
              const bool derivative = d_da != nullptr || d_dX != nullptr;
              volume += CellKernels::cavity_volume(reference, f, x,
                                                   derivative ? &d_dx : nullptr);
              if (d_da != nullptr)
                nodes.add_to_displacement(d_dx, *d_da);
              if (d_dX != nullptr)
                nodes.add_to_design(d_dx, *d_dX);
            }
    for (auto *w : {d_da, d_dX})
      if (w != nullptr)
        w->compress(VectorOperation::add);
    return Utilities::MPI::sum(volume, problem.get_communicator());
  }
} // namespace softopt
