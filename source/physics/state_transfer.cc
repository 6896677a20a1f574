#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/rtree.h>

#include <softopt/physics/state_transfer.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>

namespace softopt
{
  namespace
  {
    /** How far outside its cell a point may lie, in barycentric
     * coordinates: where the new boundary is a chord of a concave curved
     * face of the old one, or an edge the remesh kept straight, new nodes
     * lie outside the old body by the sagitta, a large fraction of a flat
     * cell's thickness (the 4 mm gripper's walls, one element thick). The
     * value extrapolated there is a start for Newton, nothing more. */
    constexpr double max_outside = 0.5;

    using CellIterator = DoFHandler<3>::active_cell_iterator;

    /** Where a point lies in the old mesh, as far as one rank knows. */
    struct Location
    {
      /** Distance outside the reference tetrahedron of its cell, in
       * barycentric coordinates (0: inside; infinite: in no cell here). */
      double       outside = std::numeric_limits<double>::infinity();
      CellIterator cell;
      Point<3>     unit;
    };

    /** The reference point of @p p in the straight tetrahedron through the
     * corners @p v of a cell (the affine part of its map). */
    Point<3>
    affine_unit_point(const std::array<Point<3>, 4> &v, const Point<3> &p)
    {
      Tensor<2, 3> J;
      for (unsigned int d = 0; d < 3; ++d)
        for (unsigned int e = 0; e < 3; ++e)
          J[e][d] = v[d + 1][e] - v[0][e];
      return Point<3>(invert(J) * (p - v[0]));
    }

    /** How far @p unit lies outside the reference tetrahedron, the largest
     * negative barycentric coordinate (0: inside). */
    double
    outside(const Point<3> &unit)
    {
      return std::max({0., -unit[0], -unit[1], -unit[2], unit[0] + unit[1] + unit[2] - 1});
    }

    /** The cell of this rank's part of the old mesh that holds each of
     * @p points best (smallest distance outside), and its reference point.
     * Candidates come from an R-tree of the cells' corner boxes, widened
     * for curved faces, and the affine map through their corners; the
     * reference point from the old (curved) mapping. */
    std::vector<Location>
    locate_here(const HyperelasticProblem &old_problem, const std::vector<Point<3>> &points)
    {
      const auto &mapping = old_problem.get_mapping();
      using Leaf          = std::pair<BoundingBox<3>, unsigned int>;
      std::vector<Leaf>                   boxes;
      std::vector<CellIterator>           cells;
      std::vector<std::array<Point<3>, 4>> corners;
      for (const auto &cell : old_problem.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto vertices = mapping.get_vertices(cell);
            std::array<Point<3>, 4> v;
            std::copy(vertices.begin(), vertices.begin() + 4, v.begin());
            BoundingBox<3> box(std::vector<Point<3>>(v.begin(), v.end()));
            box.extend(max_outside * box.get_boundary_points().first.distance(
                                       box.get_boundary_points().second));
            boxes.emplace_back(box, cells.size());
            cells.push_back(cell);
            corners.push_back(v);
          }
      const auto tree = pack_rtree(boxes);

      std::vector<Location> locations(points.size());
      std::vector<Leaf>     candidates;
      for (std::size_t i = 0; i < points.size(); ++i)
        {
          candidates.clear();
          tree.query(boost::geometry::index::intersects(points[i]),
                     std::back_inserter(candidates));
          for (const auto &[box, c] : candidates)
            {
              // The curved map moves a point by a fraction of a cell at most.
              const Point<3> affine = affine_unit_point(corners[c], points[i]);
              if (outside(affine) > max_outside + 0.3 ||
                  outside(affine) > locations[i].outside + 0.3)
                continue;
              try
                {
                  const Point<3> unit = mapping.transform_real_to_unit_cell(cells[c], points[i]);
                  if (outside(unit) < locations[i].outside)
                    locations[i] = {outside(unit), cells[c], unit};
                }
              catch (const Mapping<3>::ExcTransformationFailed &)
                {}
              if (locations[i].outside == 0)
                break; // inside: a neighbor can only tie
            }
        }
      return locations;
    }

    /** The four components (u, p~) of @p state at the points this rank
     * holds best (@p won), zero at the others: sum_i a_i N_i(xi). */
    std::vector<double>
    evaluate_here(const HyperelasticProblem         &old_problem,
                  const HyperelasticProblem::Vector &state,
                  const std::vector<Location>       &locations,
                  const std::vector<bool>           &won)
    {
      const auto          a  = old_problem.ghosted(state);
      const auto         &fe = old_problem.get_fe();
      std::vector<double> values(4 * locations.size(), 0.);
      Vector<double>      local(fe.n_dofs_per_cell());
      for (std::size_t i = 0; i < locations.size(); ++i)
        if (won[i])
          {
            locations[i].cell->get_dof_values(a, local);
            for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
              {
                const unsigned int c = fe.system_to_component_index(j).first;
                values[4 * i + c] += local[j] * fe.shape_value_component(j, locations[i].unit, c);
              }
          }
      return values;
    }
  } // namespace



  StateTransfer
  transfer_states(const HyperelasticProblem                           &old_problem,
                  const std::map<double, HyperelasticProblem::Vector> &old_states,
                  const HyperelasticProblem                           &new_problem,
                  const Mapping<3>                                    &new_mapping)
  {
    const MPI_Comm comm = new_problem.get_communicator();
    const int      rank = Utilities::MPI::this_mpi_process(comm);

    // Where the old fields are read: the nodes of the new mesh (u) and the
    // centroids of its cells (p~), in the design configuration X, each with
    // the DoFs it sets (locally owned ones only; a node once).
    const FESystem<3>    &fe      = new_problem.get_fe();
    std::vector<Point<3>> unit    = fe.base_element(0).get_unit_support_points();
    const unsigned int    n_nodes = unit.size();
    unit.emplace_back(0.25, 0.25, 0.25);
    FEValues<3>    fe_values(new_mapping, fe, Quadrature<3>(unit), update_quadrature_points);
    const IndexSet owned = new_problem.get_dof_handler().locally_owned_dofs();
    std::map<types::global_dof_index, std::pair<Point<3>, std::array<types::global_dof_index, 3>>>
                                                              nodes; // keyed by the x DoF
    std::vector<std::pair<Point<3>, types::global_dof_index>> centroids;
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : new_problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dof_indices);
          for (unsigned int n = 0; n < n_nodes; ++n)
            {
              std::array<types::global_dof_index, 3> dofs;
              for (unsigned int c = 0; c < 3; ++c)
                dofs[c] = dof_indices[fe.component_to_system_index(c, n)];
              if (owned.is_element(dofs[0]))
                nodes.emplace(dofs[0], std::make_pair(fe_values.quadrature_point(n), dofs));
            }
          centroids.emplace_back(fe_values.quadrature_point(n_nodes),
                                 dof_indices[fe.component_to_system_index(3, 0)]);
        }
    std::vector<Point<3>> points;
    for (const auto &[key, node] : nodes)
      points.push_back(node.first);
    for (const auto &[point, dof] : centroids)
      points.push_back(point);

    // Every rank searches its old cells for every rank's points; the rank
    // whose cell holds a point best evaluates it (MPI_MINLOC).
    const auto                          parts = Utilities::MPI::all_gather(comm, points);
    std::vector<Point<3>>               all_points;
    std::size_t                         first = 0; // this rank's in all_points
    for (int r = 0; r < int(parts.size()); ++r)
      {
        if (r == rank)
          first = all_points.size();
        all_points.insert(all_points.end(), parts[r].begin(), parts[r].end());
      }
    const auto locations = locate_here(old_problem, all_points);
    struct DoubleInt // MPI_DOUBLE_INT's layout
    {
      double value;
      int    rank;
    };
    std::vector<DoubleInt> best(all_points.size());
    for (std::size_t i = 0; i < all_points.size(); ++i)
      best[i] = {locations[i].outside, rank};
    MPI_Allreduce(MPI_IN_PLACE, best.data(), best.size(), MPI_DOUBLE_INT, MPI_MINLOC, comm);
    std::vector<bool> won(all_points.size());
    StateTransfer     result;
    for (std::size_t i = 0; i < all_points.size(); ++i)
      {
        won[i] = best[i].rank == rank && best[i].value <= max_outside;
        result.n_not_found += best[i].value > max_outside;
      }
    if (result.n_not_found > 0)
      return result;

    for (const auto &[load_factor, old_state] : old_states)
      {
        auto values = evaluate_here(old_problem, old_state, locations, won);
        MPI_Allreduce(MPI_IN_PLACE, values.data(), values.size(), MPI_DOUBLE, MPI_SUM, comm);
        // u at the nodes and p~ at the centroids. Not p~(u) of the new mesh:
        // at nu -> 0.5 the carried u's small error in J - 1 times K would
        // make a pressure far from equilibrium, and Newton's first step
        // from there can invert elements; the carried p~ leaves r_p small.
        auto        state = new_problem.create_vector();
        std::size_t i     = first;
        for (const auto &[key, node] : nodes)
          {
            for (unsigned int c = 0; c < 3; ++c)
              state(node.second[c]) = values[4 * i + c];
            ++i;
          }
        for (const auto &[point, dof] : centroids)
          state(dof) = values[4 * i++ + 3];
        state.compress(VectorOperation::insert);
        new_problem.get_constraints().set_zero(state); // clamped: exactly 0
        result.states.emplace(load_factor, std::move(state));
      }
    return result;
  }
} // namespace softopt
