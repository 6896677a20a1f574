#ifndef softopt_physics_nodal_ad_h
#define softopt_physics_nodal_ad_h

#include <deal.II/differentiation/ad.h>

#include <softopt/physics/cell_kernels.h>

namespace softopt
{
  /**
   * Forward automatic differentiation (Sacado) of cell and face integrals
   * in the nodal vectors of one quadratic tetrahedron, and the geometry
   * those integrals are written with, for numbers with or without
   * derivatives. Include it only where a kernel is differentiated: Sacado
   * is heavy to compile.
   */
  namespace NodalAD
  {
    using AD = Sacado::Fad::DFad<double>;

    template <typename Number>
    using Nodes = std::array<Tensor<1, 3, Number>, 10>;

    /** Nodal values as AD numbers, each component the independent variable
     * @p offset + 3 a + c of @p n_variables. */
    inline Nodes<AD>
    independent(const NodalVectors &values,
                const unsigned int  n_variables = 30,
                const unsigned int  offset      = 0)
    {
      Nodes<AD> nodes;
      for (unsigned int a = 0; a < 10; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          nodes[a][c] = AD(n_variables, offset + 3 * a + c, values[a][c]);
      return nodes;
    }

    /** d(value)/d(independent @p offset + 3 a + c) as nodal vectors. */
    inline NodalVectors
    derivatives(const AD &value, const unsigned int offset = 0)
    {
      NodalVectors d;
      for (unsigned int a = 0; a < 10; ++a)
        for (unsigned int c = 0; c < 3; ++c)
          d[a][c] = value.size() > 0 ? value.dx(offset + 3 * a + c) : 0.;
      return d;
    }

    inline double
    value_of(const double x)
    {
      return x;
    }

    inline double
    value_of(const AD &x)
    {
      return x.val();
    }

    /** dX/dxi at a quadrature point. */
    template <typename Number>
    Tensor<2, 3, Number>
    jacobian(const ReferenceTetrahedron::QuadraturePoint &point, const Nodes<Number> &X)
    {
      Tensor<2, 3, Number> J;
      for (unsigned int a = 0; a < 10; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            J[i][j] += X[a][i] * point.gradients[a][j];
      return J;
    }

    /** sum_a N_a y_a at a quadrature point. */
    template <typename Number>
    Tensor<1, 3, Number>
    interpolate(const ReferenceTetrahedron::QuadraturePoint &point, const Nodes<Number> &y)
    {
      Tensor<1, 3, Number> value;
      for (unsigned int a = 0; a < 10; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          value[i] += point.values[a] * y[a][i];
      return value;
    }

    /** n^ = x_{,s} x x_{,t} on face f (Eq. normal without normalization). */
    template <typename Number>
    Tensor<1, 3, Number>
    area_normal(const ReferenceTetrahedron                  &reference,
                const unsigned int                           face,
                const ReferenceTetrahedron::QuadraturePoint &point,
                const Nodes<Number>                         &x)
    {
      const Tensor<2, 3, Number> J  = jacobian(point, x);
      const Tensor<1, 3, Number> xs = J * reference.face_tangents[face][0];
      const Tensor<1, 3, Number> xt = J * reference.face_tangents[face][1];
      return cross_product_3d(xs, xt);
    }
  } // namespace NodalAD
} // namespace softopt

#endif
