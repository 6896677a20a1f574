#include <softopt/base/subprocess.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

namespace softopt
{
  int
  run_program(const std::vector<std::string> &argv, const std::string &log_file)
  {
    if (argv.empty())
      return -1;
    // Everything the child needs is prepared before fork(): after it only
    // async-signal-safe calls are allowed (the parent may hold MPI's locks).
    std::vector<char *> args;
    for (const auto &a : argv)
      args.push_back(const_cast<char *>(a.c_str()));
    args.push_back(nullptr);
    const pid_t parent = ::getpid();

    const pid_t child = ::fork();
    if (child < 0)
      return -1;
    if (child == 0)
      {
        // Dies with the parent; if the parent died before prctl, go now.
        if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent)
          ::_exit(127);
        const int in  = ::open("/dev/null", O_RDONLY);
        const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || log < 0 || ::dup2(in, 0) < 0 || ::dup2(log, 1) < 0 ||
            ::dup2(log, 2) < 0)
          ::_exit(127);
        ::execvp(args[0], args.data());
        ::_exit(127); // not found or not executable
      }

    int status = 0;
    while (::waitpid(child, &status, 0) < 0)
      if (errno != EINTR)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
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
