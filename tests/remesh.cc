// A new mesh of a design (DesignProblem::remesh, "Remesh below quality"),
// on the small design problem (inputs/sphere_design.prm): the design
// d = s r (r pseudo-random) is evaluated, meshed anew by gmsh inside its
// boundary triangles and evaluated there at d = 0. The new mesh must keep
// the boundary triangulation (the same corners, to round-off, and the same
// faces per boundary id) with its curved midside nodes, so the volume of
// the body is the same to round-off; be free of flat or inverted elements;
// and give the same functionals up to the discretization error of the new
// interior (a few 1e-4 relative here).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/shape/boundary_faces.h>

#include "body_volume.h"
#include "random_design.h"
#include "tests.h"

#include <filesystem>

using namespace softopt_tests;

namespace
{
  /** The boundary faces per boundary id, and all their corners (on every
   * rank). */
  std::pair<std::map<unsigned int, unsigned int>, std::vector<Point<3>>>
  boundary(const softopt::DesignConfiguration &design)
  {
    std::map<unsigned int, unsigned int> faces;
    std::vector<Point<3>>                corners;
    for (const auto &face : softopt::locally_owned_boundary_faces(design))
      {
        ++faces[face.boundary_id];
        corners.insert(corners.end(), face.corner.begin(), face.corner.end());
      }
    std::map<unsigned int, unsigned int> all_faces; // ranks hold different ids
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, faces))
      for (const auto &[id, n] : part)
        all_faces[id] += n;
    std::vector<Point<3>> all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, corners))
      all.insert(all.end(), part.begin(), part.end());
    return {all_faces, all};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_design.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  problem.add_cavity_volume();
  softopt::DesignIterate x = random_design(problem, settings);
  const auto   before         = problem.evaluate(x);
  const double volume_before  = body_volume(problem.design_configuration());
  const auto   boundary_before = boundary(problem.design_configuration());
  const auto   cells_before   = problem.hyperelastic_problem()
                                .get_dof_handler()
                                .get_triangulation()
                                .n_global_active_cells();
  deallog << "design: largest |psi| "
          << (x.psi.linfty_norm() > 1e-3 ? "above" : "BELOW")
          << " 1e-3 mm, worst element quality "
          << (problem.filter_result().worst_quality > 0.2 ? "above" : "BELOW")
          << " 0.2" << std::endl;

  const std::string file = "remeshed.msh";
  problem.remesh(x, file);
  deallog << "new mesh: smallest det(dX/dxi) "
          << (problem.design_configuration().min_jacobian(QGaussSimplex<3>(3)) > 0 ?
                "positive" :
                "NOT POSITIVE")
          << std::endl;
  const auto after = problem.evaluate(x);
  deallog << "the mesh file is " << (std::filesystem::exists(file) ? "" : "NOT ")
          << "there" << std::endl;
  // "Physics over the run" counts the old mesh's physics too.
  const unsigned int assemblies_new_mesh =
    problem.hyperelastic_problem().get_statistics().n_assemblies;
  const unsigned int assemblies_run = problem.physics_statistics().n_assemblies;
  deallog << "assemblies over the run: "
          << (assemblies_run > assemblies_new_mesh ? "some" : "NONE") << " on the old mesh, "
          << (assemblies_new_mesh > 0 ? "some" : "NONE") << " on the new one" << std::endl;
  const auto cells_after = problem.hyperelastic_problem()
                             .get_dof_handler()
                             .get_triangulation()
                             .n_global_active_cells();
  deallog << "cells: " << cells_before << " before, "
          << (std::abs(double(cells_after) - cells_before) < 0.2 * cells_before ?
                "within 20 %" :
                "NOT within 20 %")
          << " after" << std::endl;
  deallog << "new mesh: psi "
          << (x.psi.linfty_norm() == 0 ? "zero" : "NOT ZERO")
          << ", worst element quality "
          << (problem.filter_result().worst_quality > 0.2 ? "above" : "BELOW")
          << " 0.2" << std::endl;

  // The boundary triangulation is kept.
  const auto boundary_after = boundary(problem.design_configuration());
  for (const auto &[id, n] : boundary_before.first)
    deallog << "boundary id " << id << ": " << n << " faces before, "
            << (boundary_after.first.count(id) ? boundary_after.first.at(id) : 0)
            << " after" << std::endl;
  double largest = 0;
  for (const auto &p : boundary_after.second)
    {
      double nearest = std::numeric_limits<double>::max();
      for (const auto &q : boundary_before.second)
        nearest = std::min(nearest, p.distance(q));
      largest = std::max(largest, nearest);
    }
  deallog << "largest distance of a new boundary corner from an old one "
          << (largest < 1e-12 ? "below 1e-12" : error(largest)) << " mm"
          << std::endl;

  const double volume_after = body_volume(problem.design_configuration());
  const double volume_change = std::abs(volume_after - volume_before) / volume_before;
  deallog << "body volume: relative change "
          << (volume_change < 1e-12 ? "below 1e-12" : error(volume_change))
          << std::endl;
  for (unsigned int i = 0; i < before.size(); ++i)
    deallog << problem.functionals()[i]->name() << ": " << before[i]
            << " before, relative change "
            << error(std::abs(after[i] - before[i]) /
                     std::max(std::abs(before[i]), 1e-3))
            << std::endl;
}
