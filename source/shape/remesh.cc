#include <deal.II/base/mpi.h>

#include <softopt/geometry/gmsh_mesh.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/remesh.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <map>

namespace softopt
{
  namespace
  {
    /** Exact lexicographic order: the faces of neighbouring cells read a
     * shared node from the same DoFs, so equal nodes are equal bit for
     * bit. */
    struct Less
    {
      bool
      operator()(const Point<3> &a, const Point<3> &b) const
      {
        return std::lexicographical_compare(&a[0], &a[0] + 3, &b[0], &b[0] + 3);
      }
    };

    /** Lexicographic order up to @p tolerance: gmsh writes the corners it
     * read back with 16 digits, so they may differ in the last bit. Nodes
     * are much farther apart than the tolerance. */
    struct NearlyLess
    {
      double tolerance;
      bool
      operator()(const Point<3> &a, const Point<3> &b) const
      {
        for (unsigned int d = 0; d < 3; ++d)
          if (a[d] < b[d] - tolerance)
            return true;
          else if (a[d] > b[d] + tolerance)
            return false;
        return false;
      }
    };

    /** Per face: 3 corners, 3 midside nodes (x, y, z each), boundary id. */
    constexpr unsigned int face_size = 19;

    Point<3>
    point(const std::vector<double> &part, const std::size_t offset)
    {
      return Point<3>(part[offset], part[offset + 1], part[offset + 2]);
    }

    /** A boundary edge by the numbers of its corners, smaller first. */
    using Edge = std::pair<unsigned int, unsigned int>;

    Edge
    edge(const unsigned int a, const unsigned int b)
    {
      return {std::min(a, b), std::max(a, b)};
    }

    /** The boundary's corner nodes with their numbers, and the curved
     * midside node of every boundary edge. */
    struct Surface
    {
      std::map<Point<3>, unsigned int, Less> number;
      std::map<Edge, Point<3>>               midpoints;
    };

    /**
     * Writes the boundary triangles (corners only) with their boundary ids
     * as discrete surfaces, in gmsh's format 2.2.
     */
    Surface
    write_surface(const std::vector<std::vector<double>> &parts,
                  const std::string                      &file)
    {
      Surface surface;
      auto   &number = surface.number;
      for (const auto &part : parts)
        for (std::size_t t = 0; t < part.size(); t += face_size)
          for (unsigned int v = 0; v < 3; ++v)
            number.emplace(point(part, t + 3 * v), 0);
      std::ofstream out(file);
      out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
          << number.size() << "\n"
          << std::setprecision(17);
      unsigned int n = 0;
      for (auto &[p, i] : number)
        {
          i = ++n;
          out << i << " " << p[0] << " " << p[1] << " " << p[2] << "\n";
        }
      // The triangles as (boundary id, corners), sorted: the same file
      // (and so the same mesh) on any number of MPI ranks.
      std::vector<std::array<unsigned int, 4>> triangles;
      auto &midpoints = surface.midpoints;
      for (const auto &part : parts)
        for (std::size_t t = 0; t < part.size(); t += face_size)
          {
            std::array<unsigned int, 4> triangle;
            triangle[0] = static_cast<unsigned int>(part[t + 18]);
            for (unsigned int v = 0; v < 3; ++v)
              triangle[v + 1] = number.at(point(part, t + 3 * v));
            triangles.push_back(triangle);
            // midpoint[k] is opposite corner k.
            for (unsigned int k = 0; k < 3; ++k)
              midpoints[edge(triangle[1 + (k + 1) % 3], triangle[1 + (k + 2) % 3])] =
                point(part, t + 9 + 3 * k);
          }
      std::sort(triangles.begin(), triangles.end());
      out << "$EndNodes\n$Elements\n" << triangles.size() << "\n";
      n = 0;
      for (const auto &[id, a, b, c] : triangles)
        // Physical and elementary tag: the boundary id.
        out << ++n << " 2 2 " << id << " " << id << " " << a << " " << b
            << " " << c << "\n";
      out << "$EndElements\n";
      AssertThrow(out, ExcMessage("Cannot write " + file));
      return surface;
    }

    /** A quadratic tetrahedron of gmsh's mesh: corner tags, and per edge
     * its corners (local) and midside node's tag. */
    struct Tetrahedron
    {
      std::array<unsigned int, 4>                                corners;
      std::array<std::pair<Edge, unsigned int>, 6>               edges;
    };

    /**
     * min det J / max det J of the P2 map of @p t at its ten nodes and
     * centroid (negative: inverted), with node positions from @p position.
     */
    template <typename Position>
    double
    jacobian_ratio(const Tetrahedron &t, const Position &position)
    {
      // Barycentric L_0 = 1 - x - y - z, L_a = x_a, and their gradients.
      const std::array<Tensor<1, 3>, 4> dL{{Tensor<1, 3>({-1., -1., -1.}),
                                            Tensor<1, 3>({1., 0., 0.}),
                                            Tensor<1, 3>({0., 1., 0.}),
                                            Tensor<1, 3>({0., 0., 1.})}};
      std::vector<Point<3>> points{Point<3>(0, 0, 0), Point<3>(1, 0, 0),
                                   Point<3>(0, 1, 0), Point<3>(0, 0, 1),
                                   Point<3>(.25, .25, .25)};
      for (const auto &[local, tag] : t.edges)
        points.push_back((points[local.first] + points[local.second]) / 2.);
      double smallest = std::numeric_limits<double>::max(), largest = 0;
      for (const auto &x : points)
        {
          const std::array<double, 4> L{{1 - x[0] - x[1] - x[2], x[0], x[1], x[2]}};
          Tensor<2, 3>                J;
          // Corners: L_a (2 L_a - 1); edges: 4 L_a L_b.
          for (unsigned int a = 0; a < 4; ++a)
            J += outer_product(position(t.corners[a]), (4 * L[a] - 1) * dL[a]);
          for (const auto &[local, tag] : t.edges)
            J += outer_product(position(tag),
                               4 * (L[local.first] * dL[local.second] +
                                    L[local.second] * dL[local.first]));
          smallest = std::min(smallest, determinant(J));
          largest  = std::max(largest, determinant(J));
        }
      return smallest / largest;
    }

    /**
     * Whether every midside node of @p t is nearer to the straight midpoint
     * of its own edge than to any other's: split_quadratic_gmsh_mesh()
     * assigns midside nodes to edges that way when it reads the file.
     */
    template <typename Position>
    bool
    matches_edges(const Tetrahedron &t, const Position &position)
    {
      for (const auto &[own, tag] : t.edges)
        for (const auto &[other, other_tag] : t.edges)
          if (other != own &&
              position(tag).distance((position(t.corners[other.first]) +
                                      position(t.corners[other.second])) / 2.) <=
                position(tag).distance((position(t.corners[own.first]) +
                                        position(t.corners[own.second])) / 2.))
            return false;
      return true;
    }

    /**
     * Moves the midside nodes of the boundary edges in gmsh's quadratic
     * @p file (format 2.2), which gmsh put at the straight edges' midpoints,
     * to the design's curved @p midpoints, so the new mesh has the design's
     * P2 surface. gmsh's corner nodes are found among the boundary's by
     * position (gmsh renumbers them); a midside node belongs to the edge
     * whose straight midpoint is nearest (as in split_quadratic_gmsh_mesh).
     * Where that would make an element's Jacobian vary by more than a
     * factor 5 (or invert it), or put a midside node nearer to another
     * edge's midpoint than to its own, the element's edges stay straight.
     */
    void
    restore_curved_midpoints(const std::string &file, const Surface &surface)
    {
      double size = 1;
      for (const auto &[p, n] : surface.number)
        size = std::max(size, p.norm());
      std::map<Point<3>, unsigned int, NearlyLess> number(
        surface.number.begin(), surface.number.end(), NearlyLess{1e-12 * size});
      std::vector<std::string> lines;
      {
        std::ifstream in(file);
        for (std::string line; std::getline(in, line);)
          lines.push_back(line);
      }
      const auto section = [&](const std::string &name) {
        const auto it = std::find(lines.begin(), lines.end(), name);
        AssertThrow(it != lines.end(),
                    ExcMessage("gmsh wrote " + file + " without " + name));
        return std::size_t(it - lines.begin()) + 2; // after the count
      };
      std::map<unsigned int, std::size_t> line_of_node;
      std::map<unsigned int, Point<3>>    node;
      // gmsh's tag -> the boundary's number (0: an interior node).
      std::map<unsigned int, unsigned int> boundary_number;
      for (std::size_t l = section("$Nodes"); lines[l] != "$EndNodes"; ++l)
        {
          std::istringstream in(lines[l]);
          unsigned int       tag;
          Point<3>           p;
          in >> tag >> p[0] >> p[1] >> p[2];
          line_of_node[tag] = l;
          node[tag]         = p;
          const auto it     = number.find(p);
          boundary_number[tag] = it != number.end() ? it->second : 0;
        }
      std::map<unsigned int, Point<3>> moved;
      std::vector<Tetrahedron>         tetrahedra;
      for (std::size_t l = section("$Elements"); lines[l] != "$EndElements"; ++l)
        {
          std::istringstream in(lines[l]);
          unsigned int       tag, type, n_tags;
          in >> tag >> type >> n_tags;
          if (type != 9 && type != 11) // 6-node triangle, 10-node tetrahedron
            continue;
          for (unsigned int i = 0; i < n_tags; ++i)
            in >> tag;
          std::vector<unsigned int> nodes(type == 9 ? 6 : 10);
          for (auto &n : nodes)
            in >> n;
          const unsigned int n_corners = type == 9 ? 3 : 4;
          Tetrahedron        tetrahedron;
          for (unsigned int m = n_corners; m < nodes.size(); ++m)
            {
              double best = std::numeric_limits<double>::max();
              Edge   nearest, local;
              for (unsigned int a = 0; a < n_corners; ++a)
                for (unsigned int b = a + 1; b < n_corners; ++b)
                  {
                    const double distance = node.at(nodes[m]).distance(
                      (node.at(nodes[a]) + node.at(nodes[b])) / 2.);
                    if (distance < best)
                      {
                        best    = distance;
                        local   = {a, b};
                        nearest = edge(boundary_number.at(nodes[a]),
                                       boundary_number.at(nodes[b]));
                      }
                  }
              if (const auto it = surface.midpoints.find(nearest);
                  nearest.first > 0 && it != surface.midpoints.end())
                moved[nodes[m]] = it->second;
              if (type == 11)
                tetrahedron.edges[m - 4] = {local, nodes[m]};
            }
          if (type == 11)
            {
              std::copy(nodes.begin(), nodes.begin() + 4, tetrahedron.corners.begin());
              tetrahedra.push_back(tetrahedron);
            }
        }

      // A curved boundary edge can invert a new element that is thin next
      // to it; such elements keep gmsh's straight midpoints.
      const auto position = [&](const unsigned int tag) {
        const auto it = moved.find(tag);
        return it != moved.end() ? it->second : node.at(tag);
      };
      for (bool reverted = true; reverted;)
        {
          reverted = false;
          for (const auto &t : tetrahedra)
            if (std::any_of(t.edges.begin(), t.edges.end(), [&](const auto &e) {
                  return moved.count(e.second) > 0;
                }) &&
                (jacobian_ratio(t, position) < 0.2 || !matches_edges(t, position)))
              for (const auto &e : t.edges)
                reverted |= moved.erase(e.second) > 0;
        }
      AssertThrow(!tetrahedra.empty(),
                  ExcMessage("gmsh wrote no tetrahedra into " + file +
                             " (it could not fill the design's boundary)."));
      for (const auto &[tag, p] : moved)
        {
          std::ostringstream line;
          line << std::setprecision(17) << tag << " " << p[0] << " " << p[1]
               << " " << p[2];
          lines[line_of_node.at(tag)] = line.str();
        }
      std::ofstream out(file);
      for (const auto &line : lines)
        out << line << '\n';
      AssertThrow(out, ExcMessage("Cannot write " + file));
    }
  } // namespace



  void
  remesh_design(const DesignConfiguration &design, const std::string &msh_file)
  {
    const MPI_Comm comm = design.get_dof_handler().get_communicator();
    std::vector<double> local;
    for (const auto &face : locally_owned_boundary_faces(design))
      {
        for (const auto *nodes : {&face.corner, &face.midpoint})
          for (const auto &p : *nodes)
            for (unsigned int d = 0; d < 3; ++d)
              local.push_back(p[d]);
        local.push_back(face.boundary_id);
      }
    const auto  parts = Utilities::MPI::gather(comm, local, 0);
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          const std::string stem =
            (std::filesystem::path(msh_file).parent_path() /
             std::filesystem::path(msh_file).stem())
              .string();
          const auto surface = write_surface(parts, stem + ".surface.msh");
          std::ofstream geo(stem + ".geo");
          geo << "// softopt: a new mesh of the design inside its boundary\n"
              << "Merge \"" << std::filesystem::path(stem).filename().string()
              << ".surface.msh\";\n"
              << "// HXT: no slivers between the faces of walls one element\n"
              << "// thick, where the default Delaunay left some; one thread\n"
              << "// for a reproducible mesh.\n"
              << "Mesh.Algorithm3D = 10;\n"
              << "General.NumThreads = 1;\n"
              << "Surface Loop(1) = Surface{:};\n"
              << "Volume(1) = {1};\n"
              << "Physical Volume(1) = {1};\n";
          geo.close();
          AssertThrow(geo, ExcMessage("Cannot write " + stem + ".geo"));
          std::filesystem::remove(msh_file); // none of an earlier run
          const std::string log =
            run_gmsh("-3 -order 2 -format msh22 \"" + stem + ".geo\"", msh_file);
          if (!log.empty())
            error = "gmsh could not mesh the design " + log;
          else
            restore_curved_midpoints(msh_file, surface);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));
  }
} // namespace softopt
