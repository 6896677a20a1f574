#include <softopt/base/subprocess.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace softopt
{
  namespace
  {
    /** @p program as an executable path: itself if it holds a '/', else the
     * first match in PATH ("" if none). No shell and no /bin/sh fallback. */
    std::string
    executable(const std::string &program)
    {
      if (program.find('/') != std::string::npos)
        return ::access(program.c_str(), X_OK) == 0 ? program : "";
      const char *path = std::getenv("PATH");
      std::istringstream folders(path != nullptr ? path : "/usr/bin:/bin");
      for (std::string folder; std::getline(folders, folder, ':');)
        {
          const std::string candidate = (folder.empty() ? "." : folder) + "/" + program;
          if (::access(candidate.c_str(), X_OK) == 0)
            return candidate;
        }
      return "";
    }
  } // namespace



  int
  run_program(const std::vector<std::string> &argv, const std::string &log_file)
  {
    if (argv.empty())
      return -1;
    // Everything the child needs is prepared before fork(): after it only
    // async-signal-safe calls follow (the parent may hold MPI's locks).
    const std::string program = executable(argv[0]);
    if (program.empty())
      return not_found;
    std::vector<char *> args;
    for (const auto &a : argv)
      args.push_back(const_cast<char *>(a.c_str()));
    args.push_back(nullptr);
    // Opened here, close-on-exec: the child's stdin and its log.
    const int in  = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (in < 0 || log < 0)
      {
        for (const int fd : {in, log})
          if (fd >= 0)
            ::close(fd);
        return cannot_start;
      }
    const pid_t parent = ::getpid();

    const pid_t child = ::fork();
    if (child == 0)
      {
        // Dies with the parent; if the parent died before prctl, go now.
        if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent ||
            ::dup2(in, 0) < 0 || ::dup2(log, 1) < 0 || ::dup2(log, 2) < 0)
          ::_exit(127);
        // None of the parent's files (MPI's sockets, open results) reach the
        // program: everything above 2 closes on exec.
        ::close_range(3, ~0U, CLOSE_RANGE_CLOEXEC);
        ::execv(program.c_str(), args.data());
        ::_exit(127);
      }
    ::close(in);
    ::close(log);
    if (child < 0)
      return cannot_start;

    int status = 0;
    while (::waitpid(child, &status, 0) < 0)
      if (errno != EINTR)
        return cannot_start;
    return WIFEXITED(status) ? WEXITSTATUS(status) : killed;
  }



  std::string
  command_line(const std::vector<std::string> &argv)
  {
    std::string line;
    for (const auto &a : argv)
      {
        const bool quote = a.empty() || a.find_first_of(" \t\"'") != std::string::npos;
        line += (line.empty() ? "" : " ") + (quote ? "\"" + a + "\"" : a);
      }
    return line;
  }
} // namespace softopt
