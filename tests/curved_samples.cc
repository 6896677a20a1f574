// The surface of wall_thickness() sampled finer than the mesh: each
// quadratic boundary face split k x k on its curved map (curved_triangles()),
// on the actuator of Table I at 4 mm moved 0.2 mm off its initial design
// along a random direction:
// - the sample points are the design's mapping (MappingFEField) at the
//   lattice points (i, j)/k of each face's reference triangle, k = 3: the
//   quadratic shape functions and their nodes are the mapping's;
// - the sampled surface is closed for k = 2, 3, 4: every edge lies in two
//   triangles that run along it in opposite directions (the points on
//   shared edges are equal to the last bit from both faces), its Euler
//   characteristic is 4 (the outer surface and the cavity's, two spheres),
//   and every inward ray finds an opposite wall;
// - the derivative of each ray's thickness with respect to the design
//   positions, through the sample points' quadratic shape functions
//   (thickness_gradient() and WallThickness::node_dofs), against a Taylor
//   expansion along another random direction, for k = 4: the largest
//   remainder over the rays whose derivative exists and that end on the
//   same triangle at every step (no kink in between) falls as h^2.

#include <deal.II/base/mpi.h>

#include <softopt/app/analysis.h>
#include <softopt/app/settings.h>
#include <softopt/shape/boundary_faces.h>
#include <softopt/shape/wall_thickness.h>

#include "tests.h"

#include <map>

using namespace softopt_tests;

namespace
{
  /** Whether @p wall's triangles form closed surfaces, and their Euler
   * characteristic V - E + F. */
  std::pair<bool, long>
  closed(const softopt::WallThickness &wall)
  {
    std::map<std::pair<unsigned int, unsigned int>, int> edges; // +1 a->b, -1 b->a
    std::map<std::pair<unsigned int, unsigned int>, int> uses;
    for (const auto &t : wall.triangles)
      for (unsigned int v = 0; v < 3; ++v)
        {
          const unsigned int a = t[v], b = t[(v + 1) % 3];
          const auto         key = std::minmax(a, b);
          edges[key] += a < b ? 1 : -1;
          ++uses[key];
        }
    bool ok = true;
    for (const auto &[key, n] : uses)
      ok &= n == 2 && edges[key] == 0;
    return {ok,
            static_cast<long>(wall.nodes.size()) - static_cast<long>(uses.size()) +
              static_cast<long>(wall.triangles.size())};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool                       root = Utilities::MPI::this_mpi_process(comm) == 0;

  softopt::Settings     settings(SOURCE_DIR "/inputs/actuator_thin_walls.prm");
  softopt::AnalysisBody body(settings, comm);
  auto                 &design = *body.design;
  // X + h * delta, delta a random field of the design DoFs.
  const auto move = [&](const double h) {
    auto psi = design.create_vector();
    for (const auto i : psi.locally_owned_elements())
      psi(i) = 0.2 * random(i, 5) + h * random(i, 7);
    psi.compress(VectorOperation::insert);
    design.set_shape_field(psi);
  };
  move(0);

  {
    // Face f's vertex v is cell vertex w(v); the lattice point of
    // barycentric coordinates l/k in the face's vertices lies at
    // sum_v l_v/k xi_w(v) in the cell's reference tetrahedron.
    const unsigned int k     = 3;
    const auto         faces = softopt::locally_owned_boundary_faces(design);
    std::size_t        next  = 0;
    double             worst = 0;
    for (const auto &cell : design.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              std::vector<Point<3>> samples;
              for (const auto &t : softopt::curved_triangles(faces[next++], k))
                for (const auto &p : t)
                  samples.push_back(p.x);
              std::array<Point<3>, 3> xi;
              for (unsigned int v = 0; v < 3; ++v)
                for (const unsigned int w : cell->vertex_indices())
                  if (cell->vertex_index(w) == cell->face(f)->vertex_index(v))
                    xi[v] = cell->reference_cell().template vertex<3>(w);
              for (unsigned int i = 0; i <= k; ++i)
                for (unsigned int j = 0; i + j <= k; ++j)
                  {
                    const Point<3> unit = (double(k - i - j) * xi[0] + double(i) * xi[1] +
                                           double(j) * xi[2]) / double(k);
                    const Point<3> x = design.get_mapping().transform_unit_to_real_cell(cell, unit);
                    double nearest = std::numeric_limits<double>::max();
                    for (const auto &s : samples)
                      nearest = std::min(nearest, s.distance(x));
                    worst = std::max(worst, nearest);
                  }
            }
    deallog << "faces split 3 x 3: largest distance of the mapping's lattice points to the samples "
            << below(Utilities::MPI::max(worst, comm), 1e-10) << " mm" << std::endl;
  }

  for (const unsigned int k : {2u, 3u, 4u})
    {
      const auto wall = softopt::wall_thickness(design, {}, false, k);
      if (root)
        {
          const auto [ok, euler] = closed(wall);
          deallog << "faces split " << k << " x " << k << ": " << wall.triangles.size()
                  << " triangles; every edge in two of opposite directions: "
                  << (ok ? "yes" : "NO") << "; V - E + F = " << euler
                  << (euler == 4 ? " (= 4)" : " (NOT 4)") << "; rays without an opposite wall: "
                  << wall.n_without_opposite << (wall.n_without_opposite == 0 ? " (= 0)" : " (NOT 0)")
                  << std::endl;
        }
    }

  const unsigned int  k     = 4;
  const auto          wall  = softopt::wall_thickness(design, {}, false, k);
  const auto          steps = std::vector<double>{1e-2, 3e-3, 1e-3, 3e-4};
  std::vector<softopt::WallThickness> moved;
  for (const double h : steps)
    {
      move(h);
      moved.push_back(softopt::wall_thickness(design, {}, false, k));
    }
  if (root)
    {
      // d t_i / d h = sum over the sample points v it depends on of
      // dt/dX_v . sum_a N_a(v) delta_a.
      std::vector<double> remainder(steps.size(), 0.);
      unsigned int        n_rays = 0;
      for (unsigned int i = 0; i < wall.nodes.size(); ++i)
        {
          bool same = wall.differentiable[i];
          for (const auto &w : moved)
            same &= w.nodes.size() == wall.nodes.size() && w.differentiable[i] &&
                    w.hit[i] == wall.hit[i];
          if (!same)
            continue;
          ++n_rays;
          double slope = 0;
          for (const auto &[v, dt_dX] : softopt::thickness_gradient(wall, i))
            for (const auto &[N_a, dofs] : wall.node_dofs[v])
              for (unsigned int c = 0; c < 3; ++c)
                slope += dt_dX[c] * N_a * random(dofs[c], 7);
          for (unsigned int s = 0; s < steps.size(); ++s)
            remainder[s] = std::max(remainder[s],
                                    std::abs(moved[s].thickness[i] - wall.thickness[i] -
                                             steps[s] * slope));
        }
      deallog << "faces split 4 x 4: " << (n_rays > wall.nodes.size() / 2 ? "more" : "NOT more")
              << " than half the rays on the same triangle at every step; largest Taylor remainder:";
      for (unsigned int s = 0; s + 1 < steps.size(); ++s)
        deallog << ' ' << rate(remainder[s], remainder[s + 1], steps[s], steps[s + 1]);
      deallog << std::endl;
    }
}
