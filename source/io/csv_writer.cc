#include <deal.II/base/exceptions.h>

#include <softopt/io/csv_writer.h>

#include <cmath>
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
    out.open(file);
    AssertThrow(out.good(), dealii::ExcMessage("Cannot write <" + file + ">."));
    add_row(columns);
  }



  CsvWriter::CsvWriter(const std::string &file, const MPI_Comm comm)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    out.open(file, std::ios::app);
    AssertThrow(out.good(), dealii::ExcMessage("Cannot write <" + file + ">."));
  }



  void
  CsvWriter::add_row(const std::vector<std::string> &row)
  {
    if (!out.is_open())
      return;
    for (unsigned int i = 0; i < row.size(); ++i)
      out << (i > 0 ? "," : "") << row[i];
    out << std::endl;
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
