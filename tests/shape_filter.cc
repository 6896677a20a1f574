// The shape filter (Eq. PDEpot02): its tangent against central differences of
// its residual; d = 0 gives psi = 0; and a mesh update (X_o <- X_o + psi,
// d <- 0) leaves the geometry and every functional unchanged.

#include <softopt/app/settings.h>
#include <softopt/optimization/design_problem.h>

#include "tests.h"

using namespace softopt_tests;
using PVector = PETScWrappers::MPI::Vector;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;

  softopt::Settings      settings(SOURCE_DIR "/inputs/sphere_design.prm");
  softopt::DesignProblem problem(settings, MPI_COMM_WORLD);
  // A filter of its own on the problem's design configuration.
  softopt::ShapeFilter filter(settings.shape_filter);
  filter.setup(problem.design_configuration(), settings.geometry);

  auto random_vector = [&](const double scale, const unsigned int seed) {
    PVector v = problem.create_design_vector();
    for (const auto i : v.locally_owned_elements())
      v(i) = scale * random(i, seed);
    v.compress(VectorOperation::insert);
    filter.get_constraints().set_zero(v);
    return v;
  };

  // Tangent against central differences at a strongly deformed psi.
  const PVector d = random_vector(0.05, 1), psi = random_vector(0.01, 2),
               direction = random_vector(1., 3);
  filter.residual(d, psi, true);
  PVector K_direction = problem.create_design_vector();
  filter.tangent().vmult(K_direction, direction);
  double previous = 0;
  for (const double h : {1e-3, 1e-4, 1e-5})
    {
      PVector plus = psi, minus = psi;
      plus.add(h, direction);
      minus.add(-h, direction);
      PVector fd = filter.residual(d, plus, false);
      fd -= filter.residual(d, minus, false);
      fd /= 2 * h;
      fd -= K_direction;
      // Central differences: the error falls as h^2 (about 1400 h^2 here).
      const double e = fd.l2_norm() / K_direction.l2_norm();
      deallog << "h = " << h << ": |K d - FD| / |K d| = " << below(e, 1e4 * h * h);
      if (previous > 0)
        deallog << ", " << rate(previous, e, 10 * h, h);
      deallog << std::endl;
      previous = e;
    }

  // d = 0 gives psi = 0.
  PVector psi_zero = problem.create_design_vector();
  filter.solve(problem.create_design_vector(), psi_zero);
  deallog << "d = 0: max |psi| = " << below(psi_zero.linfty_norm(), 1e-14) << std::endl;

  // A design, then a mesh update: the same geometry, the same functionals.
  problem.add_cavity_volume();
  softopt::DesignIterate x = problem.initial_iterate();
  x.d                      = random_vector(0.04, 4);
  const auto before        = problem.evaluate(x);
  const auto  &health        = problem.filter_result();
  deallog << "filter: " << health.iterations << " Newton iterations, min J_psi "
          << health.min_J_psi << ", worst element quality " << health.worst_quality
          << std::endl;
  problem.update_mesh(x);
  const auto after = problem.evaluate(x);
  for (unsigned int k = 0; k < before.size(); ++k)
    deallog << problem.functionals()[k]->name() << " = " << before[k]
            << ", after the mesh update: relative change "
            << (std::abs(after[k] - before[k]) <= 1e-10 * std::abs(before[k]) ?
                  "below 1e-10" :
                  error(std::abs(after[k] - before[k]) / std::abs(before[k])))
            << std::endl;
}
