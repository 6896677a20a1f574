#ifndef softopt_io_csv_writer_h
#define softopt_io_csv_writer_h

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <vector>

namespace softopt
{
  /**
   * A CSV file written one row at a time by rank 0 and flushed after every
   * row, so that it stays valid up to the last row if a run dies.
   */
  class CsvWriter
  {
  public:
    /** Opens (truncates) @p file and writes the header. */
    CsvWriter(const std::string              &file,
              const std::vector<std::string> &columns,
              const MPI_Comm                  comm);

    /** Opens @p file to append rows (a restarted run). */
    CsvWriter(const std::string &file, const MPI_Comm comm);

    /** Appends a row; every entry already formatted. */
    void
    add_row(const std::vector<std::string> &row);

    /** A number with 10 significant digits. */
    static std::string
    format(const double value);

    /** A number rounded to @p decimals, without the sign of a rounded
     * zero (-3e-32 on a symmetry plane prints as 0.000). */
    static std::string
    fixed(const double value, const unsigned int decimals);

  private:
    /** "Cannot write <file>: the system's reason." */
    std::string
    cannot_write() const;

    std::string   name;
    std::ofstream out;
  };
} // namespace softopt

#endif
