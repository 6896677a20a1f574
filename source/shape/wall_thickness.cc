#include <deal.II/base/mpi.h>

#include <softopt/io/output_directory.h>
#include <softopt/physics/nodal_ad.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/wall_thickness.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace softopt
{
  namespace
  {
    using Kernel    = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Triangles = std::vector<Kernel::Triangle_3>;
    using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
    using Tree      = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

    /** The surface of @p faces, each split into k x k triangles on its
     * quadratic map (curved_triangles()), as indexed nodes and triangles,
     * with the design DoFs and weights of each node and the boundary id
     * of each triangle; points on shared edges are equal to the last bit. */
    void
    index_surface(const std::vector<BoundaryFace>  &faces,
                  const unsigned int                k,
                  WallThickness                    &wall,
                  std::vector<types::boundary_id>  &ids)
    {
      std::map<std::array<double, 3>, unsigned int> index;
      for (const auto &face : faces)
        {
          const std::array<const BoundaryFace::NodeDofs *, 6> dofs{
            {&face.corner_dofs[0], &face.corner_dofs[1], &face.corner_dofs[2],
             &face.midpoint_dofs[0], &face.midpoint_dofs[1], &face.midpoint_dofs[2]}};
          for (const auto &t : curved_triangles(face, k))
            {
              std::array<unsigned int, 3> triangle;
              for (unsigned int v = 0; v < 3; ++v)
                {
                  const auto &p = t[v];
                  const auto [it, added] =
                    index.emplace(std::array<double, 3>{{p.x[0], p.x[1], p.x[2]}},
                                  wall.nodes.size());
                  if (added)
                    {
                      wall.nodes.push_back(p.x);
                      wall.node_dofs.emplace_back();
                      for (unsigned int a = 0; a < 6; ++a)
                        if (p.weight[a] != 0)
                          wall.node_dofs.back().emplace_back(p.weight[a], *dofs[a]);
                    }
                  triangle[v] = it->second;
                }
              wall.triangles.push_back(triangle);
              ids.push_back(face.boundary_id);
            }
        }
    }

    /** What every ray shoots at, built once for the walls and the gaps:
     * the triangles in CGAL's AABB tree, the area-weighted outward normal
     * at each node (of its triangles off the mirror planes) and the
     * triangles of each mirror plane. Fills the rays' shared fields of
     * @p wall: around, on_mirror, unit_normal. Not copied or moved: the
     * tree points into the triangles. */
    struct Targets
    {
      Targets(WallThickness                         &wall,
              const std::vector<types::boundary_id> &ids,
              const std::set<types::boundary_id>    &mirrors)
        : ids(ids)
        , mirrors(mirrors)
        , normal(wall.nodes.size())
      {
        wall.around.assign(wall.nodes.size(), {});
        for (unsigned int t = 0; t < wall.triangles.size(); ++t)
          {
            const auto &[a, b, c] = wall.triangles[t];
            triangles.emplace_back(point(wall.nodes[a]), point(wall.nodes[b]), point(wall.nodes[c]));
            // Area-weighted outward normal (counter-clockwise from outside).
            const Tensor<1, 3> n =
              cross_product_3d(wall.nodes[b] - wall.nodes[a], wall.nodes[c] - wall.nodes[a]);
            wall.unit_normal.push_back(n / n.norm());
            wall.on_mirror.push_back(is_mirror(t));
            if (is_mirror(t))
              on_plane[ids[t]].push_back(t);
            for (const unsigned int v : wall.triangles[t])
              {
                if (!is_mirror(t))
                  normal[v] += n;
                wall.around[v].push_back(t);
              }
          }
        tree.insert(triangles.begin(), triangles.end());
        tree.build();
      }
      Targets(const Targets &) = delete;

      static Kernel::Point_3
      point(const Point<3> &p)
      {
        return Kernel::Point_3(p[0], p[1], p[2]);
      }

      bool
      is_mirror(const unsigned int t) const
      {
        return mirrors.count(ids[t]) > 0;
      }

      const std::vector<types::boundary_id>                  &ids;
      const std::set<types::boundary_id>                     &mirrors;
      Triangles                                               triangles;
      Tree                                                    tree;
      std::vector<Tensor<1, 3>>                               normal;
      std::map<types::boundary_id, std::vector<unsigned int>> on_plane;
    };

    /** The thickness at every node of the part's surface: the path along
     * the inward normal (outward with wall.outward) to the first triangle
     * of the part's surface, not one of the node's own. A mirror plane (a
     * symmetry boundary) is a cut: the body goes on beyond it. No ray
     * starts on one; a node on its rim takes the normal projected onto the
     * plane (the whole body's normal there, by symmetry) and its ray
     * ignores that plane; a ray that meets a plane is reflected and goes
     * on. */
    void
    shoot_rays(WallThickness &wall, const Targets &targets)
    {
      const auto &triangles = targets.triangles;
      const auto  is_mirror = [&](const unsigned int t) { return targets.is_mirror(t); };
      const auto &unit_normal = wall.unit_normal;
      wall.reflections.assign(wall.nodes.size(), {});
      wall.hit.assign(wall.nodes.size(), WallThickness::none);
      wall.differentiable.assign(wall.nodes.size(), false);
      wall.corner.assign(wall.nodes.size(), false);
      wall.thickness.assign(wall.nodes.size(), std::numeric_limits<double>::infinity());
      for (unsigned int i = 0; i < wall.nodes.size(); ++i)
        {
          Tensor<1, 3> normal = targets.normal[i];
          if (normal.norm() == 0) // on mirror planes only: inside the body
            continue;
          std::vector<unsigned int> skip = wall.around[i];
          Tensor<1, 3>              into_body; // away from the planes the node is on
          for (const unsigned int t : wall.around[i])
            if (is_mirror(t))
              {
                normal -= (normal * unit_normal[t]) * unit_normal[t];
                into_body -= unit_normal[t];
                const auto &plane = targets.on_plane.at(targets.ids[t]);
                skip.insert(skip.end(), plane.begin(), plane.end());
              }
          Point<3>     from      = wall.nodes[i];
          Tensor<1, 3> direction = (wall.outward ? 1. : -1.) * normal / normal.norm();
          // A ray exactly in a plane runs along the faces of the AABB boxes,
          // where CGAL's slab test is undecided: tilt it into the body by
          // 1e-6 rad, which changes the thickness by 1e-12 relative.
          if (into_body.norm() > 0)
            {
              direction += 1e-6 * into_body / into_body.norm();
              direction /= direction.norm();
            }
          double length = 0;
          for (unsigned int reflection = 0; reflection <= targets.mirrors.size(); ++reflection)
            {
              const Kernel::Ray_3 ray(Targets::point(from),
                                      Kernel::Vector_3(direction[0], direction[1], direction[2]));
              std::sort(skip.begin(), skip.end());
              const auto own = [&](const Triangles::const_iterator &id) {
                return std::binary_search(skip.begin(), skip.end(), id - triangles.begin());
              };
              const auto hit = targets.tree.first_intersection(ray, own);
              if (!hit)
                break;
              Point<3> at;
              if (const auto *p = boost::get<Kernel::Point_3>(&hit->first))
                at = Point<3>(p->x(), p->y(), p->z());
              else if (const auto *segment = boost::get<Kernel::Segment_3>(&hit->first))
                { // along a triangle: its end nearer the ray's start
                  const Point<3> a(segment->source().x(), segment->source().y(), segment->source().z());
                  const Point<3> b(segment->target().x(), segment->target().y(), segment->target().z());
                  at = a.distance(from) < b.distance(from) ? a : b;
                }
              const unsigned int t = hit->second - triangles.begin();
              length += at.distance(from);
              if (!is_mirror(t))
                {
                  wall.thickness[i] = length;
                  wall.hit[i]       = t;
                  // More than 60 degrees from facing the ray (along it
                  // included): the neighbouring face of a corner.
                  wall.corner[i] = std::abs(direction * unit_normal[t]) < 0.5;
                  // thickness_gradient() for a straight ray from a node off
                  // the planes that ends at no corner (never along its
                  // triangle, where the length jumps).
                  wall.differentiable[i] =
                    wall.reflections[i].empty() && into_body.norm() == 0 &&
                    boost::get<Kernel::Point_3>(&hit->first) != nullptr && !wall.corner[i];
                  break;
                }
              wall.reflections[i].push_back(t);
              // Reflected: it leaves that plane and cannot meet it again.
              direction -= 2 * (direction * unit_normal[t]) * unit_normal[t];
              from = at;
              const auto &plane = targets.on_plane.at(targets.ids[t]);
              skip.insert(skip.end(), plane.begin(), plane.end());
            }
          if (wall.corner[i])
            continue;
          if (wall.thickness[i] < wall.minimum)
            {
              wall.minimum = wall.thickness[i];
              wall.where   = wall.nodes[i];
            }
          else if (!std::isfinite(wall.thickness[i]))
            ++wall.n_without_opposite;
        }
    }

    /** wall_thickness() for each direction of @p outward on one sampled
     * surface and one tree. */
    std::vector<WallThickness>
    measure(const DesignConfiguration          &design,
            const std::set<types::boundary_id> &mirrors,
            const std::vector<bool>            &outward,
            const unsigned int                  subdivisions)
    {
      const auto                 comm  = design.get_dof_handler().get_communicator();
      const auto                 faces = gathered_boundary_faces(design);
      std::vector<WallThickness> walls(outward.size());
      std::string                error;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          try
            {
              WallThickness                   surface;
              std::vector<types::boundary_id> ids;
              index_surface(faces, subdivisions, surface, ids);
              const Targets targets(surface, ids, mirrors);
              for (unsigned int d = 0; d < outward.size(); ++d)
                {
                  walls[d]         = surface;
                  walls[d].outward = outward[d];
                  shoot_rays(walls[d], targets);
                }
            }
          catch (const std::exception &e)
            {
              error = std::string("The wall thickness could not be measured: ") + e.what();
            }
        }
      error = Utilities::MPI::broadcast(comm, error, 0); // thrown on every rank
      AssertThrow(error.empty(), ExcMessage(error));
      for (unsigned int d = 0; d < outward.size(); ++d)
        {
          auto &wall              = walls[d];
          wall.outward            = outward[d];
          wall.minimum            = Utilities::MPI::broadcast(comm, wall.minimum, 0);
          wall.where              = Utilities::MPI::broadcast(comm, wall.where, 0);
          wall.n_without_opposite = Utilities::MPI::broadcast(comm, wall.n_without_opposite, 0);
        }
      return walls;
    }
  } // namespace



  unsigned int
  surface_subdivisions(const DesignConfiguration &design, const double sampling_size)
  {
    if (sampling_size <= 0)
      return 2;
    // The mean length of the boundary faces' edges in the mesh (its
    // vertices, which a new mesh changes and the design does not).
    double length = 0, n = 0;
    for (const auto &cell : design.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            for (unsigned int l = 0; l < cell->face(f)->n_lines(); ++l)
              {
                length += cell->face(f)->line(l)->diameter();
                n += 1;
              }
    const auto comm = design.get_dof_handler().get_communicator();
    length          = Utilities::MPI::sum(length, comm);
    n               = Utilities::MPI::sum(n, comm);
    const double k = std::ceil(length / n / sampling_size);
    AssertThrow(k <= 64,
                ExcMessage("A sampling size of " + std::to_string(sampling_size) +
                           " mm splits each face of this mesh (mean boundary edge " +
                           std::to_string(length / n) + " mm) into " + std::to_string(k) +
                           " x " + std::to_string(k) + " triangles: at most 64 x 64. "
                           "Choose a larger Sampling size."));
    return std::max(2u, static_cast<unsigned int>(k));
  }



  WallThickness
  wall_thickness(const DesignConfiguration          &design,
                 const std::set<types::boundary_id> &mirrors,
                 const bool                          outward,
                 const unsigned int                  subdivisions)
  {
    return std::move(measure(design, mirrors, {outward}, subdivisions)[0]);
  }



  std::pair<WallThickness, WallThickness>
  walls_and_gaps(const DesignConfiguration &design, const unsigned int subdivisions)
  {
    auto both = measure(design, {}, {false, true}, subdivisions);
    return {std::move(both[0]), std::move(both[1])};
  }



  std::vector<std::pair<unsigned int, Tensor<1, 3>>>
  thickness_gradient(const WallThickness &wall, const unsigned int i)
  {
    using AD = NodalAD::AD;
    if (!wall.differentiable[i])
      return {};
    // The nodes the ray depends on, each an independent variable (3 AD
    // components).
    std::map<unsigned int, unsigned int> variable;
    const auto add = [&](const unsigned int t) {
      for (const unsigned int v : wall.triangles[t])
        variable.emplace(v, variable.size());
    };
    variable.emplace(i, 0);
    for (const unsigned int t : wall.around[i])
      add(t);
    add(wall.hit[i]);
    const unsigned int n = 3 * variable.size();
    const auto         X = [&](const unsigned int v) {
      Tensor<1, 3, AD> x;
      const unsigned int k = variable.at(v);
      for (unsigned int c = 0; c < 3; ++c)
        x[c] = AD(n, 3 * k + c, wall.nodes[v][c]);
      return x;
    };
    const auto normal_of = [&](const unsigned int t) {
      const auto &[a, b, c] = wall.triangles[t];
      const auto xa         = X(a);
      return cross_product_3d(X(b) - xa, X(c) - xa);
    };

    // The ray as shoot_rays() cast it, along the mean normal, and the
    // distance to the plane through corner a of the hit triangle with its
    // normal m: (X_a - X_i) . m / (direction . m).
    Tensor<1, 3, AD> normal;
    for (const unsigned int t : wall.around[i])
      normal += normal_of(t);
    // (AD temporaries: Sacado's expressions do not enter deal.II's tensors.)
    const AD               normal_norm = std::sqrt(normal * normal);
    const Tensor<1, 3, AD> direction   = (wall.outward ? 1. : -1.) * normal / normal_norm;
    const Tensor<1, 3, AD> from        = X(i);
    const unsigned int     t = wall.hit[i];
    const Tensor<1, 3, AD> m = normal_of(t);
    const AD               length = ((X(wall.triangles[t][0]) - from) * m) / (direction * m);

    std::vector<std::pair<unsigned int, Tensor<1, 3>>> gradient;
    for (const auto &[v, k] : variable)
      {
        Tensor<1, 3> d;
        for (unsigned int c = 0; c < 3; ++c)
          d[c] = length.size() > 0 ? length.dx(3 * k + c) : 0.;
        gradient.emplace_back(v, d);
      }
    return gradient;
  }



  void
  write_wall_thickness_vtu(const WallThickness &wall, const std::string &file)
  {
    // ParaView's XML unstructured grid, ASCII: triangles (VTK type 5).
    std::ostringstream vtu;
    vtu << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << wall.nodes.size()
        << "\" NumberOfCells=\"" << wall.triangles.size() << "\">\n"
        << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    vtu.precision(10);
    for (const auto &p : wall.nodes)
      vtu << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    vtu << "</DataArray>\n</Points>\n<Cells>\n"
        << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto &t : wall.triangles)
      vtu << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    vtu << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t t = 1; t <= wall.triangles.size(); ++t)
      vtu << 3 * t << '\n';
    vtu << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < wall.triangles.size(); ++t)
      vtu << "5\n";
    const std::string name = wall.outward ? "gap_mm" : "wall_thickness_mm";
    vtu << "</DataArray>\n</Cells>\n<PointData Scalars=\"" << name << "\">\n"
        << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < wall.thickness.size(); ++i) // -1: no opposite surface
      vtu << (wall.corner[i] ? -2. : std::isfinite(wall.thickness[i]) ? wall.thickness[i] : -1.)
          << '\n';
    vtu << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    write_whole_file(file, vtu.str());
  }
} // namespace softopt
