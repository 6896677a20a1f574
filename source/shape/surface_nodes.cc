#include <deal.II/base/mpi.h>
#include <deal.II/grid/reference_cell.h>

#include <softopt/shape/cell_nodes.h>
#include <softopt/shape/surface_nodes.h>

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

  } // namespace



  std::vector<SurfaceNode>
  nearest_surface_nodes(const HyperelasticProblem        &problem,
                        const DesignConfiguration        &design,
                        const PETScWrappers::MPI::Vector &positions,
                        const std::vector<Point<3>>      &points)
  {
    const unsigned int n        = points.size();
    const MPI_Comm     comm     = problem.get_communicator();
    const auto         on_face  = face_nodes();
    const auto        &geometry = problem.get_geometry();

    // The nearest node on this rank's boundary faces; a node on several
    // faces takes the largest of them, so that face_size depends neither
    // on the order of the cells nor on the partition.
    std::vector<SurfaceNode> found(n);
    for (auto &node : found)
      node.distance = std::numeric_limits<double>::max();
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          const CellNodes    cell_nodes(cell, same_cell(cell, design.get_dof_handler()));
          const NodalVectors x = cell_nodes.design(positions);
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->face(f)->at_boundary() ||
                  geometry.is_symmetry_plane(cell->face(f)->boundary_id()))
                continue;
              double longest_edge = 0;
              for (unsigned int i = 0; i < 3; ++i)
                longest_edge = std::max(
                  longest_edge, (x[on_face[f][i]] - x[on_face[f][(i + 1) % 3]]).norm());
              for (unsigned int k = 0; k < n; ++k)
                for (const unsigned int node : on_face[f])
                  {
                    const double d = (Point<3>(x[node]) - points[k]).norm();
                    if (d < found[k].distance)
                      found[k] = {Point<3>(x[node]),
                                  d,
                                  longest_edge,
                                  cell_nodes.displacement_dofs(node),
                                  cell_nodes.design_dofs(node)};
                    else if (d == found[k].distance)
                      found[k].face_size = std::max(found[k].face_size, longest_edge);
                  }
            }
        }

    // The nearest over all ranks (MPI_MINLOC: the lowest rank on a tie);
    // that rank's node and DoFs, and the largest face size of the ranks at
    // that distance, reach every rank.
    std::vector<double> distance(n);
    for (unsigned int k = 0; k < n; ++k)
      distance[k] = found[k].distance;
    const auto          nearest = Utilities::MPI::min_max_avg(distance, comm);
    const unsigned int  rank    = Utilities::MPI::this_mpi_process(comm);
    std::vector<double> shared(9 * n, 0.), sizes(n, 0.);
    for (unsigned int k = 0; k < n; ++k)
      {
        AssertThrow(nearest[k].min < std::numeric_limits<double>::max(),
                    ExcMessage("The mesh has no surface face to find a node "
                               "on (every boundary is a symmetry plane)."));
        if (distance[k] == nearest[k].min)
          sizes[k] = found[k].face_size;
        if (nearest[k].min_index != rank)
          continue;
        for (unsigned int c = 0; c < 3; ++c)
          {
            shared[9 * k + c]     = found[k].position[c];
            shared[9 * k + 3 + c] = found[k].displacement_dofs[c]; // exact below 2^53
            shared[9 * k + 6 + c] = found[k].design_dofs[c];
          }
      }
    Utilities::MPI::sum(shared, comm, shared);
    Utilities::MPI::max(sizes, comm, sizes);
    for (unsigned int k = 0; k < n; ++k)
      {
        found[k].position  = Point<3>(shared[9 * k], shared[9 * k + 1], shared[9 * k + 2]);
        found[k].distance  = nearest[k].min;
        found[k].face_size = sizes[k];
        for (unsigned int c = 0; c < 3; ++c)
          {
            found[k].displacement_dofs[c] =
              static_cast<types::global_dof_index>(shared[9 * k + 3 + c]);
            found[k].design_dofs[c] =
              static_cast<types::global_dof_index>(shared[9 * k + 6 + c]);
          }
      }
    return found;
  }



  Tensor<1, 3>
  nodal_value(const PETScWrappers::MPI::Vector             &v,
              const std::array<types::global_dof_index, 3> &dofs)
  {
    // Each rank contributes the entries it owns.
    std::vector<double> value(3, 0.);
    for (unsigned int c = 0; c < 3; ++c)
      if (v.in_local_range(dofs[c]))
        value[c] = v(dofs[c]);
    Utilities::MPI::sum(value, v.get_mpi_communicator(), value);
    return Tensor<1, 3>({value[0], value[1], value[2]});
  }
} // namespace softopt
