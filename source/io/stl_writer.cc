#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <softopt/io/stl_writer.h>
#include <softopt/shape/boundary_faces.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>

namespace softopt
{
  void
  write_stl(const std::vector<double> &corners, const std::string &file, const std::string &title)
  {
    const std::string temporary = file + ".tmp";
    {
      std::ofstream out(temporary, std::ios::binary);
      AssertThrow(out, ExcMessage("Cannot write " + temporary));
      std::array<char, 80> header{};
      std::copy(title.begin(), title.begin() + std::min<std::size_t>(title.size(), 80), header.begin());
      out.write(header.data(), header.size());
      const std::uint32_t count = corners.size() / 9;
      out.write(reinterpret_cast<const char *>(&count), sizeof(count));
      for (std::size_t t = 0; t < corners.size(); t += 9)
        {
          // Single precision, as STL stores it: the normal from the
          // stored corners.
          std::array<float, 12> record; // normal, then three corners
          for (unsigned int i = 0; i < 9; ++i)
            record[3 + i] = static_cast<float>(corners[t + i]);
          const auto corner = [&](const unsigned int k) {
            return Point<3>(record[3 + 3 * k], record[4 + 3 * k], record[5 + 3 * k]);
          };
          Tensor<1, 3> n    = cross_product_3d(corner(1) - corner(0), corner(2) - corner(0));
          const double norm = n.norm();
          if (norm > 0)
            n /= norm;
          for (unsigned int d = 0; d < 3; ++d)
            record[d] = static_cast<float>(n[d]);
          out.write(reinterpret_cast<const char *>(record.data()), 48);
          const std::uint16_t attribute = 0;
          out.write(reinterpret_cast<const char *>(&attribute), 2);
        }
      AssertThrow(out, ExcMessage("Writing " + temporary + " failed"));
    }
    AssertThrow(std::rename(temporary.c_str(), file.c_str()) == 0,
                ExcMessage("Cannot rename " + temporary + " to " + file));
  }



  unsigned int
  write_design_stl(const DesignConfiguration &design,
                   const std::string         &file,
                   const Deformation         *deformation)
  {
    const auto comm = design.get_dof_handler().get_communicator();

    const std::vector<double> corners =
      gathered_boundary_triangles(design, nullptr, deformation);
    unsigned int n_triangles = corners.size() / 9;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_stl(corners, file, deformation ? "softopt deformed design, mm" : "softopt design, mm");
    return Utilities::MPI::broadcast(comm, n_triangles, 0);
  }
} // namespace softopt
