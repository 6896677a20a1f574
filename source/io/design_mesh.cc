#include <deal.II/base/mpi.h>

#include <softopt/geometry/gmsh_mesh.h>
#include <softopt/io/design_mesh.h>
#include <softopt/shape/boundary_faces.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>

namespace softopt
{
  namespace
  {
    /** Per cell: 4 corners, then the midside nodes of gmsh's edges (0,1),
     * (1,2), (2,0), (3,0), (3,2), (3,1): ten nodes, x, y, z each. */
    constexpr unsigned int cell_size = 30;
    /** Per face: 3 corners, 3 midside nodes (opposite corner k), id. */
    constexpr unsigned int face_size = 19;

    constexpr std::array<std::array<unsigned int, 2>, 6> gmsh_edges{
      {{{0, 1}}, {{1, 2}}, {{2, 0}}, {{3, 0}}, {{3, 2}}, {{3, 1}}}};

    Point<3>
    point(const std::vector<double> &part, const std::size_t offset)
    {
      return Point<3>(part[offset], part[offset + 1], part[offset + 2]);
    }

    void
    push(std::vector<double> &to, const Point<3> &p)
    {
      for (unsigned int d = 0; d < 3; ++d)
        to.push_back(p[d]);
    }

    /** This rank's cells, in the layout of cell_size, oriented so that
     * gmsh's corner volume is positive. */
    std::vector<double>
    local_cells(const DesignConfiguration &design)
    {
      const auto &X = design.positions();
      std::vector<double> cells;
      for (const auto &cell : design.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            std::array<Point<3>, 4> corner;
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int c = 0; c < 3; ++c)
                corner[v][c] = X(cell->vertex_dof_index(v, c));
            // The midside node of the edge between corners a and b.
            std::map<std::pair<unsigned int, unsigned int>, Point<3>> midside;
            for (const unsigned int l : cell->line_indices())
              {
                const auto   line = cell->line(l);
                unsigned int ends[2];
                for (unsigned int e = 0; e < 2; ++e)
                  for (const unsigned int v : cell->vertex_indices())
                    if (cell->vertex_index(v) == line->vertex_index(e))
                      ends[e] = v;
                Point<3> m;
                for (unsigned int c = 0; c < 3; ++c)
                  m[c] = X(line->dof_index(c));
                midside[{ends[0], ends[1]}] = m;
                midside[{ends[1], ends[0]}] = m;
              }
            std::array<unsigned int, 4> order{{0, 1, 2, 3}};
            const double volume = cross_product_3d(corner[1] - corner[0],
                                                   corner[2] - corner[0]) *
                                  (corner[3] - corner[0]);
            if (volume < 0)
              std::swap(order[1], order[2]);
            for (const unsigned int v : order)
              push(cells, corner[v]);
            for (const auto &[a, b] : gmsh_edges)
              push(cells, midside.at({order[a], order[b]}));
          }
      return cells;
    }
  } // namespace



  void
  write_design_mesh(const DesignConfiguration &design, const std::string &file)
  {
    const MPI_Comm      comm = design.get_dof_handler().get_communicator();
    std::vector<double> faces;
    for (const auto &face : locally_owned_boundary_faces(design))
      {
        for (const auto *nodes : {&face.corner, &face.midpoint})
          for (const auto &p : *nodes)
            push(faces, p);
        faces.push_back(face.boundary_id);
      }
    const auto cell_parts = Utilities::MPI::gather(comm, local_cells(design), 0);
    const auto face_parts = Utilities::MPI::gather(comm, faces, 0);
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          // Shared nodes are read from the same DoFs: equal bit for bit.
          std::map<Point<3>, long, PointLess> number;
          for (const auto &part : cell_parts)
            for (std::size_t i = 0; i < part.size(); i += 3)
              number.emplace(point(part, i), 0);
          GmshMesh mesh;
          for (auto &[p, n] : number)
            {
              n             = mesh.nodes.size() + 1;
              mesh.nodes[n] = p;
            }
          // (physical tag, type, nodes), sorted.
          std::vector<std::pair<std::array<long, 2>, std::vector<long>>> elements;
          for (const auto &part : cell_parts)
            for (std::size_t t = 0; t < part.size(); t += cell_size)
              {
                std::vector<long> nodes;
                for (unsigned int v = 0; v < 10; ++v)
                  nodes.push_back(number.at(point(part, t + 3 * v)));
                elements.push_back({{{1, 11}}, nodes});
              }
          for (const auto &part : face_parts)
            for (std::size_t t = 0; t < part.size(); t += face_size)
              {
                // gmsh's six-node triangle: corners, then the midside
                // nodes of (0,1), (1,2), (2,0), opposite corners 2, 0, 1.
                std::vector<long> nodes;
                for (const unsigned int k : {0u, 1u, 2u, 5u, 3u, 4u})
                  nodes.push_back(number.at(point(part, t + 3 * k)));
                const long id = static_cast<long>(part[t + 18]);
                elements.push_back({{{id, 9}}, nodes});
              }
          std::sort(elements.begin(), elements.end(), [](const auto &a, const auto &b) {
            // Triangles (type 9) before tetrahedra, as gmsh writes them.
            return std::make_pair(a.first[1], std::make_pair(a.first[0], a.second)) <
                   std::make_pair(b.first[1], std::make_pair(b.first[0], b.second));
          });
          for (const auto &[tag_type, nodes] : elements)
            mesh.elements.push_back(
              {0, static_cast<int>(tag_type[1]), {tag_type[0], tag_type[0]}, nodes});
          const std::string part = file + ".part";
          write_gmsh_mesh(mesh, part);
          if (std::rename(part.c_str(), file.c_str()) != 0)
            error = "Cannot rename " + part + " to " + file;
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));
  }
} // namespace softopt
