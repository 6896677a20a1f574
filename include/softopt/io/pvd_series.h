#ifndef softopt_io_pvd_series_h
#define softopt_io_pvd_series_h

#include <deal.II/base/mpi.h>

#include <string>
#include <utility>
#include <vector>

namespace softopt
{
  /**
   * A ParaView .pvd file listing a series of .vtu/.pvtu files by "time"
   * (the load factor, or the design iteration). Rewritten after every
   * addition, so ParaView can open it while a run goes on.
   */
  class PvdSeries
  {
  public:
    PvdSeries(const std::string &file, const MPI_Comm comm);

    /** A series that goes on from the one in @p file (a restarted run):
     * its entries with times before @p continue_at whose files still
     * exist come first. */
    PvdSeries(const std::string &file, const MPI_Comm comm, const double continue_at);

    void
    add(const double time, const std::string &vtu_file);

  private:
    std::string                                 file;
    MPI_Comm                                    comm;
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace softopt

#endif
