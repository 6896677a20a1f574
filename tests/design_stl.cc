// design.stl is watertight and encloses the body: for the thick sphere
// octant (one closed surface) and the actuator of Table I (outer surface and
// the closed cavity), every edge of the triangulated boundary lies in exactly
// two triangles, traversed once in each direction (consistent outward
// orientation); the Euler characteristic is 2 per closed surface; and the
// volume the triangles enclose (divergence theorem) matches the volume of
// the curved P2 mesh and, for the sphere, the exact (pi/6)(B^3 - A^3).

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/base/quadrature_lib.h>

#include <softopt/io/stl_writer.h>
#include <softopt/shape/design_configuration.h>

#include "body_volume.h"
#include "tests.h"

#include <array>
#include <cstdint>
#include <map>
#include <set>

using namespace softopt_tests;

namespace
{
  /** Reads a binary STL and reports its topology and enclosed volume. */
  void
  check_stl(const std::string &file, const double reference_volume)
  {
    std::ifstream in(file, std::ios::binary);
    in.seekg(80);
    std::uint32_t n = 0;
    in.read(reinterpret_cast<char *>(&n), 4);
    using Vertex = std::array<float, 3>;
    std::map<Vertex, unsigned int>                       vertices;
    std::map<std::pair<unsigned int, unsigned int>, int> directed;
    double                                               volume = 0;
    for (std::uint32_t t = 0; t < n; ++t)
      {
        std::array<float, 12> data;
        in.read(reinterpret_cast<char *>(data.data()), 48);
        in.seekg(2, std::ios::cur);
        std::array<unsigned int, 3> id;
        std::array<Point<3>, 3>     p;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Vertex v{{data[3 + 3 * k], data[4 + 3 * k], data[5 + 3 * k]}};
            id[k] = vertices.emplace(v, vertices.size()).first->second;
            p[k]  = Point<3>(v[0], v[1], v[2]);
          }
        for (unsigned int k = 0; k < 3; ++k)
          ++directed[{id[k], id[(k + 1) % 3]}];
        volume += p[0] * cross_product_3d(p[1], p[2]) / 6.;
      }
    AssertThrow(in, ExcMessage("truncated STL"));

    unsigned int n_edges = 0, bad = 0;
    for (const auto &[edge, count] : directed)
      {
        const auto reverse = directed.find({edge.second, edge.first});
        bad += count != 1 || reverse == directed.end() || reverse->second != 1;
        n_edges += edge.first < edge.second;
      }
    deallog << n << " triangles; edges not shared by exactly two triangles "
            << "in opposite directions: " << bad << std::endl;
    deallog << "Euler characteristic V - E + F = "
            << int(vertices.size()) - int(n_edges) + int(n) << std::endl;
    deallog << "enclosed volume / reference - 1 = "
            << error(volume / reference_volume - 1) << std::endl;
  }

  void
  run(const std::string                          &name,
      const std::string                          &geo,
      const double                                h,
      const std::map<std::string, double>        &parameters,
      const double                                exact_volume)
  {
    softopt::Geometry geometry;
    geometry.mesh_file       = SOURCE_DIR "/../meshes/" + geo;
    geometry.mesh_size       = h;
    geometry.mesh_parameters = parameters;
    parallel::fullydistributed::Triangulation<3> triangulation(MPI_COMM_WORLD);
    const softopt::DesignConfiguration design(triangulation,
                                             geometry.create_triangulation(triangulation));

    const std::string file = name + ".stl";
    softopt::write_design_stl(design, file);
    const double volume = body_volume(design);
    deallog << name << ":" << std::endl;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        check_stl(file, volume);
        if (exact_volume > 0)
          deallog << "mesh volume / exact - 1 = "
                  << error(volume / exact_volume - 1) << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  TestLog                          log;
  run("sphere_octant",
      "sphere_octant.geo",
      0.4,
      {{"A", 1.}, {"B", 2.}},
      numbers::PI / 6 * (8 - 1));
  run("actuator", "actuator.geo", 6, {}, 0);
}
