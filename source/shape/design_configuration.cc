#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <softopt/shape/design_configuration.h>

#include <limits>

namespace softopt
{
  DesignConfiguration::DesignConfiguration(const Triangulation<3> &triangulation,
                                           const EdgeMidpoints    &edge_midpoints)
    : fe(FE_SimplexP<3>(2), 3)
    , dof_handler(triangulation)
  {
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    const MPI_Comm comm = triangulation.get_communicator();
    X_o.reinit(locally_owned_dofs, comm);
    psi.reinit(locally_owned_dofs, comm);
    X.reinit(locally_owned_dofs, locally_relevant_dofs, comm);
    X_o_ghosted.reinit(locally_owned_dofs, locally_relevant_dofs, comm);
    softopt::initial_coordinates(dof_handler, edge_midpoints, X_o);
    update_positions();
    mapping = std::make_unique<MappingFEField<3, 3, Vector>>(dof_handler, X);
    initial_mapping =
      std::make_unique<MappingFEField<3, 3, Vector>>(dof_handler, X_o_ghosted);
  }



  const Mapping<3> &
  DesignConfiguration::get_mapping() const
  {
    return *mapping;
  }



  const Mapping<3> &
  DesignConfiguration::get_initial_mapping() const
  {
    return *initial_mapping;
  }



  const DesignConfiguration::Vector &
  DesignConfiguration::positions() const
  {
    return X;
  }



  const DoFHandler<3> &
  DesignConfiguration::get_dof_handler() const
  {
    return dof_handler;
  }



  DesignConfiguration::Vector
  DesignConfiguration::create_vector() const
  {
    return Vector(locally_owned_dofs, X_o.get_mpi_communicator());
  }



  DesignConfiguration::Vector
  DesignConfiguration::ghosted(const Vector &v) const
  {
    Vector g(locally_owned_dofs, locally_relevant_dofs, X_o.get_mpi_communicator());
    g = v;
    return g;
  }



  const DesignConfiguration::Vector &
  DesignConfiguration::initial_coordinates() const
  {
    return X_o;
  }



  const DesignConfiguration::Vector &
  DesignConfiguration::shape_field() const
  {
    return psi;
  }



  void
  DesignConfiguration::set_shape_field(const Vector &new_psi)
  {
    psi = new_psi;
    update_positions();
  }



  void
  DesignConfiguration::update_mesh()
  {
    X_o += psi;
    psi = 0;
    update_positions();
  }



  void
  DesignConfiguration::set_configuration(const Vector &initial_coordinates,
                                         const Vector &new_psi)
  {
    X_o = initial_coordinates;
    psi = new_psi;
    update_positions();
  }



  void
  DesignConfiguration::update_positions()
  {
    // X is ghosted: assemble X_o + psi in an owned vector, then copy.
    Vector sum = X_o;
    sum += psi;
    X           = sum;
    X_o_ghosted = X_o;
  }



  double
  DesignConfiguration::min_jacobian(const Quadrature<3> &quadrature) const
  {
    FE_SimplexP<3> scalar(1);
    FEValues<3>    fe_values(*mapping, scalar, quadrature, update_jacobians);
    double         J_min = std::numeric_limits<double>::max();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // A Triangulation cell: scalar is not the DoFHandler's element
          // (only the mapping matters for J).
          fe_values.reinit(Triangulation<3>::cell_iterator(cell));
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            J_min = std::min(J_min, fe_values.jacobian(q).determinant());
        }
    return Utilities::MPI::min(J_min, dof_handler.get_communicator());
  }
} // namespace softopt
