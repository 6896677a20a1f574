#ifndef softopt_io_output_directory_h
#define softopt_io_output_directory_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace softopt
{
  /**
   * The output directory of a run: created (by rank 0) on construction and
   * owned by the run while the object lives. Rank 0 holds an exclusive lock
   * (flock) on `softopt.lock` in it, which names the process; a second run
   * into the same directory stops at once with a message naming the first.
   * The operating system releases the lock when the process ends, however
   * it ends, so a killed run leaves no stale lock.
   */
  class OutputDirectory
  {
  public:
    OutputDirectory(const std::string &directory, const MPI_Comm comm);

    ~OutputDirectory();

    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &
    operator=(const OutputDirectory &) = delete;

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

    /** Writes @p text to @p name (rank 0), whole: see write_whole_file(). */
    void
    write_text(const std::string &name, const std::string &text) const;

  private:
    /** Rank 0: locks softopt.lock; returns an error message or "". */
    std::string
    acquire_lock();

    std::string directory;
    MPI_Comm    comm;
    /** The locked file's descriptor on rank 0 (-1 elsewhere). */
    int lock = -1;
  };
  /** Writes @p text to the file @p name aside and renames it over @p name,
   * so that a kill leaves the old file or the new one, never a part. Throws
   * a message naming the file and the system's reason (a full disk). */
  void
  write_whole_file(const std::string &name, const std::string &text);
} // namespace softopt

#endif
