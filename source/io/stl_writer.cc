#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <softopt/io/stl_writer.h>
#include <softopt/shape/boundary_faces.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>

namespace softopt
{
  unsigned int
  write_design_stl(const DesignConfiguration &design, const std::string &file)
  {
    const auto comm = design.get_dof_handler().get_communicator();

    // Triangles of this rank as 9 floats each (x, y, z of three corners).
    std::vector<float> local;
    for (const auto &face : locally_owned_boundary_faces(design))
      for (const auto &t : flat_triangles(face))
        for (const auto &p : t)
          for (unsigned int d = 0; d < 3; ++d)
            local.push_back(static_cast<float>(p[d]));

    const auto all = Utilities::MPI::gather(comm, local, 0);
    unsigned int n_triangles = 0;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        for (const auto &part : all)
          n_triangles += part.size() / 9;
        const std::string temporary = file + ".tmp";
        {
          std::ofstream out(temporary, std::ios::binary);
          AssertThrow(out, ExcMessage("Cannot write " + temporary));
          std::array<char, 80> header{};
          const std::string    title = "softopt design, mm";
          std::copy(title.begin(), title.end(), header.begin());
          out.write(header.data(), header.size());
          const std::uint32_t count = n_triangles;
          out.write(reinterpret_cast<const char *>(&count), sizeof(count));
          for (const auto &part : all)
            for (std::size_t t = 0; t < part.size(); t += 9)
              {
                const Point<3> a(part[t], part[t + 1], part[t + 2]),
                  b(part[t + 3], part[t + 4], part[t + 5]),
                  c(part[t + 6], part[t + 7], part[t + 8]);
                Tensor<1, 3> n    = cross_product_3d(b - a, c - a);
                const double norm = n.norm();
                if (norm > 0)
                  n /= norm;
                const std::array<float, 3> normal{
                  {float(n[0]), float(n[1]), float(n[2])}};
                out.write(reinterpret_cast<const char *>(normal.data()), 12);
                out.write(reinterpret_cast<const char *>(&part[t]), 36);
                const std::uint16_t attribute = 0;
                out.write(reinterpret_cast<const char *>(&attribute), 2);
              }
          AssertThrow(out, ExcMessage("Writing " + temporary + " failed"));
        }
        AssertThrow(std::rename(temporary.c_str(), file.c_str()) == 0,
                    ExcMessage("Cannot rename " + temporary + " to " + file));
      }
    return Utilities::MPI::broadcast(comm, n_triangles, 0);
  }
} // namespace softopt
