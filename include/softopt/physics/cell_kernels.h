#ifndef softopt_physics_cell_kernels_h
#define softopt_physics_cell_kernels_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>

#include <softopt/physics/material.h>

#include <array>
#include <functional>
#include <vector>

namespace softopt
{
  /** A vector at each of the 10 nodes of a quadratic tetrahedron (u, X, the
   * positions x = X + u, adjoint fields), in the base element's node order. */
  using NodalVectors = std::array<Tensor<1, 3>, 10>;

  /**
   * The quadratic tetrahedron on the reference cell: shape values and
   * gradients at the quadrature points of the cell and of each face, and
   * each face's parametrization. With the nodal positions of a cell this is
   * all the cell-level kernels below need, so they can run on numbers that
   * carry derivatives with respect to the positions.
   */
  class ReferenceTetrahedron
  {
  public:
    /** The quadratures of the HyperelasticProblem (cell, face). */
    ReferenceTetrahedron(const Quadrature<3> &cell_quadrature,
                         const Quadrature<2> &face_quadrature);

    struct QuadraturePoint
    {
      std::array<double, 10>       values;
      std::array<Tensor<1, 3>, 10> gradients; // d/dxi on the reference cell
      double                       weight;
    };

    std::vector<QuadraturePoint> cell_points;

    /** Face f: xi = xi_0 + s t_0 + t t_1 with t_0 x t_1 pointing out of the
     * cell; the weights integrate over (s, t) on the reference triangle. */
    std::array<std::vector<QuadraturePoint>, 4> face_points;
    std::array<std::array<Tensor<1, 3>, 2>, 4>  face_tangents;
  };

  /**
   * Cell-level kernels in the design configuration X (mm) of one cell. The
   * functions ending in _shape_derivative differentiate with respect to the
   * nodal positions: the condensed residual's by hand (it runs on every
   * cell; tests/cell_kernels checks it against finite differences), the
   * face kernels by forward automatic differentiation (NodalAD) of the same
   * code that gives their values. The integrands of functionals live with
   * them (softopt/functionals/).
   */
  namespace CellKernels
  {
    /**
     * The condensed residual r^e (N) of Eq. statCond2 without the follower
     * load, at r_p = 0: the element pressure p~ = -K/|Omega^e| int (J - 1) dV
     * is computed from u and X, so this is the residual of u -> r(u, p~(u))
     * that the adjoint of the condensed system sees.
     */
    NodalVectors
    condensed_residual(const ReferenceTetrahedron &reference,
                       const Material      &material,
                       const NodalVectors         &u,
                       const NodalVectors         &X);

    /** d(mu . r^e)/dX for condensed_residual(), through the material's
     * stress, tangent and pressure coupling. */
    NodalVectors
    condensed_residual_shape_derivative(const ReferenceTetrahedron &reference,
                                        const Material      &material,
                                        const NodalVectors         &u,
                                        const NodalVectors         &X,
                                        const NodalVectors         &mu);

    /**
     * The follower load per unit load factor on face f (appendix, Eq.
     * isoPressureLoad): p^ int N n^_c dxi_1 dxi_2, n^_c = x_{,s} x x_{,t},
     * a function of the deformed positions x = X + u only.
     */
    NodalVectors
    follower_load(const ReferenceTetrahedron &reference,
                  const unsigned int          face,
                  const double                p_hat,
                  const NodalVectors         &x);

    /** d(mu . follower_load)/dx, which is both d/dX and d/du. */
    NodalVectors
    follower_load_derivative(const ReferenceTetrahedron &reference,
                             const unsigned int          face,
                             const double                p_hat,
                             const NodalVectors         &x,
                             const NodalVectors         &mu);

    /** The contribution of face f to the cavity volume,
     * -1/3 int x . n^_c dxi (mm^3), and its derivative in x. */
    double
    cavity_volume(const ReferenceTetrahedron &reference,
                  const unsigned int          face,
                  const NodalVectors         &x,
                  NodalVectors               *d_dx);
  } // namespace CellKernels
} // namespace softopt

#endif
