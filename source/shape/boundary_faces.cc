#include <deal.II/base/mpi.h>

#include <softopt/shape/boundary_faces.h>

namespace softopt
{
  std::vector<BoundaryFace>
  locally_owned_boundary_faces(const DesignConfiguration &design,
                               const Deformation         *deformation)
  {
    const auto &X = design.positions();
    std::vector<BoundaryFace> faces;
    for (const auto &design_cell : design.get_dof_handler().active_cell_iterators())
      if (design_cell->is_locally_owned() && design_cell->at_boundary())
        {
          // The same cell on the displacement's DoFs: its nodes' DoFs for
          // the components 0-2 are ordered as the design's.
          const auto u_cell = deformation ?
                                DoFHandler<3>::active_cell_iterator(&design_cell->get_triangulation(),
                                                                    design_cell->level(),
                                                                    design_cell->index(),
                                                                    &deformation->dof_handler) :
                                design_cell;
          // The design DoFs of the node whose DoFs are @p dof(cell, c).
          const auto dofs_of = [&](const auto &dof) {
            return BoundaryFace::NodeDofs{
              {dof(design_cell, 0), dof(design_cell, 1), dof(design_cell, 2)}};
          };
          // The node whose DoFs are @p dof(cell, c) for the components c.
          const auto position = [&](const auto &dof) {
            Point<3> p(X(dof(design_cell, 0)), X(dof(design_cell, 1)), X(dof(design_cell, 2)));
            if (deformation)
              for (unsigned int c = 0; c < 3; ++c)
                p[c] += deformation->u(dof(u_cell, c));
            return p;
          };
          const auto &cell = design_cell;
          Point<3> cell_center;
          for (const unsigned int v : cell->vertex_indices())
            cell_center += position([&](const auto &on, const unsigned int c) {
                             return on->vertex_dof_index(v, c);
                           }) / 4.;
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                const auto   face = cell->face(f);
                BoundaryFace result;
                result.boundary_id = face->boundary_id();
                for (unsigned int v = 0; v < 3; ++v)
                  {
                    const auto dof = [&](const auto &on, const unsigned int c) {
                      return on->face(f)->vertex_dof_index(v, c);
                    };
                    result.corner[v]      = position(dof);
                    result.corner_dofs[v] = dofs_of(dof);
                  }
                for (unsigned int l = 0; l < 3; ++l)
                  {
                    const auto   line     = face->line(l);
                    unsigned int opposite = 0;
                    for (unsigned int v = 0; v < 3; ++v)
                      if (face->vertex_index(v) != line->vertex_index(0) &&
                          face->vertex_index(v) != line->vertex_index(1))
                        opposite = v;
                    const auto dof = [&](const auto &on, const unsigned int c) {
                      return on->face(f)->line(l)->dof_index(c);
                    };
                    result.midpoint[opposite]      = position(dof);
                    result.midpoint_dofs[opposite] = dofs_of(dof);
                  }
                // Outward: away from the cell's center.
                const Tensor<1, 3> normal =
                  cross_product_3d(result.corner[1] - result.corner[0],
                                   result.corner[2] - result.corner[0]);
                const Point<3> face_center =
                  (result.corner[0] + result.corner[1] + result.corner[2]) / 3.;
                if (normal * (face_center - cell_center) < 0)
                  {
                    std::swap(result.corner[1], result.corner[2]);
                    std::swap(result.midpoint[1], result.midpoint[2]);
                    std::swap(result.corner_dofs[1], result.corner_dofs[2]);
                    std::swap(result.midpoint_dofs[1], result.midpoint_dofs[2]);
                  }
                faces.push_back(result);
              }
        }
    return faces;
  }


  std::vector<BoundaryFace>
  gathered_boundary_faces(const DesignConfiguration &design, const Deformation *deformation)
  {
    // Sent as numbers: 18 coordinates a face, and 18 DoFs and the id.
    std::vector<double>                  x;
    std::vector<types::global_dof_index> n;
    for (const auto &face : locally_owned_boundary_faces(design, deformation))
      {
        for (const auto *nodes : {&face.corner, &face.midpoint})
          for (const auto &p : *nodes)
            for (unsigned int d = 0; d < 3; ++d)
              x.push_back(p[d]);
        for (const auto *nodes : {&face.corner_dofs, &face.midpoint_dofs})
          for (const auto &dofs : *nodes)
            n.insert(n.end(), dofs.begin(), dofs.end());
        n.push_back(face.boundary_id);
      }
    const auto comm = design.get_dof_handler().get_communicator();
    const auto all_x = Utilities::MPI::gather(comm, x, 0);
    const auto all_n = Utilities::MPI::gather(comm, n, 0);
    std::vector<BoundaryFace> faces;
    for (unsigned int rank = 0; rank < all_x.size(); ++rank)
      for (std::size_t f = 0; 18 * f < all_x[rank].size(); ++f)
        {
          const double *p     = &all_x[rank][18 * f];
          const auto   *dofs  = &all_n[rank][19 * f];
          BoundaryFace  face;
          for (unsigned int v = 0; v < 3; ++v)
            for (unsigned int d = 0; d < 3; ++d)
              {
                face.corner[v][d]          = p[3 * v + d];
                face.midpoint[v][d]        = p[9 + 3 * v + d];
                face.corner_dofs[v][d]     = dofs[3 * v + d];
                face.midpoint_dofs[v][d]   = dofs[9 + 3 * v + d];
              }
          face.boundary_id = dofs[18];
          faces.push_back(face);
        }
    return faces;
  }



  std::array<std::array<Point<3>, 3>, 4>
  flat_triangles(const BoundaryFace &face)
  {
    // Corners c and midside nodes m (m[k] opposite corner k), with the
    // face's orientation.
    const auto &c = face.corner;
    const auto &m = face.midpoint;
    return {{{{c[0], m[2], m[1]}},
             {{c[1], m[0], m[2]}},
             {{c[2], m[1], m[0]}},
             {{m[0], m[1], m[2]}}}};
  }



  std::vector<std::array<SurfacePoint, 3>>
  curved_triangles(const BoundaryFace &face, const unsigned int k)
  {
    AssertThrow(k > 0, ExcMessage("A face is split into k x k triangles, k > 0."));
    // The point of barycentric coordinates l / k (l[a]: corner a's), with
    // the quadratic shape functions N_a = lambda_a (2 lambda_a - 1) of the
    // corners and N = 4 lambda_a lambda_b of the midpoint between a and b.
    const auto point = [&](const std::array<unsigned int, 3> &l) {
      SurfacePoint p;
      p.weight.fill(0.);
      for (unsigned int a = 0; a < 3; ++a)
        if (l[a] == k) // a corner: the node itself
          {
            p.x         = face.corner[a];
            p.weight[a] = 1;
            return p;
          }
      for (unsigned int c = 0; c < 3; ++c)
        if (l[c] == 0) // on the edge opposite corner c: from its three nodes
          {
            unsigned int a = (c + 1) % 3, b = (c + 2) % 3;
            if (face.corner_dofs[b][0] < face.corner_dofs[a][0])
              std::swap(a, b);
            const double la = double(l[a]) / k, lb = double(l[b]) / k;
            p.weight[a]     = la * (2 * la - 1);
            p.weight[b]     = lb * (2 * lb - 1);
            p.weight[3 + c] = 4 * la * lb;
            for (unsigned int d = 0; d < 3; ++d)
              p.x[d] = p.weight[a] * face.corner[a][d] + p.weight[b] * face.corner[b][d] +
                       p.weight[3 + c] * face.midpoint[c][d];
            return p;
          }
      std::array<double, 3> lambda;
      for (unsigned int a = 0; a < 3; ++a)
        lambda[a] = double(l[a]) / k;
      for (unsigned int a = 0; a < 3; ++a)
        {
          p.weight[a]     = lambda[a] * (2 * lambda[a] - 1);
          p.weight[3 + a] = 4 * lambda[(a + 1) % 3] * lambda[(a + 2) % 3];
          p.x += p.weight[a] * face.corner[a] + p.weight[3 + a] * face.midpoint[a];
        }
      return p;
    };
    // Point (i, j): i/k of the way to corner 1, j/k to corner 2; the
    // triangles (i, j) (i + 1, j) (i, j + 1) and (i + 1, j) (i + 1, j + 1)
    // (i, j + 1) turn as corners 0, 1, 2 do.
    const auto at = [&](const unsigned int i, const unsigned int j) {
      return point({{k - i - j, i, j}});
    };
    std::vector<std::array<SurfacePoint, 3>> triangles;
    for (unsigned int j = 0; j < k; ++j)
      for (unsigned int i = 0; i + j < k; ++i)
        {
          triangles.push_back({{at(i, j), at(i + 1, j), at(i, j + 1)}});
          if (i + j + 1 < k)
            triangles.push_back({{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
        }
    return triangles;
  }



  std::vector<double>
  gathered_boundary_triangles(const DesignConfiguration       &design,
                              std::vector<types::boundary_id> *boundary_ids,
                              const Deformation               *deformation)
  {
    std::vector<double> corners;
    if (boundary_ids)
      boundary_ids->clear();
    for (const auto &face : gathered_boundary_faces(design, deformation))
      for (const auto &t : flat_triangles(face))
        {
          if (boundary_ids)
            boundary_ids->push_back(face.boundary_id);
          for (const auto &p : t)
            for (unsigned int d = 0; d < 3; ++d)
              corners.push_back(p[d]);
        }
    return corners;
  }
} // namespace softopt
