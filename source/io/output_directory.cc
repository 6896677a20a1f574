#include <deal.II/base/exceptions.h>

#include <softopt/io/output_directory.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iostream>

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
          error = "Cannot create the output directory <" + directory +
                  ">: " + code.message();
        else
          error = acquire_lock();
      }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), dealii::ExcMessage(error));
  }



  OutputDirectory::~OutputDirectory()
  {
    if (lock >= 0)
      ::close(lock); // releases the flock
  }



  std::string
  OutputDirectory::acquire_lock()
  {
    const std::string name = file("softopt.lock");
    // Not inherited by gmsh or the plotting script, which could otherwise
    // hold the lock after this process ends.
    lock = ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock < 0)
      return "Cannot write into the output directory <" + directory +
             ">: " + name + ": " + std::strerror(errno);
    if (::flock(lock, LOCK_EX | LOCK_NB) != 0)
      {
        const int   reason = errno;
        std::string holder;
        std::getline(std::ifstream(name), holder);
        ::close(lock);
        lock = -1;
        // A file system without locks (some cluster mounts): no lock.
        if (reason == ENOSYS || reason == EOPNOTSUPP || reason == ENOLCK)
          {
            std::cerr << "Warning: " << name << " cannot be locked ("
                      << std::strerror(reason) << "): nothing stops a second "
                      << "run into this directory." << std::endl;
            return "";
          }
        if (reason != EWOULDBLOCK)
          return "Cannot lock " + name + ": " + std::strerror(reason);
        return "Another softopt run (" + (holder.empty() ? "unknown" : holder) +
               ") is writing into the output directory <" + directory +
               ">. Wait for it to end, or set another \"Output directory\".";
      }
    char host[256] = "";
    ::gethostname(host, sizeof(host) - 1);
    const std::string holder =
      "process " + std::to_string(::getpid()) + " on " + host + "\n";
    if (::ftruncate(lock, 0) != 0 ||
        ::write(lock, holder.data(), holder.size()) != ssize_t(holder.size()))
      return "Cannot write " + name + ": " + std::strerror(errno);
    return "";
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
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::PRM);
    write_whole_file(file("parameters.prm"), text.str());
  }



  void
  OutputDirectory::write_text(const std::string &name,
                              const std::string &text) const
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    write_whole_file(file(name), text);
  }



  void
  write_whole_file(const std::string &name, const std::string &text)
  {
    // Aside, then renamed over the old one: a kill leaves either version.
    const std::string aside = name + ".part";
    errno                   = 0;
    {
      std::ofstream out(aside);
      out << text;
      out.flush();
      AssertThrow(out.good(),
                  dealii::ExcMessage("Cannot write <" + name + "> (as <" + aside + ">): " +
                                     (errno != 0 ? std::strerror(errno) :
                                                   "unknown reason") + "."));
    }
    std::error_code error;
    std::filesystem::rename(aside, name, error);
    AssertThrow(!error,
                dealii::ExcMessage("Cannot rename <" + aside + "> to <" + name +
                                   ">: " + error.message() + "."));
  }
} // namespace softopt
