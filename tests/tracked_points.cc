// Tracked points ("Tracked points" in subsection Output) on the thick sphere
// octant of sphere_inflation (inputs/tracked_sphere.prm: A = 1, B = 2,
// nu = 0.4999, 693 tetrahedra, p = 0.5 mu), through follow_load_path and the
// tracked_points.csv it writes.
//
// The nearest-node search: "pole" is a mesh vertex (distance 0); "diagonal"
// lies 0.2 outside the outer surface and "inner" 0.13 inside the cavity, so
// their nodes lie on the spheres r = 2 and r = 1 a little farther away;
// "wall" lies inside the wall on the symmetry plane x = 0, which is not
// searched, so its node lies on the outer sphere (r = 2, x = 0) 0.44 away;
// "far" is 3.1 away and must be warned about. (The same nodes come out of a
// brute-force search over gmsh's quadratic surface nodes.)
//
// The displacement: at every converged step the radial displacement of each
// node must match the closed form of sphere.h at the node's radius R,
// u_r = R (lambda(R) - 1) with lambda(R)^3 = 1 + (lambda_a^3 - 1) (A/R)^3,
// within 1% (measured: 0.2-0.8% on this coarse mesh), and its tangential
// part must be small (measured: below 0.3%; the pole sits on two symmetry
// planes, so u_x = u_y = 0 there exactly). Reading a neighbouring node or
// swapping components shows as a tangential part of order 10% and an error
// above 1%. The two-rank variant must print the same: there the nearest
// nodes of "pole", "inner" and "far" live on rank 1.

#include <softopt/app/analysis.h>
#include <softopt/app/settings.h>

#include "sphere.h"

#include <filesystem>

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root = Utilities::MPI::this_mpi_process(comm) == 0;

  softopt::Settings settings(SOURCE_DIR "/inputs/tracked_sphere.prm");
  parallel::fullydistributed::Triangulation<3> triangulation(comm);
  const softopt::DesignConfiguration design(
    triangulation, settings.geometry.create_triangulation(triangulation));
  softopt::HyperelasticProblem       problem(triangulation,
                                       design.get_mapping(),
                                       settings.geometry,
                                       *settings.material,
                                       settings.loading.pressure_kPa * 1e-3);
  problem.setup_system();
  deallog << "tetrahedra: " << triangulation.n_global_active_cells()
          << std::endl;

  const std::string directory = "results";
  if (root)
    std::filesystem::create_directories(directory);
  MPI_Barrier(comm);
  std::ostringstream       printed;
  const ConditionalOStream pcout(printed, root);
  softopt::follow_load_path(problem,
                            design,
                            settings,
                            {},
                            settings.loading.target_load_factors,
                            directory,
                            pcout);
  if (!root)
    return 0;

  // What the program printed about the search.
  std::istringstream lines(printed.str());
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("Tracked point", 0) == 0 || line.rfind("  Warning", 0) == 0)
      deallog << line << std::endl;

  const auto rows = read_csv(directory + "/tracked_points.csv");
  deallog << "columns:";
  for (const auto &c : rows[0])
    deallog << ' ' << c;
  deallog << std::endl;
  deallog << "rows: " << rows.size() - 1 << ", load_path.csv rows: "
          << read_csv(directory + "/load_path.csv").size() - 1 << std::endl;

  const double A = 1., B = 2.;
  const double p_over_mu =
    settings.loading.pressure_kPa * 1e-3 / settings.material->shear_modulus;
  const auto &names = settings.output.tracked_points;
  for (unsigned int r = 1; r < rows.size(); ++r)
    {
      const double lambda = std::stod(rows[r][1]);
      if (lambda == 0)
        continue;
      const double lambda_a = closed_form_stretch(lambda * p_over_mu, A / B);
      deallog << "load factor " << lambda << ":" << std::endl;
      double worst = 0, worst_tangential = 0;
      for (unsigned int k = 0; k < names.size(); ++k)
        {
          Point<3>     X;
          Tensor<1, 3> u;
          for (unsigned int c = 0; c < 3; ++c)
            {
              X[c] = std::stod(rows[r][3 + 6 * k + c]);
              u[c] = std::stod(rows[r][6 + 6 * k + c]);
            }
          const double       R   = X.norm();
          const Tensor<1, 3> e_r = X / R;
          const double       u_r = u * e_r;
          const double       exact =
            R *
            (std::cbrt(1 + (std::pow(lambda_a, 3) - 1) * std::pow(A / R, 3)) -
             1);
          const double relative_error = std::abs(u_r - exact) / exact;
          const double tangential     = (u - u_r * e_r).norm() / std::abs(u_r);
          worst                       = std::max(worst, relative_error);
          worst_tangential            = std::max(worst_tangential, tangential);
          deallog << "  " << names[k].name << ": R = " << R << ", u_r = " << u_r
                  << ", closed form " << exact << ", relative error "
                  << error(relative_error) << ", |u_t| / |u_r| "
                  << (tangential < 1e-8 ? "below 1e-8" : error(tangential));
          if (names[k].name == "pole")
            deallog << " (u_x = " << u[0] << ", u_y = " << u[1] << ")";
          deallog << std::endl;
        }
      deallog << "  largest relative error "
              << (worst < 1e-2 ? "below 1%" : "ABOVE 1%")
              << ", largest |u_t| / |u_r| "
              << (worst_tangential < 1e-2 ? "below 1%" : "ABOVE 1%")
              << std::endl;
    }
}
