// The quantity "thin walls" (softopt/functionals/quantities/thin_walls.cc):
// - on the thick sphere octant (walls B - A = 1 mm; t_min = 1.25 mm) against
//   the closed form Q = (1 - (B - A)/t_min)^2, within what the flat
//   triangles' chord error of 0.01 mm allows (castability's bound), and the
//   thickness itself at the points of each face split k x k on its curved
//   map: the error falls with the chord error as k goes from 2 (the nodes)
//   to 4;
// - its adjoint gradient (ray thickness through node, normal and hit
//   triangle, then the filter) against a Taylor expansion along a random
//   design direction, on the sphere (nodes on its symmetry planes left out)
//   and on the actuator of Table I (walls of 1.5 mm below t_min = 2 mm, and
//   the gaps across the cavity, 20 mm, below g_min = 25 mm), at a
//   design 0.2 mm off the initial one along another random direction, with
//   "Sampling size" 1 mm (each face split 3 x 3 on its curved map, the
//   derivative through the quadratic shape functions of the face): in
//   the initial mesh the ray of the node at (1.5, 0, 11.5) runs in the
//   plane of the cavity's floor and its length jumps (1.5 or 23 mm) with
//   any change of shape, a place where the ray thickness has no
//   derivative (such ties are rare in a design that moved). The ray
//   thickness is smooth only between such kinks, as where a ray moves to
//   the next triangle: the steps stay between 1e-3 and 3e-5 mm
//   (tests/curved_samples checks each ray's derivative alone, kinks left
//   out).

#include <deal.II/base/mpi.h>

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>
#include <softopt/shape/wall_thickness.h>

#include "taylor_test.h"

#include <cmath>

using namespace softopt_tests;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  {
    softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_thin_walls.prm");
    softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
    softopt::DesignIterate x      = problem.initial_iterate();
    const auto             values = problem.evaluate(x);
    const double           r      = 1. / 1.25;
    const double           Q      = values[1]; // f_1 = Q - 0
    // |dQ/dt| = 2 (1 - r) / t_min for a thickness error of 0.01 mm.
    const double bound = 2 * (1 - r) / 1.25 * 0.01;
    deallog << "sphere octant: Q " << Q << ", |Q - (1 - (B - A)/t_min)^2| "
            << below(Q - (1 - r) * (1 - r), bound) << std::endl;
    // Thickness B - A = 1 at the points of the spherical surfaces (off the
    // symmetry planes, where rays are tilted), the faces split k x k.
    std::vector<double> error;
    for (const unsigned int k : {2u, 4u})
      {
        const auto wall = softopt::wall_thickness(problem.design_configuration(),
                                                  settings.geometry.symmetry_planes(),
                                                  false,
                                                  k);
        double worst = 0;
        for (unsigned int i = 0; i < wall.nodes.size(); ++i)
          {
            const auto &p = wall.nodes[i];
            if (std::min({p[0], p[1], p[2]}) > 1e-9 && std::isfinite(wall.thickness[i]))
              worst = std::max(worst, std::abs(wall.thickness[i] - 1));
          }
        error.push_back(Utilities::MPI::broadcast(MPI_COMM_WORLD, worst, 0));
        deallog << "sphere octant, faces split " << k << " x " << k << " ("
                << Utilities::MPI::broadcast(MPI_COMM_WORLD, wall.nodes.size(), 0)
                << " points): largest |t - (B - A)| " << below(error.back(), 0.01)
                << "; rays without an opposite wall: "
                << Utilities::MPI::broadcast(MPI_COMM_WORLD, wall.n_without_opposite, 0)
                << (wall.n_without_opposite == 0 ? " (= 0)" : " (NOT 0)") << std::endl;
      }
    // Against the spacing of the points, h / k.
    deallog << "the error falls with the spacing: " << rate(error[0], error[1], 1. / 2, 1. / 4, 1.5)
            << std::endl;
    const auto gradients = problem.gradients(x);
    taylor_test(problem, x, values, gradients, settings.optimization.design_bound, 11);
  }
  {
    softopt::Settings      settings(SOURCE_DIR "/inputs/actuator_thin_walls.prm");
    softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
    softopt::DesignIterate x = problem.initial_iterate();
    for (const auto i : x.d.locally_owned_elements())
      x.d(i) = 0.2 * random(i, 5);
    x.d.compress(VectorOperation::insert);
    const auto values = problem.evaluate(x);
    deallog << "actuator: faces split "
            << softopt::surface_subdivisions(problem.design_configuration(), 1.) << " x "
            << softopt::surface_subdivisions(problem.design_configuration(), 1.) << ", Q "
            << values[1] << std::endl;
    const auto gradients = problem.gradients(x);
    // Steps of 1e-3 to 3e-5 mm: larger ones cross the edges where a ray
    // moves to the next triangle (a kink), smaller ones meet the noise of
    // the Newton and filter solves.
    taylor_test(problem, x, values, gradients, 1., 11, {1e-3, 3e-4, 1e-4, 3e-5});
  }
}
