// The volume of a body in its design configuration, for tests that compare
// a mesh with another description of the same body.
#ifndef softopt_tests_body_volume_h
#define softopt_tests_body_volume_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <softopt/shape/design_configuration.h>

namespace softopt_tests
{
  using namespace dealii;

  /** The volume of the body in the design configuration X, in mm^3. */
  inline double
  body_volume(const softopt::DesignConfiguration &design)
  {
    FE_SimplexP<3>         fe(1);
    const QGaussSimplex<3> quadrature(3);
    FEValues<3> fe_values(design.get_mapping(), fe, quadrature, update_JxW_values);
    double      volume = 0;
    for (const auto &cell : design.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // A Triangulation cell: fe is not the DoFHandler's element (only
          // the mapping matters for JxW).
          fe_values.reinit(Triangulation<3>::cell_iterator(cell));
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            volume += fe_values.JxW(q);
        }
    return Utilities::MPI::sum(volume, MPI_COMM_WORLD);
  }
} // namespace softopt_tests

#endif
