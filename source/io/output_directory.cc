#include <deal.II/base/exceptions.h>

#include <softopt/io/output_directory.h>

#include <filesystem>
#include <fstream>

namespace softopt
{
  OutputDirectory::OutputDirectory(const std::string &directory,
                                   const MPI_Comm     comm)
    : directory(directory)
    , comm(comm)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code code;
        std::filesystem::create_directories(directory, code);
        if (code)
          error = code.message();
      }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(),
                dealii::ExcMessage("Cannot create the output directory <" +
                                   directory + ">: " + error));
  }



  const std::string &
  OutputDirectory::path() const
  {
    return directory;
  }



  std::string
  OutputDirectory::file(const std::string &name) const
  {
    return (std::filesystem::path(directory) / name).string();
  }



  void
  OutputDirectory::write_parameters(const dealii::ParameterHandler &prm) const
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream out(file("parameters.prm"));
    prm.print_parameters(out, dealii::ParameterHandler::PRM);
  }



  void
  OutputDirectory::write_text(const std::string &name,
                              const std::string &text) const
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream out(file(name));
    out << text;
  }
} // namespace softopt
