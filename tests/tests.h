// Shared helpers for softopt's tests (deal.II style: a test writes to the
// file "output" through deallog; numdiff compares it with foo.output).
#ifndef softopt_tests_h
#define softopt_tests_h

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <softopt/base/seeded_random.h>
#include <softopt/geometry/geometry.h>
#include <softopt/physics/material.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>
#include <string>

namespace softopt_tests
{
  using namespace dealii;

  /** deallog into the file "output", on rank 0 only. */
  class TestLog
  {
  public:
    TestLog()
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          file.open("output");
          deallog.attach(file, false);
        }
      deallog.depth_console(0);
      deallog << std::setprecision(8);
    }
    ~TestLog()
    {
      if (file.is_open())
        deallog.detach();
    }

  private:
    std::ofstream file;
  };

  /** The paper's material with E (MPa) and nu. */
  inline std::shared_ptr<const softopt::Material>
  neo_hookean(const double youngs_modulus, const double nu)
  {
    return softopt::Materials::create(
      "neo-Hookean",
      {{"Young's modulus", Utilities::to_string(youngs_modulus)},
       {"Poisson's ratio", Utilities::to_string(nu)}});
  }

  /** The Yeoh material with C_10, C_20, ... (MPa, comma-separated). */
  inline std::shared_ptr<const softopt::Material>
  yeoh(const std::string &coefficients, const double nu)
  {
    return softopt::Materials::create(
      "Yeoh",
      {{"Yeoh coefficients", coefficients},
       {"Poisson's ratio", Utilities::to_string(nu)}});
  }

  /** The rows of a CSV file written by CsvWriter, split at commas. */
  inline std::vector<std::vector<std::string>>
  read_csv(const std::string &file)
  {
    std::ifstream                         in(file);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);)
      rows.push_back(Utilities::split_string_list(line, ','));
    return rows;
  }

  /** A number with two significant digits (for errors that must be small). */
  inline std::string
  error(const double e)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(1) << e;
    return s.str();
  }

  /**
   * A small number with its verdict, "2.1e-09 (< 1e-08)" or "2.1e-07 (NOT <
   * 1e-08)": numdiff's absolute tolerance of 1e-6 passes any two numbers
   * below it, so the words carry the check.
   */
  inline std::string
  below(const double e, const double bound)
  {
    std::ostringstream b;
    b << std::scientific << std::setprecision(0) << bound;
    return error(e) + (std::abs(e) < bound ? " (< " : " (NOT < ") + b.str() + ")";
  }

  /** The observed order log(e_1 / e_2) / log(h_1 / h_2) of two errors at
   * steps h_1 > h_2, with its verdict against @p minimum. */
  inline std::string
  rate(const double e_1, const double e_2, const double h_1, const double h_2,
       const double minimum = 1.9)
  {
    const double       r = std::log(e_1 / e_2) / std::log(h_1 / h_2);
    std::ostringstream s;
    s << "rate " << std::fixed << std::setprecision(2) << r
      << (r >= minimum ? " (>= " : " (NOT >= ") << std::setprecision(1) << minimum << ")";
    return s.str();
  }

  /** A deterministic pseudo-random number in [-1, 1] for index i, the same
   * on any number of MPI ranks (softopt::seeded_random). */
  inline double
  random(const unsigned long i, const unsigned int seed = 1)
  {
    return softopt::seeded_random(i, seed);
  }

  /**
   * The unit cube cut into tetrahedra, distributed: boundary ids 0 at x = 0,
   * 1 at x = 1, 2 elsewhere.
   */
  inline void
  make_cube(parallel::fullydistributed::Triangulation<3> &triangulation,
            const unsigned int                            subdivisions = 2)
  {
    Triangulation<3> serial;
    GridGenerator::subdivided_hyper_cube_with_simplices(serial, subdivisions);
    for (const auto &face : serial.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(face->center()[0] < 1e-12       ? 0 :
                              face->center()[0] > 1. - 1e-12 ? 1 :
                                                                2);
    softopt::Geometry::distribute(serial, triangulation);
  }
} // namespace softopt_tests

#endif
