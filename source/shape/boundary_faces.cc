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


  namespace
  {
    /** Corners c and midside nodes m (m[k] opposite corner k) split into
     * four triangles with the face's orientation. */
    template <typename T>
    std::array<std::array<T, 3>, 4>
    split(const std::array<T, 3> &c, const std::array<T, 3> &m)
    {
      return {{{{c[0], m[2], m[1]}},
               {{c[1], m[0], m[2]}},
               {{c[2], m[1], m[0]}},
               {{m[0], m[1], m[2]}}}};
    }
  } // namespace



  std::array<std::array<Point<3>, 3>, 4>
  flat_triangles(const BoundaryFace &face)
  {
    return split(face.corner, face.midpoint);
  }



  std::array<std::array<BoundaryFace::NodeDofs, 3>, 4>
  flat_triangle_dofs(const BoundaryFace &face)
  {
    return split(face.corner_dofs, face.midpoint_dofs);
  }



  std::vector<double>
  gathered_boundary_triangles(const DesignConfiguration            &design,
                              std::vector<types::boundary_id>      *boundary_ids,
                              const Deformation                    *deformation,
                              std::vector<types::global_dof_index> *dofs)
  {
    const auto          comm = design.get_dof_handler().get_communicator();
    std::vector<double> local;
    std::vector<types::boundary_id>      local_ids;
    std::vector<types::global_dof_index> local_dofs;
    for (const auto &face : locally_owned_boundary_faces(design, deformation))
      {
        for (const auto &t : flat_triangles(face))
          {
            local_ids.push_back(face.boundary_id);
            for (const auto &p : t)
              for (unsigned int d = 0; d < 3; ++d)
                local.push_back(p[d]);
          }
        if (dofs)
          for (const auto &t : flat_triangle_dofs(face))
            for (const auto &node : t)
              local_dofs.insert(local_dofs.end(), node.begin(), node.end());
      }
    std::vector<double> all;
    for (const auto &part : Utilities::MPI::gather(comm, local, 0))
      all.insert(all.end(), part.begin(), part.end());
    if (boundary_ids)
      {
        boundary_ids->clear();
        for (const auto &part : Utilities::MPI::gather(comm, local_ids, 0))
          boundary_ids->insert(boundary_ids->end(), part.begin(), part.end());
      }
    if (dofs)
      {
        dofs->clear();
        for (const auto &part : Utilities::MPI::gather(comm, local_dofs, 0))
          dofs->insert(dofs->end(), part.begin(), part.end());
      }
    return all;
  }
} // namespace softopt
