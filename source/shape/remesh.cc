#include <deal.II/base/mpi.h>

#include <softopt/geometry/gmsh_mesh.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/quadratic_tetrahedron.h>
#include <softopt/shape/remesh.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>

namespace softopt
{
  namespace
  {
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
      /** Exact: the faces of neighbouring cells read a shared node from
       * the same DoFs, so equal nodes are equal bit for bit. */
      std::map<Point<3>, unsigned int, PointLess> number;
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
      GmshMesh mesh;
      for (auto &[p, i] : number)
        {
          i = mesh.nodes.size() + 1;
          mesh.nodes[i] = p;
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
      for (const auto &[id, a, b, c] : triangles)
        // Physical and elementary tag: the boundary id.
        mesh.elements.push_back({0, 2, {id, id}, {a, b, c}});
      write_gmsh_mesh(mesh, file);
      return surface;
    }

    /** A quadratic tetrahedron of gmsh's mesh: its corner tags and, per
     * edge, the edge's corners (local) and the midside node's tag. */
    struct Tetrahedron
    {
      std::array<long, 4>                  corners;
      std::array<std::pair<Edge, long>, 6> edges;
    };

    /** The nodes of @p t, with positions from @p position. */
    template <typename Position>
    QuadraticTetrahedron
    nodes(const Tetrahedron &t, const Position &position)
    {
      QuadraticTetrahedron result;
      for (unsigned int a = 0; a < 4; ++a)
        result.corners[a] = position(t.corners[a]);
      for (unsigned int e = 0; e < 6; ++e)
        result.edges[e] = {t.edges[e].first, position(t.edges[e].second)};
      return result;
    }



    /**
     * Whether every midside node of @p t is nearest to the straight midpoint
     * of its own edge, as split_quadratic_gmsh_mesh() assigns midside nodes
     * when it reads the file back.
     */
    bool
    matches_edges(const QuadraticTetrahedron &t)
    {
      const std::vector<Point<3>> corners(t.corners.begin(), t.corners.end());
      for (const auto &[own, node] : t.edges)
        if (nearest_edge(corners, node) != own)
          return false;
      return true;
    }

    /**
     * Moves the midside nodes of the boundary edges in gmsh's quadratic
     * @p file, which gmsh put at the straight edges' midpoints, to the
     * design's curved ones, so the new mesh has the design's P2 surface.
     * gmsh's corner nodes are found among the boundary's by position (gmsh
     * renumbers them). Where that would make an element's Jacobian vary by
     * more than a factor 5 (or invert it), or put a midside node nearer to
     * another edge's midpoint than to its own, the element's edges stay
     * straight.
     */
    void
    restore_curved_midpoints(const std::string &file, const Surface &surface)
    {
      double size = 1;
      for (const auto &[p, n] : surface.number)
        size = std::max(size, p.norm());
      const std::map<Point<3>, unsigned int, NearlyLess> number(
        surface.number.begin(), surface.number.end(), NearlyLess{1e-12 * size});
      GmshMesh mesh = read_gmsh_mesh(file);
      // gmsh's tag -> the boundary's number (0: an interior node).
      std::map<long, unsigned int> boundary_number;
      for (const auto &[tag, p] : mesh.nodes)
        {
          const auto it        = number.find(p);
          boundary_number[tag] = it != number.end() ? it->second : 0;
        }

      std::map<long, Point<3>> moved;
      std::vector<Tetrahedron> tetrahedra;
      for (const auto &e : mesh.elements)
        {
          std::vector<Point<3>> corners;
          for (unsigned int v = 0; v < e.n_corners(); ++v)
            corners.push_back(mesh.nodes.at(e.nodes[v]));
          Tetrahedron t;
          for (unsigned int m = e.n_corners(); m < e.nodes.size(); ++m)
            {
              const Edge local = nearest_edge(corners, mesh.nodes.at(e.nodes[m]));
              const Edge boundary_edge =
                edge(boundary_number.at(e.nodes[local.first]),
                     boundary_number.at(e.nodes[local.second]));
              if (const auto it = surface.midpoints.find(boundary_edge);
                  boundary_edge.first > 0 && it != surface.midpoints.end())
                moved[e.nodes[m]] = it->second;
              if (e.type == 11)
                t.edges[m - 4] = {local, e.nodes[m]};
            }
          if (e.type == 11)
            {
              std::copy(e.nodes.begin(), e.nodes.begin() + 4, t.corners.begin());
              tetrahedra.push_back(t);
            }
        }
      AssertThrow(!tetrahedra.empty(),
                  ExcMessage("gmsh wrote no quadratic tetrahedra into " + file +
                             " (it could not fill the design's boundary)."));

      // A curved boundary edge can invert a new element that is thin next
      // to it; such elements keep gmsh's straight midpoints.
      const auto position = [&](const long tag) {
        const auto it = moved.find(tag);
        return it != moved.end() ? it->second : mesh.nodes.at(tag);
      };
      for (bool reverted = true; reverted;)
        {
          reverted = false;
          for (const auto &t : tetrahedra)
            if (std::any_of(t.edges.begin(), t.edges.end(), [&](const auto &e) {
                  return moved.count(e.second) > 0;
                }))
              if (const auto curved = nodes(t, position);
                  jacobian_ratio(curved) < 0.2 || !matches_edges(curved))
                for (const auto &e : t.edges)
                  reverted |= moved.erase(e.second) > 0;
        }
      for (const auto &[tag, p] : moved)
        mesh.nodes[tag] = p;
      write_gmsh_mesh(mesh, file);
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
            run_gmsh({"-3", "-order", "2", "-format", "msh22", stem + ".geo"},
                     msh_file);
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
