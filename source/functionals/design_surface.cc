#include <deal.II/base/mpi.h>

#include <softopt/functionals/design_surface.h>
#include <softopt/physics/nodal_ad.h>
#include <softopt/shape/mesh_loops.h>

namespace softopt
{
  namespace
  {
    using namespace NodalAD;

    /** On face f in the configuration X: the area int dS, int u . v dS and
     * int (u . v)^2 dS (the integrals of Eqs. g0 and constraint), with their
     * derivatives in u and X (the latter by AD, through dS and v(X)). */
    struct FaceMoments
    {
      double       area = 0, linear = 0, quadratic = 0;
      NodalVectors d_area_dX{}, d_linear_dX{}, d_quadratic_dX{};
      NodalVectors d_linear_du{}, d_quadratic_du{};
    };

    FaceMoments
    face_moments(const ReferenceTetrahedron &reference,
                 const unsigned int          face,
                 const NodalVectors         &u,
                 const NodalVectors         &X_values,
                 const DirectionField       &v)
    {
      FaceMoments          result;
      const Nodes<AD>      X = independent(X_values);
      std::array<AD, 3>    m{{0., 0., 0.}};
      for (const auto &point : reference.face_points[face])
        {
          const Tensor<1, 3, AD> n  = area_normal(reference, face, point, X);
          const AD               dS = sqrt(n * n) * point.weight;
          const Tensor<1, 3, AD> Xq = interpolate(point, X);
          Point<3>               X_value;
          for (unsigned int i = 0; i < 3; ++i)
            X_value[i] = value_of(Xq[i]);
          // v(X) to first order about X_value carries the exact first
          // derivative: the problem-specific dv/dpsi of Eq. g0sens.
          const Tensor<1, 3> v0 = v.value(X_value);
          const Tensor<2, 3> G  = v.gradient(X_value);
          Tensor<1, 3, AD>   v_q;
          for (unsigned int i = 0; i < 3; ++i)
            {
              v_q[i] = v0[i];
              for (unsigned int j = 0; j < 3; ++j)
                v_q[i] += G[i][j] * (Xq[j] - X_value[j]);
            }
          Tensor<1, 3> u_q;
          for (unsigned int a = 0; a < 10; ++a)
            u_q += point.values[a] * u[a];
          const AD s = u_q * v_q;
          m[0] += dS;
          m[1] += s * dS;
          m[2] += s * s * dS;
          for (unsigned int a = 0; a < 10; ++a)
            {
              const double w = point.values[a] * value_of(dS);
              result.d_linear_du[a] += w * v0;
              result.d_quadratic_du[a] += 2. * value_of(s) * w * v0;
            }
        }
      result.area           = m[0].val();
      result.linear         = m[1].val();
      result.quadratic      = m[2].val();
      result.d_area_dX      = derivatives(m[0]);
      result.d_linear_dX    = derivatives(m[1]);
      result.d_quadratic_dX = derivatives(m[2]);
      return result;
    }
  } // namespace



  DesignSurfaceIntegrals
  integrate_over_design_surface(const HyperelasticProblem        &problem,
                                const DesignConfiguration        &design,
                                const PETScWrappers::MPI::Vector &a,
                                const DirectionField             &v,
                                const bool                        derivatives)
  {
    const ReferenceTetrahedron reference(problem.cell_quadrature(),
                                         problem.face_quadrature());
    const auto     a_ghost = problem.ghosted(a);
    const auto    &X       = design.positions();
    const MPI_Comm comm    = problem.get_communicator();

    DesignSurfaceIntegrals result;
    if (derivatives)
      {
        for (auto *w : {&result.d_area_dX, &result.d_linear_dX, &result.d_quadratic_dX})
          w->reinit(design.create_vector());
        for (auto *w : {&result.d_linear_da, &result.d_quadratic_da})
          w->reinit(problem.create_vector());
      }
    for_each_boundary_face(
      problem,
      design,
      problem.get_geometry().design_boundary_ids,
      [&](const CellNodes &nodes, const unsigned int face) {
        const auto m =
          face_moments(reference, face, nodes.displacement(a_ghost), nodes.design(X), v);
        result.area += m.area;
        result.linear += m.linear;
        result.quadratic += m.quadratic;
        if (!derivatives)
          return;
        nodes.add_to_design(m.d_area_dX, result.d_area_dX);
        nodes.add_to_design(m.d_linear_dX, result.d_linear_dX);
        nodes.add_to_design(m.d_quadratic_dX, result.d_quadratic_dX);
        nodes.add_to_displacement(m.d_linear_du, result.d_linear_da);
        nodes.add_to_displacement(m.d_quadratic_du, result.d_quadratic_da);
      });
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
    if (d_da != nullptr)
      d_da->reinit(problem.create_vector());
    if (d_dX != nullptr)
      d_dX->reinit(design.create_vector());
    const bool derivative = d_da != nullptr || d_dX != nullptr;

    double       volume = 0;
    NodalVectors d_dx;
    for_each_boundary_face(problem,
                           design,
                           problem.get_geometry().pressure_boundary_ids,
                           [&](const CellNodes &nodes, const unsigned int face) {
                             volume += CellKernels::cavity_volume(
                               reference,
                               face,
                               nodes.deformed(a_ghost, X),
                               derivative ? &d_dx : nullptr);
                             if (d_da != nullptr)
                               nodes.add_to_displacement(d_dx, *d_da);
                             if (d_dX != nullptr)
                               nodes.add_to_design(d_dx, *d_dX);
                           });
    for (auto *w : {d_da, d_dX})
      if (w != nullptr)
        w->compress(VectorOperation::add);
    return Utilities::MPI::sum(volume, problem.get_communicator());
  }
} // namespace softopt
