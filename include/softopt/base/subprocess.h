#ifndef softopt_base_subprocess_h
#define softopt_base_subprocess_h

#include <string>
#include <vector>

namespace softopt
{
  /**
   * Runs the program @p argv[0] (looked up in PATH if it has no '/') with
   * the arguments @p argv[1...], each passed to it as it is: no shell sees
   * them, so no quoting, globbing or command substitution can happen, and
   * a file name from a parameter file stays a file name. Its standard output
   * and error go to @p log_file (created or truncated), its standard input
   * is /dev/null, and it inherits no other file of the caller. The child
   * is killed when the calling process dies (kill -9 included), so no gmsh
   * outlives an interrupted run. Returns the exit status, or not_found,
   * cannot_start (no log, no process) or killed.
   */
  int
  run_program(const std::vector<std::string> &argv, const std::string &log_file);

  /** What run_program() returns when the program did not run to its end. */
  constexpr int not_found = -2, cannot_start = -1, killed = -3;

  /** @p argv as one line for a message, each argument in double quotes
   * where it holds a space or a quote (for reading, not for a shell). */
  std::string
  command_line(const std::vector<std::string> &argv);
} // namespace softopt

#endif
