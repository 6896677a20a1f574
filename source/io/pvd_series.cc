#include <deal.II/base/data_out_base.h>

#include <softopt/io/pvd_series.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace softopt
{
  PvdSeries::PvdSeries(const std::string &file, const MPI_Comm comm)
    : file(file)
    , comm(comm)
  {}



  PvdSeries::PvdSeries(const std::string &file,
                       const MPI_Comm     comm,
                       const double       continue_at)
    : PvdSeries(file, comm)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // deal.II's records: <DataSet timestep="T" group="" part="0" file="F"/>
    const auto folder = std::filesystem::path(file).parent_path();
    std::ifstream in(file);
    const auto    value = [](const std::string &line, const std::string &key) {
      const auto start = line.find(key + "=\"");
      if (start == std::string::npos)
        return std::string();
      const auto from = start + key.size() + 2;
      return line.substr(from, line.find('"', from) - from);
    };
    for (std::string line; std::getline(in, line);)
      {
        const std::string time = value(line, "timestep"), vtu = value(line, "file");
        std::error_code   error;
        if (line.find("<DataSet") == std::string::npos || time.empty() ||
            vtu.empty() || !std::filesystem::exists(folder / vtu, error))
          continue;
        char        *end = nullptr;
        const double t   = std::strtod(time.c_str(), &end);
        if (*end == '\0' && t < continue_at)
          entries.emplace_back(t, vtu);
      }
  }



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
