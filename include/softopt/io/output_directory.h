#ifndef softopt_io_output_directory_h
#define softopt_io_output_directory_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace softopt
{
  /** The output directory of a run: created (by rank 0) on construction. */
  class OutputDirectory
  {
  public:
    OutputDirectory(const std::string &directory, const MPI_Comm comm);

    /** The directory. */
    const std::string &
    path() const;

    /** @p name inside the directory. */
    std::string
    file(const std::string &name) const;

    /** Writes the expanded parameter file (every entry, with defaults) as
     * parameters.prm. */
    void
    write_parameters(const dealii::ParameterHandler &prm) const;

    /** Writes @p text to @p name (rank 0). */
    void
    write_text(const std::string &name, const std::string &text) const;

  private:
    std::string directory;
    MPI_Comm    comm;
  };
} // namespace softopt

#endif
