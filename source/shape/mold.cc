#include <deal.II/base/exceptions.h>

#include <softopt/shape/mold.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <numeric>
#include <sstream>

namespace softopt
{
  namespace
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    // Booleans with exact constructions: the intersection points of one
    // corefinement are the input of the next, and the parts must fill the
    // box exactly.
    using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
    using Solid = CGAL::Surface_mesh<Epeck::Point_3>;
    // Queries (ray shooting, inside tests) on double copies.
    using Epick   = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Surface = CGAL::Surface_mesh<Epick::Point_3>;
    using Tree =
      CGAL::AABB_tree<CGAL::AABB_traits<Epick, CGAL::AABB_face_graph_triangle_primitive<Surface>>>;

    using Triangle = std::array<std::size_t, 3>;

    /** Points and triangles, indices into the points. */
    struct Soup
    {
      std::vector<Point<3>> points;
      std::vector<Triangle> triangles;
    };

    /** @p x on a grid of 2^-14 mm (6.1e-5 mm, far below what a printer
     * resolves). Points that round-off puts a hair apart (a box corner
     * 1e-16 mm off the split plane, mesh nodes 4e-14 mm off it) coincide,
     * instead of leaving slivers that the STL's floats cannot hold; and
     * every input coordinate below 1024 mm is a float, as the STL stores
     * it. */
    double
    snapped(const double x)
    {
      return std::ldexp(std::round(std::ldexp(x, 14)), -14);
    }

    /** A closed solid from @p soup (its points snapped), oriented to bound
     * its volume. */
    Solid
    solid(const Soup &soup)
    {
      std::vector<Epeck::Point_3> points;
      for (const auto &p : soup.points)
        points.emplace_back(snapped(p[0]), snapped(p[1]), snapped(p[2]));
      std::vector<std::vector<std::size_t>> polygons;
      for (const auto &t : soup.triangles)
        polygons.push_back({t[0], t[1], t[2]});
      Solid mesh;
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      if (CGAL::is_closed(mesh))
        PMP::orient_to_bound_a_volume(mesh);
      return mesh;
    }

    /** The double nearest to @p p's exact coordinates (a lazy number's
     * double can change once its exact value is known), without -0. */
    Point<3>
    point(const Epeck::Point_3 &p)
    {
      return Point<3>(CGAL::to_double(CGAL::exact(p.x())) + 0.0,
                      CGAL::to_double(CGAL::exact(p.y())) + 0.0,
                      CGAL::to_double(CGAL::exact(p.z())) + 0.0);
    }

    /** A double copy of @p mesh for queries. */
    Surface
    approximate(const Solid &mesh)
    {
      Surface                                      copy;
      std::map<Solid::Vertex_index, Surface::Vertex_index> vertex;
      for (const auto v : mesh.vertices())
        {
          const auto p = point(mesh.point(v));
          vertex[v]    = copy.add_vertex(Epick::Point_3(p[0], p[1], p[2]));
        }
      for (const auto f : mesh.faces())
        {
          std::vector<Surface::Vertex_index> corners;
          for (const auto v : vertices_around_face(mesh.halfedge(f), mesh))
            corners.push_back(vertex[v]);
          copy.add_face(corners);
        }
      return copy;
    }

    enum class Operation
    {
      unite,
      subtract,
      intersect
    };

    /** a (op) b; both must be closed and bound a volume. */
    Solid
    boolean(Solid a, Solid b, const Operation op, const std::string &what)
    {
      Solid      out;
      const bool ok = op == Operation::unite    ? PMP::corefine_and_compute_union(a, b, out) :
                      op == Operation::subtract ? PMP::corefine_and_compute_difference(a, b, out) :
                                                  PMP::corefine_and_compute_intersection(a, b, out);
      AssertThrow(ok,
                  ExcMessage("The mold could not be built: " + what +
                             " is not a closed manifold (CGAL's corefinement). A "
                             "different Mold / Split plane normal or Wall thickness "
                             "may avoid the degenerate contact."));
      return out;
    }

    /** An orthonormal pair perpendicular to the unit vector @p a, the first
     * along @p hint where it is not parallel to a. */
    std::array<Tensor<1, 3>, 2>
    perpendicular(const Tensor<1, 3> &a, const Tensor<1, 3> &hint)
    {
      Tensor<1, 3> e1 = hint - (hint * a) * a;
      if (e1.norm() < 1e-8)
        e1 = std::abs(a[0]) < 0.9 ? Tensor<1, 3>({1, 0, 0}) : Tensor<1, 3>({0, 1, 0});
      e1 = e1 - (e1 * a) * a;
      e1 /= e1.norm();
      return {{e1, cross_product_3d(a, e1)}};
    }

    /** A prism of @p n sides approximating the cylinder of radius @p r from
     * @p from to @p to; two of its side edges lie in the plane spanned by the
     * axis and @p hint. */
    Solid
    cylinder(const Point<3>     &from,
             const Point<3>     &to,
             const double        r,
             const Tensor<1, 3> &hint,
             const unsigned int  n = 48)
    {
      Tensor<1, 3> a = to - from;
      a /= a.norm();
      const auto e = perpendicular(a, hint);
      Soup       soup;
      soup.points = {from, to};
      for (const Point<3> &end : {from, to})
        for (unsigned int i = 0; i < n; ++i)
          {
            const double phi = 2 * M_PI * i / n;
            soup.points.push_back(end + r * (std::cos(phi) * e[0] + std::sin(phi) * e[1]));
          }
      for (unsigned int i = 0; i < n; ++i)
        {
          const std::size_t b0 = 2 + i, b1 = 2 + (i + 1) % n, t0 = b0 + n, t1 = b1 + n;
          soup.triangles.push_back(Triangle{{0, b1, b0}});
          soup.triangles.push_back(Triangle{{1, t0, t1}});
          soup.triangles.push_back(Triangle{{b0, b1, t1}});
          soup.triangles.push_back(Triangle{{b0, t1, t0}});
        }
      return solid(soup);
    }

    /** A sphere of radius @p r about @p c (latitude rings about the axis
     * @p pole; its equator is a ring, so the plane normal to @p pole through
     * c cuts it along its edges). */
    Solid
    sphere(const Point<3> &c, const double r, const Tensor<1, 3> &pole)
    {
      const unsigned int n_rings = 11, n_around = 24; // odd: a ring at the equator
      const auto         e = perpendicular(pole, Tensor<1, 3>({1, 0, 0}));
      Soup               soup;
      soup.points = {c - r * pole, c + r * pole};
      for (unsigned int j = 1; j <= n_rings; ++j)
        {
          const double theta = M_PI * j / (n_rings + 1) - M_PI / 2;
          for (unsigned int i = 0; i < n_around; ++i)
            {
              const double phi = 2 * M_PI * i / n_around;
              soup.points.push_back(c + r * (std::sin(theta) * pole +
                                             std::cos(theta) * (std::cos(phi) * e[0] +
                                                                std::sin(phi) * e[1])));
            }
        }
      const auto ring = [&](const unsigned int j, const unsigned int i) {
        return std::size_t(2 + (j - 1) * n_around + i % n_around);
      };
      for (unsigned int i = 0; i < n_around; ++i)
        {
          soup.triangles.push_back(Triangle{{0, ring(1, i + 1), ring(1, i)}});
          soup.triangles.push_back(Triangle{{1, ring(n_rings, i), ring(n_rings, i + 1)}});
          for (unsigned int j = 1; j < n_rings; ++j)
            {
              soup.triangles.push_back(Triangle{{ring(j, i), ring(j, i + 1), ring(j + 1, i + 1)}});
              soup.triangles.push_back(Triangle{{ring(j, i), ring(j + 1, i + 1), ring(j + 1, i)}});
            }
        }
      return solid(soup);
    }

    /** The box [x0, x1] x [y0, y1] x [z0, z1] (in the mold's frame). */
    Solid
    box(const std::array<double, 2> &x, const std::array<double, 2> &y, const std::array<double, 2> &z)
    {
      Soup soup;
      for (unsigned int k = 0; k < 8; ++k)
        soup.points.emplace_back(x[k & 1], y[(k >> 1) & 1], z[(k >> 2) & 1]);
      // Two triangles per face of the cube with corners numbered by bits.
      const std::array<std::array<std::size_t, 4>, 6> faces{
        {{{0, 1, 3, 2}}, {{4, 6, 7, 5}}, {{0, 4, 5, 1}}, {{2, 3, 7, 6}}, {{0, 2, 6, 4}}, {{1, 5, 7, 3}}}};
      for (const auto &f : faces)
        {
          soup.triangles.push_back(Triangle{{f[0], f[1], f[2]}});
          soup.triangles.push_back(Triangle{{f[0], f[2], f[3]}});
        }
      return solid(soup);
    }

    double
    volume(const Solid &mesh)
    {
      return CGAL::to_double(PMP::volume(mesh));
    }

    /** Whether the corners of @p part stay apart as the floats of an STL
     * file: two vertices that become one leave it open or pinched. */
    bool
    apart_as_floats(const MoldPart &part)
    {
      std::set<std::array<double, 3>> vertices;
      std::set<std::array<float, 3>>  written;
      for (std::size_t i = 0; i + 2 < part.corners.size(); i += 3)
        {
          const double *p = &part.corners[i];
          vertices.insert({{p[0], p[1], p[2]}});
          written.insert({{float(p[0]), float(p[1]), float(p[2])}});
        }
      return written.size() == vertices.size();
    }

    /** The part @p mesh; its volume inside @p box if given (a core's stem
     * reaches beyond the mold), else all of it. */
    MoldPart
    part(const std::string &name, const Solid &mesh, const Solid *box = nullptr)
    {
      MoldPart result;
      result.name = name;
      std::map<Solid::Vertex_index, Point<3>> at; // each vertex once
      for (const auto v : mesh.vertices())
        at[v] = point(mesh.point(v));
      for (const auto f : mesh.faces())
        for (const auto v : vertices_around_face(mesh.halfedge(f), mesh))
          result.corners.insert(result.corners.end(), {at[v][0], at[v][1], at[v][2]});
      std::vector<Solid::Halfedge_index> pinched;
      PMP::non_manifold_vertices(mesh, std::back_inserter(pinched));
      result.closed   = CGAL::is_closed(mesh);
      result.manifold = result.closed && pinched.empty() && CGAL::is_valid_polygon_mesh(mesh);
      result.volume        = volume(mesh);
      result.volume_in_box =
        box ? volume(boolean(mesh, *box, Operation::intersect, name)) : result.volume;
      return result;
    }

    /** The soup of the triangles of @p corners whose id is (not) in @p ids,
     * with corners that are equal to the last bit merged. */
    Soup
    select(const std::vector<double>              &corners,
           const std::vector<types::boundary_id> &boundary_ids,
           const std::set<types::boundary_id>    &ids,
           const bool                             in)
    {
      Soup                                          soup;
      std::map<std::array<double, 3>, std::size_t> index;
      for (std::size_t t = 0; t < boundary_ids.size(); ++t)
        if ((ids.count(boundary_ids[t]) > 0) == in)
          {
            Triangle triangle;
            for (unsigned int v = 0; v < 3; ++v)
              {
                const std::array<double, 3> p{
                  {corners[9 * t + 3 * v], corners[9 * t + 3 * v + 1], corners[9 * t + 3 * v + 2]}};
                const auto [it, added] = index.emplace(p, soup.points.size());
                if (added)
                  soup.points.emplace_back(p[0], p[1], p[2]);
                triangle[v] = it->second;
              }
            soup.triangles.push_back(triangle);
          }
      return soup;
    }

    /** The connected pieces of @p soup (triangles sharing corners). */
    std::vector<Soup>
    pieces(const Soup &soup)
    {
      std::vector<std::size_t> parent(soup.points.size());
      std::iota(parent.begin(), parent.end(), 0);
      const auto root = [&](std::size_t i) {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      };
      for (const auto &t : soup.triangles)
        for (unsigned int v = 1; v < 3; ++v)
          parent[root(t[v])] = root(t[0]);
      std::map<std::size_t, Soup> by_root;
      for (const auto &t : soup.triangles)
        {
          Soup &piece = by_root[root(t[0])];
          piece.triangles.push_back(t); // renumbered below
        }
      std::vector<Soup> result;
      for (auto &[r, piece] : by_root)
        {
          std::map<std::size_t, std::size_t> renumber;
          for (auto &t : piece.triangles)
            for (auto &v : t)
              {
                const auto [it, added] = renumber.emplace(v, piece.points.size());
                if (added)
                  piece.points.push_back(soup.points[v]);
                v = it->second;
              }
          result.push_back(std::move(piece));
        }
      return result;
    }

    /** The centroid of the volume a closed, outward soup bounds. */
    Point<3>
    centroid(const Soup &soup)
    {
      double       v = 0;
      Tensor<1, 3> moment;
      for (const auto &t : soup.triangles)
        {
          const auto  &a = soup.points[t[0]], &b = soup.points[t[1]], &c = soup.points[t[2]];
          const double dv = a * cross_product_3d(b, c) / 6; // the tetrahedron with the origin
          v += dv;
          moment += dv * (a + b + c) / 4;
        }
      return Point<3>(moment / v);
    }

    /** "(x, y, z) mm". */
    std::string
    str(const Point<3> &p, const std::string &unit = " mm")
    {
      std::ostringstream s;
      s.precision(4);
      s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")" << unit;
      return s.str();
    }

    /**
     * The molding faces of @p half (those on the cast part, a core or a
     * sprue: @p filled) that cannot release when it moves along @p pull:
     * those from which a ray along the pull, started @p tolerance into the
     * half, meets @p filled. A wall leaning into the pull, or a bulge of the
     * part beyond the face, is in its way; an overhang smaller than the
     * tolerance (the sagitta of a flat facet on a curved wall where the
     * plane cuts it) is not.
     */
    Undercut
    undercut(const std::string  &name,
             const Solid        &half,
             const Tensor<1, 3> &pull,
             const Tree         &filled,
             const double        tolerance)
    {
      Undercut result;
      result.half          = name;
      result.pull          = pull;
      const double on      = 1e-5; // mm: a face on the part's surface
      double       largest = 0;
      const Epick::Vector_3 d(pull[0], pull[1], pull[2]);
      for (const auto f : half.faces())
        {
          std::vector<Point<3>> x;
          for (const auto v : vertices_around_face(half.halfedge(f), half))
            x.push_back(point(half.point(v)));
          Tensor<1, 3> normal = cross_product_3d(x[1] - x[0], x[2] - x[0]);
          const double area   = normal.norm() / 2;
          const Point<3> c    = (x[0] + x[1] + x[2]) / 3;
          // Slivers of the corefinement have no reliable normal.
          if (area < 1e-9 || filled.squared_distance(Epick::Point_3(c[0], c[1], c[2])) > on * on)
            continue;
          result.molding_area += area;
          normal /= 2 * area;
          const Point<3> start = c - tolerance * normal;
          if (filled.do_intersect(Epick::Ray_3(Epick::Point_3(start[0], start[1], start[2]), d)))
            {
              result.area += area;
              if (area > largest)
                {
                  largest      = area;
                  result.where = c;
                }
            }
        }
      return result;
    }
  } // namespace



  namespace
  {
    /**
     * The mold in the frame of the actuator: @p corners in coordinates
     * along the axis (outward through the clamped base), the side and the
     * split plane's normal, from the base's centroid. The box's faces and
     * the split plane are coordinate planes there, so points snapped onto
     * them stay on them, whatever the frame's directions in the design.
     */
    Mold
    mold_in_frame(const std::vector<double>             &corners,
                  const std::vector<types::boundary_id> &boundary_ids,
                  const std::set<types::boundary_id>    &cavity_ids,
                  const MoldDimensions                  &dims)
    {
      Mold               mold;
      const Tensor<1, 3> axis({1, 0, 0}), side({0, 1, 0}), normal({0, 0, 1});

      // The outer surface (the body with its cavities filled) and the cavities.
      const Soup outer_soup = select(corners, boundary_ids, cavity_ids, false);
      const Solid outer     = solid(outer_soup);
      AssertThrow(CGAL::is_closed(outer),
                  ExcMessage("The design's outer surface is not closed: no mold can be made "
                             "around it."));
      std::array<std::array<double, 2>, 3> extent;
      for (unsigned int d = 0; d < 3; ++d)
        extent[d] = {{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()}};
      for (const auto &p : outer_soup.points)
        for (unsigned int d = 0; d < 3; ++d)
          extent[d] = {{std::min(extent[d][0], p[d]), std::max(extent[d][1], p[d])}};
      const double size = extent[0][1] - extent[0][0];
      AssertThrow(extent[0][1] < 1e-6 * size,
                  ExcMessage("The clamped base is not the end of the design along its normal "
                             "(the body reaches " +
                             std::to_string(extent[0][1]) +
                             " mm beyond it): the core stems and the pour opening go out "
                             "through the base."));
      const double w   = dims.wall;
      const double top = w; // the box's face beyond the base, in axis units
      const Solid  mold_box =
        box({{extent[0][0] - w, top}}, {{extent[1][0] - w, extent[1][1] + w}},
            {{extent[2][0] - w, extent[2][1] + w}});
      mold.box_volume = volume(mold_box);

      // Cores: each cavity with a stem along the axis, out through the base.
      std::vector<Solid> cavities, cores;
      const auto         cavity_pieces = pieces(select(corners, boundary_ids, cavity_ids, true));
      double             stems_reach   = 0; // how far from the axis the stems reach
      for (std::size_t k = 0; k < cavity_pieces.size(); ++k)
        {
          const std::string name = "core_" + std::to_string(k + 1);
          cavities.push_back(solid(cavity_pieces[k]));
          AssertThrow(CGAL::is_closed(cavities.back()),
                      ExcMessage("Cavity " + std::to_string(k + 1) +
                                 " of the design is not closed: no core can be made of it."));
          Soup inward = cavity_pieces[k]; // its faces are outward from the body
          for (auto &t : inward.triangles)
            std::swap(t[1], t[2]);
          const Point<3> c = centroid(inward);
          {
            const Surface                               copy = approximate(cavities.back());
            const CGAL::Side_of_triangle_mesh<Surface, Epick> inside(copy);
            AssertThrow(inside(Epick::Point_3(c[0], c[1], c[2])) == CGAL::ON_BOUNDED_SIDE,
                        ExcMessage("The centroid " + str(c) + " of cavity " +
                                   std::to_string(k + 1) +
                                   " lies outside it: its core's stem cannot start there."));
          }
          const double   from_axis = std::hypot(c[1], c[2]);
          const Point<3> end       = c + (top + dims.stem_length - c[0]) * axis;
          stems_reach = std::max(stems_reach, from_axis + dims.stem_diameter / 2);
          cores.push_back(boolean(cavities.back(),
                                  cylinder(c, end, dims.stem_diameter / 2, side),
                                  Operation::unite,
                                  name));
        }

      // Pour opening and vent, on the split plane, through the base between
      // the stems and the rim, from 0.2 mm inside the base to beyond the box.
      const double       rim = std::min(-extent[1][0], extent[1][1]);
      const double       s   = (rim + stems_reach) / 2; // their distance from the axis
      std::vector<Solid> channels;
      for (const auto &[diameter, sign, entry] :
           {std::tuple<double, double, std::string>{dims.pour_diameter, 1, "Pour opening diameter"},
            {dims.vent_diameter, -1, "Vent diameter"}})
        {
          AssertThrow(s - diameter / 2 > stems_reach && s + diameter / 2 < rim,
                      ExcMessage("Mold / " + entry + " = " + std::to_string(diameter) +
                                 " mm does not fit on the base between the core stems (out to " +
                                 std::to_string(stems_reach) + " mm from the axis) and the rim (" +
                                 std::to_string(rim) + " mm)."));
          const Point<3> at(0, sign * s, 0);
          channels.push_back(
            cylinder(at - 0.2 * axis, at + (top + 1) * axis, diameter / 2, normal, 24));
          for (const auto &cavity : cavities)
            AssertThrow(!PMP::do_intersect(channels.back(), cavity),
                        ExcMessage("Mold / " + entry +
                                   ": the opening would reach a cavity (the base is thinner "
                                   "than 0.2 mm at " +
                                   str(at) + ")."));
        }

      // Keys: four spheres on the split plane in the side walls.
      std::vector<Solid> keys;
      for (const double s : {extent[0][0] + size / 4, extent[0][1] - size / 4})
        for (const double t : {extent[1][0] - w / 2, extent[1][1] + w / 2})
          keys.push_back(sphere(Point<3>(s, t, 0), dims.key_radius, normal));

      // What the mold holds: the outer surface, the cores, the sprues.
      Solid filled = outer;
      for (const auto &core : cores)
        filled = boolean(filled, core, Operation::unite, "the body with its cores");
      Solid sprues_and_body = outer;
      for (const auto &channel : channels)
        {
          filled = boolean(filled, channel, Operation::unite, "the body with its sprues");
          sprues_and_body =
            boolean(sprues_and_body,
                    boolean(channel, mold_box, Operation::intersect, "a sprue"),
                    Operation::unite,
                    "the body with its sprues");
        }
      Solid cast = sprues_and_body;
      for (const auto &core : cores)
        cast = boolean(cast, core, Operation::subtract, "the cast part");
      mold.parts.push_back(part("cast", cast));

      for (std::size_t k = 0; k < cores.size(); ++k)
        mold.parts.push_back(part("core_" + std::to_string(k + 1), cores[k], &mold_box));

      // The halves: half_a on the -normal side with the keys, half_b with
      // their seats.
      Solid half_a = box({{extent[0][0] - w, top}},
                         {{extent[1][0] - w, extent[1][1] + w}}, {{extent[2][0] - w, 0}});
      Solid half_b = box({{extent[0][0] - w, top}},
                         {{extent[1][0] - w, extent[1][1] + w}}, {{0, extent[2][1] + w}});
      for (const auto &key : keys)
        {
          half_a = boolean(half_a, key, Operation::unite, "half_a with its keys");
          half_b = boolean(half_b, key, Operation::subtract, "half_b with its key seats");
        }
      half_a = boolean(half_a, filled, Operation::subtract, "half_a");
      half_b = boolean(half_b, filled, Operation::subtract, "half_b");
      mold.parts.push_back(part("half_a", half_a));
      mold.parts.push_back(part("half_b", half_b));

      const Surface filled_copy = approximate(filled);
      Tree          tree(faces(filled_copy).first, faces(filled_copy).second, filled_copy);
      tree.accelerate_distance_queries();
      mold.undercuts.push_back(undercut("half_a", half_a, -normal, tree, dims.undercut_tolerance));
      mold.undercuts.push_back(undercut("half_b", half_b, normal, tree, dims.undercut_tolerance));
      return mold;
    }
  } // namespace



  Mold
  make_mold(const std::vector<double>             &corners,
            const std::vector<types::boundary_id> &boundary_ids,
            const std::set<types::boundary_id>    &clamped_ids,
            const std::set<types::boundary_id>    &cavity_ids,
            const MoldDimensions                  &dims)
  {
    // The clamped base: its centroid and outward normal give the axis.
    const Soup base = select(corners, boundary_ids, clamped_ids, true);
    AssertThrow(!base.triangles.empty(),
                ExcMessage("The design has no clamped base (a Dirichlet boundary fixing x, "
                           "y and z): the mold needs it for the core stems and the pour "
                           "opening."));
    Point<3>     base_center;
    Tensor<1, 3> axis;
    double       base_area = 0;
    for (const auto &t : base.triangles)
      {
        const auto &a = base.points[t[0]], &b = base.points[t[1]], &c = base.points[t[2]];
        const Tensor<1, 3> n = cross_product_3d(b - a, c - a) / 2;
        base_area += n.norm();
        axis += n;
        base_center += n.norm() * (a + b + c) / 3;
      }
    base_center /= base_area;
    axis /= axis.norm();

    Tensor<1, 3> normal = dims.split_normal / dims.split_normal.norm();
    AssertThrow(std::abs(normal * axis) < 1e-3,
                ExcMessage("Mold / Split plane normal is not perpendicular to the actuator's "
                           "axis (the clamped base's normal, " +
                           str(Point<3>(axis), "") +
                           "): the plane that splits the outer mold must contain the axis."));
    normal -= (normal * axis) * axis;
    normal /= normal.norm();
    const Tensor<1, 3> side = cross_product_3d(normal, axis); // (axis, side, normal) right-handed

    // Into the frame, built there, and back.
    const auto to_frame = [&](const Point<3> &p) {
      const Tensor<1, 3> d = p - base_center;
      return Point<3>(d * axis, d * side, d * normal);
    };
    const auto to_design = [&](const Point<3> &q) {
      return base_center + q[0] * axis + q[1] * side + q[2] * normal;
    };
    std::vector<double> in_frame(corners.size());
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3)
      {
        const Point<3> q = to_frame(Point<3>(corners[i], corners[i + 1], corners[i + 2]));
        std::copy(&q[0], &q[0] + 3, in_frame.begin() + i);
      }
    Mold mold = mold_in_frame(in_frame, boundary_ids, cavity_ids, dims);
    for (auto &part : mold.parts)
      {
        for (std::size_t i = 0; i + 2 < part.corners.size(); i += 3)
          {
            const Point<3> p =
              to_design(Point<3>(part.corners[i], part.corners[i + 1], part.corners[i + 2]));
            for (unsigned int d = 0; d < 3; ++d)
              part.corners[i + d] = p[d] + 0.0; // no -0 in the STL
          }
        part.manifold = part.manifold && apart_as_floats(part);
      }
    for (auto &u : mold.undercuts)
      {
        u.pull  = u.pull[0] * axis + u.pull[1] * side + u.pull[2] * normal;
        u.where = to_design(u.where);
      }
    mold.axis         = axis;
    mold.split_normal = normal;
    return mold;
  }
} // namespace softopt
