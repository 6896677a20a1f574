#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/grid/reference_cell.h>

#include <softopt/physics/cell_kernels.h>
#include <softopt/physics/nodal_ad.h>

namespace softopt
{
  ReferenceTetrahedron::ReferenceTetrahedron(const Quadrature<3> &cell_quadrature,
                                             const Quadrature<2> &face_quadrature)
  {
    const FE_SimplexP<3> fe(2);
    AssertDimension(fe.n_dofs_per_cell(), 10);
    const auto evaluate = [&](const Point<3> &xi, const double weight) {
      QuadraturePoint point;
      for (unsigned int a = 0; a < 10; ++a)
        {
          point.values[a]    = fe.shape_value(a, xi);
          point.gradients[a] = fe.shape_grad(a, xi);
        }
      point.weight = weight;
      return point;
    };

    for (unsigned int q = 0; q < cell_quadrature.size(); ++q)
      cell_points.push_back(
        evaluate(cell_quadrature.point(q), cell_quadrature.weight(q)));

    const ReferenceCell tet = ReferenceCells::Tetrahedron;
    const Point<3>      centroid(0.25, 0.25, 0.25);
    for (unsigned int f = 0; f < 4; ++f)
      {
        std::array<Point<3>, 3> v;
        for (unsigned int i = 0; i < 3; ++i)
          v[i] = tet.vertex<3>(tet.face_to_cell_vertices(f, i, 1));
        Tensor<1, 3> t0 = v[1] - v[0], t1 = v[2] - v[0];
        const Point<3> face_centroid((v[0] + v[1] + v[2]) / 3.);
        if (cross_product_3d(t0, t1) * (face_centroid - centroid) < 0)
          std::swap(t0, t1);
        face_tangents[f] = {{t0, t1}};
        for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const Point<2> &st = face_quadrature.point(q);
            face_points[f].push_back(
              evaluate(v[0] + st[0] * t0 + st[1] * t1, face_quadrature.weight(q)));
          }
      }
  }



  namespace CellKernels
  {
    namespace
    {
      using namespace NodalAD;

      /** What the condensed residual of a cell and its shape derivative
       * share, at each quadrature point: grad N, H = grad u and dV in the
       * configuration X, J - 1; and the cell's volume and int (J - 1) dV. */
      struct CellState
      {
        CellState(const ReferenceTetrahedron &reference,
                  const NodalVectors         &u,
                  const NodalVectors         &X)
          : grad_N(reference.cell_points.size())
          , H(reference.cell_points.size())
          , dV(reference.cell_points.size())
          , J_minus_1(reference.cell_points.size())
        {
          for (unsigned int q = 0; q < grad_N.size(); ++q)
            {
              const auto        &point   = reference.cell_points[q];
              const Tensor<2, 3> J       = jacobian(point, X);
              const Tensor<2, 3> J_inv_T = transpose(invert(J));
              for (unsigned int a = 0; a < 10; ++a)
                {
                  grad_N[q][a] = J_inv_T * point.gradients[a];
                  H[q] += outer_product(u[a], grad_N[q][a]);
                }
              dV[q]        = determinant(J) * point.weight;
              J_minus_1[q] = jacobian_minus_one(H[q]);
              volume += dV[q];
              dilatation += J_minus_1[q] * dV[q];
            }
        }

        /** r_p = 0 solved for the element pressure (Eq. statCond1). */
        double
        pressure(const Material &material) const
        {
          return -material.bulk_modulus * dilatation / volume;
        }

        std::vector<NodalVectors> grad_N;
        std::vector<Tensor<2, 3>> H;
        std::vector<double>       dV, J_minus_1;
        double                    volume = 0, dilatation = 0;
      };

      template <typename Number>
      Nodes<Number>
      load(const ReferenceTetrahedron &reference,
           const unsigned int          face,
           const double                p_hat,
           const Nodes<Number>        &x)
      {
        Nodes<Number> f;
        for (const auto &point : reference.face_points[face])
          {
            const Tensor<1, 3, Number> n = area_normal(reference, face, point, x);
            for (unsigned int a = 0; a < 10; ++a)
              for (unsigned int i = 0; i < 3; ++i)
                f[a][i] += p_hat * point.values[a] * point.weight * n[i];
          }
        return f;
      }

      template <typename Number>
      Number
      volume(const ReferenceTetrahedron &reference,
             const unsigned int          face,
             const Nodes<Number>        &x)
      {
        Number V = 0;
        for (const auto &point : reference.face_points[face])
          {
            const Tensor<1, 3, Number> n  = area_normal(reference, face, point, x);
            const Tensor<1, 3, Number> xq = interpolate(point, x);
            const Number               xn = xq * n;
            V -= xn * point.weight / 3.;
          }
        return V;
      }

      /** mu . v over the ten nodes of a cell: the adjoint-weighted sum
       * whose derivative is mu^T dv/dX. */
      AD
      contract(const NodalVectors &mu, const Nodes<AD> &v)
      {
        AD sum = 0;
        for (unsigned int a = 0; a < 10; ++a)
          for (unsigned int i = 0; i < 3; ++i)
            sum += mu[a][i] * v[a][i];
        return sum;
      }
    } // namespace



    NodalVectors
    condensed_residual(const ReferenceTetrahedron &reference,
                       const Material             &material,
                       const NodalVectors         &u,
                       const NodalVectors         &X)
    {
      const CellState cell(reference, u, X);
      const double    p = cell.pressure(material);
      NodalVectors    r{};
      for (unsigned int q = 0; q < cell.dV.size(); ++q)
        {
          const Tensor<2, 3> P =
            material.first_piola(unit_symmetric_tensor<3>() + cell.H[q], p);
          for (unsigned int a = 0; a < 10; ++a)
            r[a] += P * cell.grad_N[q][a] * cell.dV[q];
        }
      return r;
    }



    NodalVectors
    condensed_residual_shape_derivative(const ReferenceTetrahedron &reference,
                                        const Material             &material,
                                        const NodalVectors         &u,
                                        const NodalVectors         &X,
                                        const NodalVectors         &mu)
    {
      // mu . r^e = int P(F, p~) : G dV with G = grad mu. A perturbation V of
      // the nodes (grad V = sum_c V_c (x) grad N_c) changes grad N by
      // -grad N grad V, dV by tr(grad V) dV, so H = grad u by -H grad V and
      // G by -G grad V; each quadrature point contributes Sigma : grad V dV,
      //   Sigma = -H^T (G : A) - G^T P + (P : G) I,
      // and the element pressure p~ = -K D / |Omega^e|, D = int (J - 1) dV,
      // adds (int dP/dp~ : G dV) dp~ with
      //   dp~ = -K / |Omega^e| int (H^T dP/dp~ + (J - 1 - D/|Omega^e|) I) : grad V dV
      // (dP/dp~ = -J F^{-T}). d/dV_c of Sigma : grad V is Sigma grad N_c.
      const CellState    cell(reference, u, X);
      const unsigned int n_q = cell.dV.size();
      const double       p   = cell.pressure(material);
      const auto &grad_N = cell.grad_N;
      const auto &H      = cell.H;
      const auto &dV     = cell.dV;
      std::vector<Tensor<2, 3>> G(n_q);
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int a = 0; a < 10; ++a)
          G[q] += outer_product(mu[a], grad_N[q][a]);

      NodalVectors              d{};
      std::vector<Tensor<2, 3>> coupling(n_q);
      double                    pressure_sensitivity = 0; // int dP/dp~ : G dV
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<2, 3> F = unit_symmetric_tensor<3>() + H[q];
          const Tensor<2, 3> P = material.first_piola(F, p);
          const Tensor<4, 3> A = material.tangent(F, p);
          coupling[q]          = material.pressure_coupling(F);
          pressure_sensitivity += scalar_product(coupling[q], G[q]) * dV[q];
          Tensor<2, 3> GA; // (G : A)_kl = G_ij A_ijkl
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              GA += G[q][i][j] * A[i][j];
          const Tensor<2, 3> Sigma =
            -transpose(H[q]) * GA - transpose(G[q]) * P +
            scalar_product(P, G[q]) * unit_symmetric_tensor<3>();
          for (unsigned int c = 0; c < 10; ++c)
            d[c] += Sigma * grad_N[q][c] * dV[q];
        }
      const double factor =
        -material.bulk_modulus / cell.volume * pressure_sensitivity;
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<2, 3> Pi =
            transpose(H[q]) * coupling[q] +
            (cell.J_minus_1[q] - cell.dilatation / cell.volume) *
              unit_symmetric_tensor<3>();
          for (unsigned int c = 0; c < 10; ++c)
            d[c] += factor * (Pi * grad_N[q][c]) * dV[q];
        }
      return d;
    }



    NodalVectors
    follower_load(const ReferenceTetrahedron &reference,
                  const unsigned int          face,
                  const double                p_hat,
                  const NodalVectors         &x)
    {
      return load(reference, face, p_hat, x);
    }



    NodalVectors
    follower_load_derivative(const ReferenceTetrahedron &reference,
                             const unsigned int          face,
                             const double                p_hat,
                             const NodalVectors         &x,
                             const NodalVectors         &mu)
    {
      return derivatives(contract(mu, load(reference, face, p_hat, independent(x))));
    }



    double
    cavity_volume(const ReferenceTetrahedron &reference,
                  const unsigned int          face,
                  const NodalVectors         &x,
                  NodalVectors               *d_dx)
    {
      if (d_dx == nullptr)
        return volume(reference, face, x);
      const AD V = volume(reference, face, independent(x));
      *d_dx      = derivatives(V);
      return V.val();
    }
  } // namespace CellKernels
} // namespace softopt
