#include <deal.II/base/data_out_base.h>

#include <softopt/io/pvd_series.h>

#include <filesystem>
#include <fstream>

namespace softopt
{
  PvdSeries::PvdSeries(const std::string &file, const MPI_Comm comm)
    : file(file)
    , comm(comm)
  {}



  void
  PvdSeries::add(const double time, const std::string &vtu_file)
  {
    entries.emplace_back(time, vtu_file);
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // Write aside and rename, so a reader never sees a half-written file.
    const std::string tmp = file + ".tmp";
    {
      std::ofstream out(tmp);
      dealii::DataOutBase::write_pvd_record(out, entries);
    }
    std::filesystem::rename(tmp, file);
  }
} // namespace softopt
