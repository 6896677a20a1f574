#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <softopt/functionals/surface_mean.h>

#include <algorithm>

namespace softopt
{
  double
  design_surface_mean(const HyperelasticProblem         &problem,
                      const HyperelasticProblem::Vector &a,
                      const std::function<Tensor<1, 3>(const Point<3> &)> &v)
  {
    const auto      a_ghost = problem.ghosted(a);
    const auto     &ids     = problem.get_geometry().design_boundary_ids;
    FEFaceValues<3> fe_face_values(problem.get_mapping(),
                                   problem.get_fe(),
                                   problem.face_quadrature(),
                                   update_values | update_quadrature_points |
                                     update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, 3>>        u(problem.face_quadrature().size());
    double                           integral = 0, area = 0;
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) !=
                ids.end())
            {
              fe_face_values.reinit(cell, f);
              fe_face_values[displacement].get_function_values(a_ghost, u);
              for (unsigned int q = 0; q < u.size(); ++q)
                {
                  const double dS = fe_face_values.JxW(q);
                  integral += u[q] * v(fe_face_values.quadrature_point(q)) * dS;
                  area += dS;
                }
            }
    area = Utilities::MPI::sum(area, problem.get_communicator());
    AssertThrow(area > 0, ExcMessage("The design surface has zero area."));
    return Utilities::MPI::sum(integral, problem.get_communicator()) / area;
  }
} // namespace softopt
