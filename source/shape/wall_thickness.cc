#include <deal.II/base/mpi.h>

#include <softopt/io/output_directory.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/wall_thickness.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace softopt
{
  namespace
  {
    using Kernel    = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Triangles = std::vector<Kernel::Triangle_3>;
    using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
    using Tree      = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

    /** The surface of @p corners (9 numbers a triangle) as indexed nodes
     * and triangles; shared corners are equal to the last bit. */
    void
    index_surface(const std::vector<double> &corners, WallThickness &wall)
    {
      std::map<std::array<double, 3>, unsigned int> index;
      for (std::size_t t = 0; t < corners.size(); t += 9)
        {
          std::array<unsigned int, 3> triangle;
          for (unsigned int v = 0; v < 3; ++v)
            {
              const std::array<double, 3> p{
                {corners[t + 3 * v], corners[t + 3 * v + 1], corners[t + 3 * v + 2]}};
              const auto [it, added] = index.emplace(p, wall.nodes.size());
              if (added)
                wall.nodes.emplace_back(p[0], p[1], p[2]);
              triangle[v] = it->second;
            }
          wall.triangles.push_back(triangle);
        }
    }

    /** The thickness at every node off the mirror planes: the path along
     * the inward normal to the first triangle of the body's surface, not
     * one of the node's own. A ray that meets a mirror plane (a symmetry
     * boundary: the body goes on beyond it) is reflected there and goes on,
     * as it would in the whole body. */
    void
    shoot_rays(WallThickness &wall, const std::vector<bool> &mirror)
    {
      const auto point = [&](const Point<3> &p) { return Kernel::Point_3(p[0], p[1], p[2]); };
      Triangles                              triangles;
      std::vector<Tensor<1, 3>>              face_normal;
      std::vector<Tensor<1, 3>>              normal(wall.nodes.size());
      std::vector<std::vector<unsigned int>> around(wall.nodes.size());
      for (unsigned int t = 0; t < wall.triangles.size(); ++t)
        {
          const auto &[a, b, c] = wall.triangles[t];
          triangles.emplace_back(point(wall.nodes[a]), point(wall.nodes[b]), point(wall.nodes[c]));
          // Area-weighted outward normal (the triangles are counter-clockwise
          // seen from outside).
          face_normal.push_back(
            cross_product_3d(wall.nodes[b] - wall.nodes[a], wall.nodes[c] - wall.nodes[a]));
          for (const unsigned int v : wall.triangles[t])
            {
              if (!mirror[t])
                normal[v] += face_normal.back();
              around[v].push_back(t);
            }
        }
      Tree tree(triangles.begin(), triangles.end());

      wall.thickness.assign(wall.nodes.size(), std::numeric_limits<double>::infinity());
      for (unsigned int i = 0; i < wall.nodes.size(); ++i)
        {
          if (normal[i].norm() == 0) // on mirror planes only
            continue;
          Point<3>                  from      = wall.nodes[i];
          Tensor<1, 3>              direction = -normal[i] / normal[i].norm();
          std::vector<unsigned int> skip      = around[i];
          double                    length    = 0;
          for (unsigned int reflection = 0; reflection <= 3; ++reflection)
            {
              const Kernel::Ray_3 ray(point(from),
                                      Kernel::Vector_3(direction[0], direction[1], direction[2]));
              const auto own = [&](const Triangles::const_iterator &id) {
                return std::find(skip.begin(), skip.end(), id - triangles.begin()) != skip.end();
              };
              const auto hit = tree.first_intersection(ray, own);
              if (!hit)
                break;
              Point<3> at;
              if (const auto *p = boost::get<Kernel::Point_3>(&hit->first))
                at = Point<3>(p->x(), p->y(), p->z());
              else if (const auto *segment = boost::get<Kernel::Segment_3>(&hit->first))
                at = Point<3>(segment->source().x(), segment->source().y(), segment->source().z());
              const unsigned int t = hit->second - triangles.begin();
              length += at.distance(from);
              if (!mirror[t])
                {
                  wall.thickness[i] = length;
                  break;
                }
              const Tensor<1, 3> n = face_normal[t] / face_normal[t].norm();
              direction -= 2 * (direction * n) * n;
              from = at;
              skip = {t};
            }
          if (wall.thickness[i] < wall.minimum)
            {
              wall.minimum = wall.thickness[i];
              wall.where   = wall.nodes[i];
            }
        }
    }
  } // namespace



  WallThickness
  wall_thickness(const DesignConfiguration &design, const std::set<types::boundary_id> &mirrors)
  {
    const auto                      comm = design.get_dof_handler().get_communicator();
    std::vector<types::boundary_id> ids;
    const auto    corners = gathered_boundary_triangles(design, &ids); // design.stl's
    WallThickness wall;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        index_surface(corners, wall);
        std::vector<bool> mirror;
        for (const auto id : ids)
          mirror.push_back(mirrors.count(id) > 0);
        shoot_rays(wall, mirror);
      }
    wall.minimum = Utilities::MPI::broadcast(comm, wall.minimum, 0);
    wall.where   = Utilities::MPI::broadcast(comm, wall.where, 0);
    return wall;
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
    vtu << "</DataArray>\n</Cells>\n<PointData Scalars=\"wall_thickness_mm\">\n"
        << "<DataArray type=\"Float64\" Name=\"wall_thickness_mm\" format=\"ascii\">\n";
    for (const double t : wall.thickness)
      vtu << (std::isfinite(t) ? t : -1.) << '\n'; // -1: no opposite wall found
    vtu << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    write_whole_file(file, vtu.str());
  }
} // namespace softopt
