#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <softopt/io/stl_writer.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>

namespace softopt
{
  namespace
  {
    using Triangle = std::array<Point<3>, 3>;

    /** The position of the node whose x-component DoF is @p dof_x; the
     * other components follow it (FESystem of three P2 elements orders the
     * DoFs of a node by component). */
    Point<3>
    node_position(const DesignConfiguration::Vector &X,
                  const std::array<types::global_dof_index, 3> &dofs)
    {
      return Point<3>(X(dofs[0]), X(dofs[1]), X(dofs[2]));
    }
  } // namespace



  unsigned int
  write_design_stl(const DesignConfiguration &design, const std::string &file)
  {
    const auto &dof_handler = design.get_dof_handler();
    const auto &X           = design.positions();
    const auto  comm        = dof_handler.get_communicator();

    // Triangles of this rank as 9 floats each (x, y, z of three corners).
    std::vector<float> local;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          Point<3> cell_center;
          for (const unsigned int v : cell->vertex_indices())
            {
              std::array<types::global_dof_index, 3> dofs;
              for (unsigned int c = 0; c < 3; ++c)
                dofs[c] = cell->vertex_dof_index(v, c);
              cell_center += node_position(X, dofs) / 4.;
            }
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                const auto face = cell->face(f);
                // Corners, and the midpoint node of the edge opposite to
                // corner k stored at index k.
                std::array<Point<3>, 3> corner, midpoint;
                for (unsigned int v = 0; v < 3; ++v)
                  {
                    std::array<types::global_dof_index, 3> dofs;
                    for (unsigned int c = 0; c < 3; ++c)
                      dofs[c] = face->vertex_dof_index(v, c);
                    corner[v] = node_position(X, dofs);
                  }
                for (unsigned int l = 0; l < 3; ++l)
                  {
                    const auto line = face->line(l);
                    std::array<types::global_dof_index, 3> dofs;
                    for (unsigned int c = 0; c < 3; ++c)
                      dofs[c] = line->dof_index(c);
                    unsigned int opposite = 0;
                    for (unsigned int v = 0; v < 3; ++v)
                      if (face->vertex_index(v) != line->vertex_index(0) &&
                          face->vertex_index(v) != line->vertex_index(1))
                        opposite = v;
                    midpoint[opposite] = node_position(X, dofs);
                  }
                // Four triangles of the face, counter-clockwise as corners
                // 0, 1, 2: m_k is opposite corner k.
                std::array<Triangle, 4> triangles{
                  {{{corner[0], midpoint[2], midpoint[1]}},
                   {{corner[1], midpoint[0], midpoint[2]}},
                   {{corner[2], midpoint[1], midpoint[0]}},
                   {{midpoint[0], midpoint[1], midpoint[2]}}}};
                // Outward: away from the cell's center.
                const Tensor<1, 3> normal =
                  cross_product_3d(corner[1] - corner[0], corner[2] - corner[0]);
                const Point<3> face_center =
                  (corner[0] + corner[1] + corner[2]) / 3.;
                const bool flip = normal * (face_center - cell_center) < 0;
                for (auto &t : triangles)
                  {
                    if (flip)
                      std::swap(t[1], t[2]);
                    for (const auto &p : t)
                      for (unsigned int c = 0; c < 3; ++c)
                        local.push_back(static_cast<float>(p[c]));
                  }
              }
        }

    const auto all = Utilities::MPI::gather(comm, local, 0);
    unsigned int n_triangles = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        for (const auto &part : all)
          n_triangles += part.size() / 9;
        const std::string temporary = file + ".tmp";
        {
          std::ofstream out(temporary, std::ios::binary);
          AssertThrow(out, ExcMessage("Cannot write " + temporary));
          std::array<char, 80> header{};
          const std::string    title = "softopt design, mm";
          std::copy(title.begin(), title.end(), header.begin());
          out.write(header.data(), header.size());
          const std::uint32_t count = n_triangles;
          out.write(reinterpret_cast<const char *>(&count), sizeof(count));
          for (const auto &part : all)
            for (std::size_t t = 0; t < part.size(); t += 9)
              {
                const Point<3> a(part[t], part[t + 1], part[t + 2]),
                  b(part[t + 3], part[t + 4], part[t + 5]),
                  c(part[t + 6], part[t + 7], part[t + 8]);
                Tensor<1, 3> n    = cross_product_3d(b - a, c - a);
                const double norm = n.norm();
                if (norm > 0)
                  n /= norm;
                const std::array<float, 3> normal{
                  {float(n[0]), float(n[1]), float(n[2])}};
                out.write(reinterpret_cast<const char *>(normal.data()), 12);
                out.write(reinterpret_cast<const char *>(&part[t]), 36);
                const std::uint16_t attribute = 0;
                out.write(reinterpret_cast<const char *>(&attribute), 2);
              }
          AssertThrow(out, ExcMessage("Writing " + temporary + " failed"));
        }
        AssertThrow(std::rename(temporary.c_str(), file.c_str()) == 0,
                    ExcMessage("Cannot rename " + temporary + " to " + file));
      }
    return Utilities::MPI::broadcast(comm, n_triangles, 0);
  }
} // namespace softopt
