// The self-intersection test of the design surface (issue 19): the thin
// sphere octant (A = 0.9, B = 1), whose surface is closed and embedded, with
// three shape fields: none, an inflation by 5 % (X -> 1.05 X, still
// embedded), and a dimple that pushes the outer surface 0.2 mm inwards
// within 20 degrees of the axis (1, 1, 1), through the inner surface 0.1 mm
// below it. Only the dimple may intersect, and the point reported must lie
// in the dimple or its rim, whose triangles reach one element (h = 0.1 mm,
// 6 degrees) beyond it: within 26 degrees of the axis.

#include <softopt/shape/design_configuration.h>
#include <softopt/shape/self_intersection.h>

#include "tests.h"

#include <functional>
#include <map>

using namespace softopt_tests;

namespace
{
  /** psi with psi(X_o) = f(X_o) at every node. */
  softopt::DesignConfiguration::Vector
  shape_field(const softopt::DesignConfiguration            &design,
              const std::function<Tensor<1, 3>(const Point<3> &)> &f)
  {
    const auto &dofs = design.get_dof_handler();
    const auto &fe   = dofs.get_fe();
    const auto  X_o  = design.ghosted(design.initial_coordinates());
    auto        psi  = design.create_vector();
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          std::map<unsigned int, std::array<types::global_dof_index, 3>> nodes;
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const auto [component, node] = fe.system_to_component_index(i);
              nodes[node][component] = indices[i];
            }
          for (const auto &[node, index] : nodes)
            {
              const Point<3> X(X_o[index[0]], X_o[index[1]], X_o[index[2]]);
              const auto     value = f(X);
              for (unsigned int c = 0; c < 3; ++c)
                if (psi.in_local_range(index[c]))
                  psi[index[c]] = value[c];
            }
        }
    psi.compress(VectorOperation::insert);
    return psi;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Geometry geometry;
  geometry.mesh_file       = SOURCE_DIR "/../meshes/sphere_octant.geo";
  geometry.mesh_size       = 0.1;
  geometry.mesh_parameters = {{"A", 0.9}, {"B", 1.}};
  parallel::fullydistributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
  softopt::DesignConfiguration design(triangulation,
                                      geometry.create_triangulation(triangulation));

  const Tensor<1, 3> axis = Point<3>(1, 1, 1) / std::sqrt(3.);
  const double       cone = std::cos(20. * numbers::PI / 180);
  const std::map<std::string, std::function<Tensor<1, 3>(const Point<3> &)>> fields{
    {"no shape field", [](const Point<3> &) { return Tensor<1, 3>(); }},
    {"inflated by 5 %", [](const Point<3> &X) { return Tensor<1, 3>(0.05 * X); }},
    {"dimple through the wall", [&](const Point<3> &X) {
       const double r = X.norm();
       return r > 0.97 && X * axis > cone * r ? Tensor<1, 3>(-0.2 * X / r) :
                                                Tensor<1, 3>();
     }}};
  for (const auto &[name, f] : fields)
    {
      design.set_shape_field(shape_field(design, f));
      const auto   found  = softopt::design_self_intersections(design);
      const bool   dimple = name == "dimple through the wall";
      const double angle =
        std::acos(std::min(1., found.where * axis / found.where.norm())) * 180 /
        numbers::PI;
      deallog << name << ": " << found.pairs << " intersecting triangle pairs "
              << (dimple ? (found.pairs > 0 ? "(> 0)" : "(NONE FOUND)") :
                           (found.pairs == 0 ? "(none, as expected)" : "(WRONG)"));
      if (dimple)
        deallog << ", at " << std::setprecision(2) << angle << " degrees from the axis"
                << (angle < 26 ? " (< 26)" : " (OUTSIDE THE DIMPLE)");
      deallog << std::endl;
    }
}
