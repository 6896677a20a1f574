#ifndef softopt_shape_design_configuration_h
#define softopt_shape_design_configuration_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe_field.h>
#include <deal.II/lac/petsc_vector.h>

#include <softopt/geometry/geometry.h>

#include <memory>

namespace softopt
{
  /**
   * The design configuration of Section 3: the positions X = X_o + psi of
   * the nodes of the quadratic mesh, as a P2 vector field, and the
   * MappingFEField they drive. X_o are the initial design coordinates (the
   * mesh as read, curved through gmsh's midside nodes), psi the shape field.
   * Physics runs on get_mapping() and never sees psi.
   */
  class DesignConfiguration
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    /** X_o from the mesh @p triangulation and its curved @p edge_midpoints
     * (both from Geometry::create_triangulation()), psi = 0. */
    DesignConfiguration(const Triangulation<3> &triangulation,
                        const EdgeMidpoints    &edge_midpoints);

    /** The mapping X(xi) of the current design. */
    const Mapping<3> &
    get_mapping() const;

    /** The mapping X_o(xi) of the initial design Omega_o (the shape filter
     * lives there). */
    const Mapping<3> &
    get_initial_mapping() const;

    /** X = X_o + psi, ghosted (the positions the mapping reads). */
    const Vector &
    positions() const;

    /** The P2 vector DoFs of X_o, psi and d. */
    const DoFHandler<3> &
    get_dof_handler() const;

    /** A zero vector on get_dof_handler() (locally owned entries). */
    Vector
    create_vector() const;

    /** A ghosted copy of @p v. */
    Vector
    ghosted(const Vector &v) const;

    /** X_o in mm. */
    const Vector &
    initial_coordinates() const;

    /** psi in mm. */
    const Vector &
    shape_field() const;

    /** Sets psi, and X = X_o + psi for the mapping. */
    void
    set_shape_field(const Vector &psi);

    /** The mesh update of Section 5: X_o <- X_o + psi and psi <- 0, which
     * leaves X (the geometry) unchanged. */
    void
    update_mesh();

    /** Sets X_o and psi (a restart from a checkpoint). */
    void
    set_configuration(const Vector &initial_coordinates, const Vector &psi);

    /** The smallest Jacobian determinant det(dX/dxi) over the quadrature
     * points of @p quadrature (negative: an inverted element). */
    double
    min_jacobian(const Quadrature<3> &quadrature) const;

  private:
    void
    update_positions();

    FESystem<3>   fe;
    DoFHandler<3> dof_handler;
    IndexSet      locally_owned_dofs;
    IndexSet      locally_relevant_dofs;
    Vector        X_o;
    Vector        psi;
    Vector        X;
    Vector        X_o_ghosted;
    std::unique_ptr<MappingFEField<3, 3, Vector>> mapping;
    std::unique_ptr<MappingFEField<3, 3, Vector>> initial_mapping;
  };
} // namespace softopt

#endif
