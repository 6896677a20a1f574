#include <deal.II/base/mpi.h>

#include <softopt/geometry/gmsh_mesh.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/quadratic_tetrahedron.h>
#include <softopt/shape/remesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

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

    /** The P2 surface of a face with @p part's nodes at @p t: the point at
     * barycentric coordinates (n - i - j, i, j) / n. Points on an edge are
     * computed from that edge's nodes alone, from its lexicographically
     * smaller end, so neighbouring faces get them equal bit for bit. */
    Point<3>
    surface_point(const std::vector<double> &part,
                  const std::size_t          t,
                  const unsigned int         i,
                  const unsigned int         j,
                  const unsigned int         n)
    {
      const auto corner = [&](const unsigned int k) { return point(part, t + 3 * k); };
      // midpoint(k): the midside node opposite corner k.
      const auto midpoint = [&](const unsigned int k) { return point(part, t + 9 + 3 * k); };
      // The edge from corner a to b, k/n of the way.
      const auto on_edge = [&](unsigned int a, unsigned int b, const unsigned int m, unsigned int k) {
        if (PointLess()(corner(b), corner(a)))
          {
            std::swap(a, b);
            k = n - k;
          }
        const double s = double(k) / n;
        return Point<3>((1 - s) * (1 - 2 * s) * corner(a) + s * (2 * s - 1) * corner(b) +
                        4 * s * (1 - s) * midpoint(m));
      };
      if (j == 0)
        return on_edge(0, 1, 2, i);
      if (i == 0)
        return on_edge(0, 2, 1, j);
      if (i + j == n)
        return on_edge(1, 2, 0, j);
      const double l[3] = {double(n - i - j) / n, double(i) / n, double(j) / n};
      Point<3>     x;
      for (unsigned int k = 0; k < 3; ++k)
        x += l[k] * (2 * l[k] - 1) * corner(k) +
             4 * l[(k + 1) % 3] * l[(k + 2) % 3] * midpoint(k);
      return x;
    }

    /**
     * Writes the boundary triangles (corners only) with their boundary ids
     * as discrete surfaces, in gmsh's format 2.2. With @p n > 1 each face
     * is split into n^2 triangles whose nodes, and the midside nodes of
     * whose edges, lie on the face's P2 surface: a finer triangulation of
     * the same curved body.
     */
    Surface
    write_surface(const std::vector<std::vector<double>> &parts,
                  const std::string                      &file,
                  const unsigned int                      n)
    {
      Surface surface;
      auto   &number    = surface.number;
      auto   &midpoints = surface.midpoints;
      // Per face, the (i, j) of the sub-triangles' corners on the grid of
      // step 1/n: "up" ones (i, j), (i+1, j), (i, j+1) and "down" ones
      // (i+1, j), (i+1, j+1), (i, j+1), oriented as the face.
      std::vector<std::array<std::array<unsigned int, 2>, 3>> pattern;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; i + j < n; ++j)
          {
            pattern.push_back({{{{i, j}}, {{i + 1, j}}, {{i, j + 1}}}});
            if (i + j + 1 < n)
              pattern.push_back({{{{i + 1, j}}, {{i + 1, j + 1}}, {{i, j + 1}}}});
          }
      for (const auto &part : parts)
        for (std::size_t t = 0; t < part.size(); t += face_size)
          for (unsigned int i = 0; i <= n; ++i)
            for (unsigned int j = 0; i + j <= n; ++j)
              number.emplace(surface_point(part, t, i, j, n), 0);
      GmshMesh mesh;
      for (auto &[p, i] : number)
        {
          i = mesh.nodes.size() + 1;
          mesh.nodes[i] = p;
        }
      // The triangles as (boundary id, corners), sorted: the same file
      // (and so the same mesh) on any number of MPI ranks.
      std::vector<std::array<unsigned int, 4>> triangles;
      for (const auto &part : parts)
        for (std::size_t t = 0; t < part.size(); t += face_size)
          for (const auto &corners : pattern)
            {
              std::array<unsigned int, 4> triangle;
              triangle[0] = static_cast<unsigned int>(part[t + 18]);
              for (unsigned int v = 0; v < 3; ++v)
                triangle[v + 1] =
                  number.at(surface_point(part, t, corners[v][0], corners[v][1], n));
              triangles.push_back(triangle);
              // The midside node of each edge: its grid midpoint, on the
              // grid of step 1/(2n).
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const auto &a = corners[(k + 1) % 3], &b = corners[(k + 2) % 3];
                  midpoints[edge(triangle[1 + (k + 1) % 3], triangle[1 + (k + 2) % 3])] =
                    surface_point(part, t, a[0] + b[0], a[1] + b[1], 2 * n);
                }
            }
      std::sort(triangles.begin(), triangles.end());
      for (const auto &[id, a, b, c] : triangles)
        // Physical and elementary tag: the boundary id.
        mesh.elements.push_back({0, 2, {id, id}, {a, b, c}});
      write_gmsh_mesh(mesh, file);
      return surface;
    }

    /** The mean length of the boundary faces' straight edges, over
     * @p parts. */
    double
    mean_edge_length(const std::vector<std::vector<double>> &parts)
    {
      double       sum = 0;
      std::size_t  count = 0;
      for (const auto &part : parts)
        for (std::size_t t = 0; t < part.size(); t += face_size)
          for (unsigned int k = 0; k < 3; ++k, ++count)
            sum += point(part, t + 3 * k).distance(point(part, t + 3 * ((k + 1) % 3)));
      return count > 0 ? sum / count : 0;
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
     * straight. Returns the worst mean ratio of the tetrahedra's corners.
     */
    double
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

      double worst = 1;
      for (const auto &t : tetrahedra)
        worst = std::min(worst, mean_ratio(nodes(t, position).corners));
      return worst;
    }



    /** Every boundary face of @p design in the layout of face_size; on
     * rank 0 one part per rank, elsewhere none. Collective. */
    std::vector<std::vector<double>>
    gathered_faces(const DesignConfiguration &design)
    {
      std::vector<double> local;
      for (const auto &face : locally_owned_boundary_faces(design))
        {
          for (const auto *nodes : {&face.corner, &face.midpoint})
            for (const auto &p : *nodes)
              for (unsigned int d = 0; d < 3; ++d)
                local.push_back(p[d]);
          local.push_back(face.boundary_id);
        }
      return Utilities::MPI::gather(design.get_dof_handler().get_communicator(), local, 0);
    }
  } // namespace



  double
  mean_boundary_edge_length(const DesignConfiguration &design)
  {
    const MPI_Comm comm = design.get_dof_handler().get_communicator();
    return Utilities::MPI::broadcast(comm, mean_edge_length(gathered_faces(design)), 0);
  }



  std::string
  NewMesh::note() const
  {
    if (!meshed_twice)
      return "";
    std::ostringstream text;
    text << std::setprecision(2) << "gmsh's HXT left an element of mean ratio "
         << hxt_worst_quality << "; ";
    if (delaunay_failed)
      text << "gmsh's Delaunay failed on the design (its message: the "
           << ".delaunay.log beside the mesh): HXT's mesh is used";
    else
      text << "its Delaunay mesh, worst " << delaunay_worst_quality << ", "
           << (delaunay ? "is used" : "is no better: HXT's is used");
    return text.str();
  }



  NewMesh
  remesh_design(const DesignConfiguration &design,
                const std::string         &msh_file,
                const double               mesh_size,
                const double               sliver_quality)
  {
    const MPI_Comm comm  = design.get_dof_handler().get_communicator();
    const auto     parts = gathered_faces(design);
    std::string    error;
    NewMesh        result;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          const std::string stem =
            (std::filesystem::path(msh_file).parent_path() /
             std::filesystem::path(msh_file).stem())
              .string();
          // Each face split n x n: edges of at most mesh_size on average.
          const double       mean_edge = mean_edge_length(parts);
          const unsigned int n =
            mesh_size > 0 ?
              std::max(1u, static_cast<unsigned int>(std::ceil(mean_edge / mesh_size - 1e-9))) :
              1;
          const auto surface = write_surface(parts, stem + ".surface.msh", n);

          // gmsh's 3D algorithm 10 (HXT) or 1 (Delaunay) into @p file.
          const auto mesh_with = [&](const unsigned int algorithm,
                                     const std::string &geo_file,
                                     const std::string &file) {
            std::ofstream geo(geo_file);
            geo << "// softopt: a new mesh of the design inside its boundary\n"
                << "Merge \"" << std::filesystem::path(stem).filename().string()
                << ".surface.msh\";\n"
                << "Mesh.Algorithm3D = " << algorithm << ";\n"
                << "// One thread for a reproducible mesh.\n"
                << "General.NumThreads = 1;\n";
            geo << "Surface Loop(1) = Surface{:};\n"
                << "Volume(1) = {1};\n"
                << "Physical Volume(1) = {1};\n";
            // The split boundary's edges can be as short as half the size (n
            // rounds up). gmsh would fill the whole body at their size (the
            // gripper's schedule mesh at 0.8 mm: 272,152 tetrahedra); the
            // size grows from theirs at the boundary to mesh_size at 2
            // mesh_size inside instead (200,434). An abrupt jump to mesh_size
            // made fewer (149,244) but flat ones, the worst near the remesh
            // guard's quality of 0.2 (doc/benchmarks.md, session 20).
            if (mesh_size > 0)
              geo << "Mesh.MeshSizeMax = " << mesh_size << ";\n"
                  << "Mesh.MeshSizeExtendFromBoundary = 0;\n"
                  << "Field[1] = Distance;\n"
                  << "Field[1].SurfacesList = {Surface{:}};\n"
                  << "Field[2] = Threshold;\n"
                  << "Field[2].InField = 1;\n"
                  << "Field[2].SizeMin = " << std::min(mesh_size, mean_edge / n)
                  << ";\n"
                  << "Field[2].SizeMax = " << mesh_size << ";\n"
                  << "Field[2].DistMin = 0;\n"
                  << "Field[2].DistMax = " << 2 * mesh_size << ";\n"
                  << "Background Field = 2;\n";
            geo.close();
            AssertThrow(geo, ExcMessage("Cannot write " + geo_file));
            std::filesystem::remove(file); // none of an earlier run
            const std::string log =
              run_gmsh({"-3", "-order", "2", "-format", "msh22", geo_file}, file);
            if (!log.empty())
              throw std::runtime_error("gmsh could not mesh the design " + log);
            return restore_curved_midpoints(file, surface);
          };

          // HXT first: the default Delaunay left slivers between the faces
          // of walls one element thick. HXT in turn can leave a flat
          // tetrahedron on a large boundary face beside a crease, its
          // interior node in the face's plane (the contractor's 0.8 mm mesh
          // of session 38: mean ratio 0.0075, where Delaunay's worst was
          // 0.21); the optimizer flattens such an element further, and
          // the remesh guard cannot help, since the mesh itself is below
          // it. Then Delaunay meshes the design too, and the better worst
          // element wins.
          result.worst_quality = mesh_with(10, stem + ".geo", msh_file);
          if (result.worst_quality < sliver_quality)
            {
              const std::string other = stem + ".delaunay.msh";
              result.meshed_twice      = true;
              result.hxt_worst_quality = result.worst_quality;
              double delaunay = -1;
              try
                {
                  delaunay = mesh_with(1, stem + ".delaunay.geo", other);
                }
              catch (const std::exception &e)
                {
                  // HXT's mesh is still a mesh of the design: keep it.
                  result.delaunay_failed = true;
                  std::ofstream(stem + ".delaunay.log") << e.what() << '\n';
                }
              result.delaunay_worst_quality = delaunay;
              std::error_code ignored;
              if (result.delaunay_failed)
                std::filesystem::remove_all(other, ignored); // a partial file
              else if (delaunay > result.worst_quality)
                {
                  std::filesystem::rename(other, msh_file);
                  result.worst_quality = delaunay;
                  result.delaunay      = true;
                }
              else
                std::filesystem::remove(other);
            }
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));
    return Utilities::MPI::broadcast(comm, result, 0);
  }
} // namespace softopt
