#include <deal.II/base/exceptions.h>

#include <softopt/io/csv_writer.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace softopt
{
  CsvWriter::CsvWriter(const std::string              &file,
                       const std::vector<std::string> &columns,
                       const MPI_Comm                  comm)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    name = file;
    errno = 0;
    out.open(file);
    AssertThrow(out.good(), dealii::ExcMessage(cannot_write()));
    add_row(columns);
  }



  CsvWriter::CsvWriter(const std::string &file, const MPI_Comm comm)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    name = file;
    errno = 0;
    out.open(file, std::ios::app);
    AssertThrow(out.good(), dealii::ExcMessage(cannot_write()));
  }



  void
  CsvWriter::add_row(const std::vector<std::string> &row)
  {
    if (!out.is_open())
      return;
    // The row in one piece, so that a kill cuts at most the row being
    // written (which a restart drops).
    std::string line;
    for (unsigned int i = 0; i < row.size(); ++i)
      line += (i > 0 ? "," : "") + row[i];
    line += '\n';
    errno = 0;
    out << line << std::flush;
    AssertThrow(out.good(), dealii::ExcMessage(cannot_write()));
  }



  std::string
  CsvWriter::cannot_write() const
  {
    return "Cannot write <" + name + ">: " +
           (errno != 0 ? std::strerror(errno) : "unknown reason") + ".";
  }



  std::string
  CsvWriter::format(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(10) << value;
    return s.str();
  }



  std::string
  CsvWriter::fixed(const double value, const unsigned int decimals)
  {
    const double scale   = std::pow(10., decimals);
    double       rounded = std::round(value * scale) / scale;
    if (rounded == 0)
      rounded = 0;
    std::ostringstream s;
    s << std::fixed << std::setprecision(decimals) << rounded;
    return s.str();
  }
} // namespace softopt
