#include <deal.II/base/mpi.h>
#include <deal.II/grid/reference_cell.h>

#include <softopt/io/csv_writer.h>
#include <softopt/io/tracked_points.h>
#include <softopt/shape/cell_nodes.h>

#include <algorithm>
#include <limits>

namespace softopt
{
  namespace
  {
    /** The six nodes of each face of the quadratic tetrahedron, in the node
     * order of FE_SimplexP<3>(2): the face's vertices (nodes 0-3 are the
     * cell's vertices) and its edges (node 4 + l sits on line l). */
    std::array<std::array<unsigned int, 6>, 4>
    face_nodes()
    {
      const ReferenceCell tet = ReferenceCells::Tetrahedron;
      std::array<std::array<unsigned int, 6>, 4> nodes;
      for (unsigned int f = 0; f < 4; ++f)
        for (unsigned int i = 0; i < 3; ++i)
          {
            nodes[f][i]     = tet.face_to_cell_vertices(f, i, 1);
            nodes[f][3 + i] = 4 + tet.face_to_cell_lines(f, i, 1);
          }
      return nodes;
    }

    /** Symmetry planes (Dirichlet boundaries fixing only some components)
     * are cuts through the body, not its surface. */
    bool
    is_symmetry_plane(const Geometry &geometry, const types::boundary_id id)
    {
      const auto d = geometry.dirichlet_boundaries.find(id);
      if (d == geometry.dirichlet_boundaries.end())
        return false;
      const auto n_fixed = std::count(d->second.begin(), d->second.end(), true);
      return n_fixed > 0 && n_fixed < 3;
    }

    /** A length in mm to the micrometre. */
    std::string
    format_mm(const double x)
    {
      return CsvWriter::fixed(x, 3);
    }

    std::string
    format_point(const Point<3> &p)
    {
      return "(" + format_mm(p[0]) + ", " + format_mm(p[1]) + ", " +
             format_mm(p[2]) + ")";
    }
  } // namespace



  bool
  TrackedPoints::SurfaceNode::far() const
  {
    return distance > std::max(1.0, 0.5 * face_size);
  }



  TrackedPoints::TrackedPoints(const HyperelasticProblem     &problem,
                               const DesignConfiguration     &design,
                               const std::vector<NamedPoint> &requested)
  {
    const unsigned int n        = requested.size();
    const MPI_Comm     comm     = problem.get_communicator();
    const auto        &X        = design.positions();
    const auto         on_face  = face_nodes();
    const auto        &geometry = problem.get_geometry();

    // The nearest node on this rank's boundary faces; a node on several
    // faces takes the largest of them, so that face_size depends neither
    // on the order of the cells nor on the partition.
    std::vector<double>   distance(n, std::numeric_limits<double>::max());
    std::vector<double>   face_size(n, 0.);
    std::vector<Point<3>> position(n);
    std::vector<std::array<types::global_dof_index, 3>> node_dofs(n);
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          const CellNodes    cell_nodes(cell,
                                     same_cell(cell, design.get_dof_handler()));
          const NodalVectors x = cell_nodes.design(X);
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->face(f)->at_boundary() ||
                  is_symmetry_plane(geometry, cell->face(f)->boundary_id()))
                continue;
              double longest_edge = 0;
              for (unsigned int i = 0; i < 3; ++i)
                longest_edge = std::max(
                  longest_edge,
                  (x[on_face[f][i]] - x[on_face[f][(i + 1) % 3]]).norm());
              for (unsigned int k = 0; k < n; ++k)
                for (const unsigned int node : on_face[f])
                  {
                    const double d =
                      (Point<3>(x[node]) - requested[k].position).norm();
                    if (d < distance[k])
                      {
                        distance[k]  = d;
                        face_size[k] = longest_edge;
                        position[k]  = Point<3>(x[node]);
                        node_dofs[k] = cell_nodes.displacement_dofs(node);
                      }
                    else if (d == distance[k])
                      face_size[k] = std::max(face_size[k], longest_edge);
                  }
            }
        }

    // The nearest over all ranks (MPI_MINLOC: the lowest rank on a tie);
    // that rank's node and DoFs, and the largest face size of the ranks at
    // that distance, reach every rank.
    const auto nearest = Utilities::MPI::min_max_avg(distance, comm);
    const unsigned int  rank = Utilities::MPI::this_mpi_process(comm);
    std::vector<double> shared(6 * n, 0.), sizes(n, 0.);
    for (unsigned int k = 0; k < n; ++k)
      {
        AssertThrow(nearest[k].min < std::numeric_limits<double>::max(),
                    ExcMessage("Tracked point \"" + requested[k].name +
                               "\": the mesh has no boundary face to put it "
                               "on."));
        if (distance[k] == nearest[k].min)
          sizes[k] = face_size[k];
        if (nearest[k].min_index != rank)
          continue;
        for (unsigned int c = 0; c < 3; ++c)
          {
            shared[6 * k + c]     = position[k][c];
            shared[6 * k + 3 + c] = node_dofs[k][c]; // exact below 2^53
          }
      }
    Utilities::MPI::sum(shared, comm, shared);
    Utilities::MPI::max(sizes, comm, sizes);
    for (unsigned int k = 0; k < n; ++k)
      {
        nodes.push_back(
          {requested[k].name,
           requested[k].position,
           Point<3>(shared[6 * k], shared[6 * k + 1], shared[6 * k + 2]),
           nearest[k].min,
           sizes[k]});
        std::array<types::global_dof_index, 3> node;
        for (unsigned int c = 0; c < 3; ++c)
          node[c] = static_cast<types::global_dof_index>(shared[6 * k + 3 + c]);
        dofs.push_back(node);
      }
  }



  void
  TrackedPoints::print(const ConditionalOStream &out) const
  {
    std::string text;
    for (const auto &node : nodes)
      {
        text += "Tracked point " + node.name + ": requested " +
                format_point(node.requested) + " mm, surface node " +
                format_point(node.position) + " mm at distance " +
                format_mm(node.distance) + " mm\n";
        if (node.far())
          text += "  Warning: farther than max(1 mm, half the longest edge of "
                  "its boundary face = " +
                  format_mm(0.5 * node.face_size) +
                  " mm): the point is probably not on the surface; check its "
                  "coordinates (mm, design configuration) in \"Tracked "
                  "points\".\n";
      }
    out << text << std::flush;
  }



  std::vector<Tensor<1, 3>>
  TrackedPoints::displacements(const HyperelasticProblem::Vector &a) const
  {
    // Each rank contributes the entries it owns.
    std::vector<double> u(3 * nodes.size(), 0.);
    for (unsigned int k = 0; k < nodes.size(); ++k)
      for (unsigned int c = 0; c < 3; ++c)
        if (a.in_local_range(dofs[k][c]))
          u[3 * k + c] = a(dofs[k][c]);
    Utilities::MPI::sum(u, a.get_mpi_communicator(), u);
    std::vector<Tensor<1, 3>> result(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      result[k] = Tensor<1, 3>({u[3 * k], u[3 * k + 1], u[3 * k + 2]});
    return result;
  }



  std::vector<std::string>
  TrackedPoints::csv_columns() const
  {
    std::vector<std::string> columns;
    for (const auto &node : nodes)
      for (const char *c :
           {"_X_mm", "_Y_mm", "_Z_mm", "_ux_mm", "_uy_mm", "_uz_mm"})
        columns.push_back(node.name + c);
    return columns;
  }



  std::vector<std::string>
  TrackedPoints::csv_entries(const HyperelasticProblem::Vector &a) const
  {
    const auto               u = displacements(a);
    std::vector<std::string> entries;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        for (unsigned int c = 0; c < 3; ++c)
          entries.push_back(CsvWriter::format(nodes[k].position[c]));
        for (unsigned int c = 0; c < 3; ++c)
          entries.push_back(CsvWriter::format(u[k][c]));
      }
    return entries;
  }
} // namespace softopt
