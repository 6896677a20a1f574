// remesh_design() meshes with gmsh's HXT and, where HXT leaves an element
// below the sliver quality, with gmsh's Delaunay too, keeping the mesh
// whose worst element is better (the contractor's 0.8 mm mesh of session
// 38 had an HXT sliver of mean ratio 0.0075; Delaunay's worst was 0.21).
//
// mean_ratio() first, against tetrahedra whose quality is known. Then the
// small design problem's design (inputs/sphere_design.prm, d = s r) is
// meshed with the default sliver quality (HXT alone: its worst element is
// above it) and with a sliver quality of 1 (every mesh has an element
// below 1, so both algorithms mesh it). The reported worst element must be
// the better of the two and must be that of the file kept, read back.
// Last, Delaunay is made to fail (a folder stands where its mesh goes):
// HXT's mesh must be kept, and the log must say so.

#include <softopt/app/settings.h>
#include <softopt/geometry/gmsh_mesh.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/shape/quadratic_tetrahedron.h>
#include <softopt/shape/remesh.h>

#include "random_design.h"
#include "tests.h"

#include <filesystem>

using namespace softopt_tests;

namespace
{
  /** The worst mean ratio of the tetrahedra of a gmsh file, by its
   * corners. */
  double
  worst_in_file(const std::string &file)
  {
    const softopt::GmshMesh mesh  = softopt::read_gmsh_mesh(file);
    double                  worst = 1;
    for (const auto &e : mesh.elements)
      if (e.type == 4 || e.type == 11)
        {
          std::array<Point<3>, 4> p;
          for (unsigned int a = 0; a < 4; ++a)
            p[a] = mesh.nodes.at(e.nodes[a]);
          worst = std::min(worst, softopt::mean_ratio(p));
        }
    return worst;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  // The regular tetrahedron: 1. The corner of the unit cube (V = 1/6,
  // squared edges 1, 1, 1, 2, 2, 2): 12 (1/2)^(2/3) / 9. Flat: 0.
  // Inside out: its negative volume.
  const double s3 = std::sqrt(3.), s6 = std::sqrt(6.);
  const std::array<Point<3>, 4> regular{
    {Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(0.5, s3 / 2, 0), Point<3>(0.5, s3 / 6, s6 / 3)}};
  const std::array<Point<3>, 4> corner{
    {Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(0, 1, 0), Point<3>(0, 0, 1)}};
  const std::array<Point<3>, 4> flat{
    {Point<3>(0, 0, 0), Point<3>(1, 0, 0), Point<3>(0, 1, 0), Point<3>(1, 1, 0)}};
  const std::array<Point<3>, 4> inverted{
    {Point<3>(0, 0, 0), Point<3>(0, 1, 0), Point<3>(1, 0, 0), Point<3>(0, 0, 1)}};
  deallog << "mean ratio: regular, error "
          << below(softopt::mean_ratio(regular) - 1, 1e-14) << std::endl;
  deallog << "mean ratio: cube corner, error "
          << below(softopt::mean_ratio(corner) - 12 * std::pow(0.5, 2. / 3.) / 9, 1e-14)
          << std::endl;
  deallog << "mean ratio: flat " << softopt::mean_ratio(flat) << ", inside out "
          << softopt::mean_ratio(inverted) << " (-1/6)" << std::endl;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_design.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  softopt::DesignIterate x = random_design(problem, settings);
  problem.evaluate(x);
  const auto &design = problem.design_configuration();

  const auto hxt = softopt::remesh_design(design, "hxt.msh");
  deallog << "default sliver quality " << softopt::NewMesh::sliver_quality
          << ": meshed " << (hxt.meshed_twice ? "TWICE" : "once") << ", by "
          << (hxt.delaunay ? "Delaunay" : "HXT") << ", worst element "
          << (hxt.worst_quality > softopt::NewMesh::sliver_quality ? "above" : "NOT above")
          << " it; in the file, error "
          << below(worst_in_file("hxt.msh") - hxt.worst_quality, 1e-12) << std::endl;

  const auto both = softopt::remesh_design(design, "both.msh", 0, 1.);
  deallog << "sliver quality 1: meshed " << (both.meshed_twice ? "twice" : "ONCE")
          << ", HXT's worst "
          << (both.hxt_worst_quality == hxt.worst_quality ? "as before" : "NOT AS BEFORE")
          << ", the kept one's the better of the two, error "
          << below(both.worst_quality -
                     std::max(both.hxt_worst_quality, both.delaunay_worst_quality),
                   1e-15)
          << "; in the file, error "
          << below(worst_in_file("both.msh") - both.worst_quality, 1e-12) << std::endl;
  deallog << "the other algorithm's file is "
          << (std::filesystem::exists("both.delaunay.msh") ? "STILL THERE" : "gone")
          << "; the log says: " << both.note() << std::endl;
  deallog << "after HXT alone, the log says " << (hxt.note().empty() ? "nothing" : "SOMETHING")
          << std::endl;

  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::filesystem::create_directories("failed.delaunay.msh/in_the_way");
      std::filesystem::remove("failed.delaunay.log");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const auto failed = softopt::remesh_design(design, "failed.msh", 0, 1.);
  deallog << "Delaunay failing: " << (failed.delaunay_failed ? "noticed" : "NOT NOTICED")
          << ", HXT's mesh " << (failed.delaunay ? "NOT KEPT" : "kept") << ", worst "
          << (failed.worst_quality == hxt.worst_quality ? "as HXT's" : "NOT AS HXT'S")
          << "; in the file, error "
          << below(worst_in_file("failed.msh") - failed.worst_quality, 1e-12)
          << "; gmsh's message "
          << (std::filesystem::exists("failed.delaunay.log") && std::filesystem::file_size("failed.delaunay.log") > 0 ? "kept" : "MISSING")
          << std::endl;
  deallog << "the log says: " << failed.note() << std::endl;
}
