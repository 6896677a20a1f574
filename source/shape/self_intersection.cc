#include <deal.II/base/mpi.h>

#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/self_intersection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <map>
#include <vector>

namespace softopt
{
  namespace
  {
    using Kernel  = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Surface = CGAL::Surface_mesh<Kernel::Point_3>;

    /** Intersecting triangle pairs of the surface with these corners (9
     * doubles a triangle); shared corners are equal to the last bit. */
    SelfIntersection
    intersections(const std::vector<double> &corners)
    {
      // Indexed vertices: CGAL skips pairs that share a vertex or an edge
      // only when they share the index.
      std::map<std::array<double, 3>, std::size_t> index;
      std::vector<Kernel::Point_3>                 points;
      std::vector<std::array<std::size_t, 3>>      triangles;
      for (std::size_t t = 0; t < corners.size(); t += 9)
        {
          std::array<std::size_t, 3> triangle;
          for (unsigned int v = 0; v < 3; ++v)
            {
              const std::array<double, 3> p{
                {corners[t + 3 * v], corners[t + 3 * v + 1], corners[t + 3 * v + 2]}};
              const auto [it, added] = index.emplace(p, points.size());
              if (added)
                points.emplace_back(p[0], p[1], p[2]);
              triangle[v] = it->second;
            }
          triangles.push_back(triangle);
        }

      namespace PMP = CGAL::Polygon_mesh_processing;
      Surface surface;
      PMP::polygon_soup_to_polygon_mesh(points, triangles, surface);
      std::vector<std::pair<Surface::Face_index, Surface::Face_index>> pairs;
      PMP::self_intersections(surface, std::back_inserter(pairs));

      SelfIntersection result;
      result.pairs = pairs.size();
      if (!pairs.empty())
        {
          Kernel::Vector_3 sum(0, 0, 0);
          for (const auto v : vertices_around_face(halfedge(pairs[0].first, surface),
                                                   surface))
            sum = sum + (surface.point(v) - CGAL::ORIGIN);
          for (unsigned int d = 0; d < 3; ++d)
            result.where[d] = CGAL::to_double(sum[d]) / 3;
        }
      return result;
    }
  } // namespace



  SelfIntersection
  design_self_intersections(const DesignConfiguration &design, const Deformation *deformation)
  {
    const auto comm = design.get_dof_handler().get_communicator();
    const auto corners =
      gathered_boundary_triangles(design, nullptr, deformation); // design.stl's
    SelfIntersection result;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      result = intersections(corners);
    result.pairs = Utilities::MPI::broadcast(comm, result.pairs, 0);
    result.where = Utilities::MPI::broadcast(comm, result.where, 0);
    return result;
  }
} // namespace softopt
