#ifndef softopt_app_settings_h
#define softopt_app_settings_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/app/castability.h>
#include <softopt/app/mold.h>
#include <softopt/app/verification_parameters.h>
#include <softopt/base/input.h>
#include <softopt/io/output_parameters.h>
#include <softopt/optimization/problem_parameters.h>

#include <memory>
#include <string>

namespace softopt
{
  /**
   * Every entry of a parameter file: the problem's (ProblemParameters), what
   * a run writes (OutputParameters), where and which command, and the file
   * itself. The classes declare and parse their own entries; this only
   * gathers them.
   */
  struct Settings : ProblemParameters
  {
    /** Declares every entry; the numbered subsections ("Objective N") those
     * @p input contains, or one of each as an example without a file. */
    static void
    declare_parameters(ParameterHandler &prm, const InputFile *input = nullptr);

    /** Reads and checks @p file; throws a message naming the file, entry
     * and what is wrong. */
    explicit Settings(const std::string &file);

    std::unique_ptr<InputFile> input;
    ParameterHandler           prm;

    /** Top level. */
    std::string output_directory;
    std::string command;

    /** subsection Output and Print timings */
    OutputParameters output;

    /** subsection Verification */
    VerificationParameters verification;

    /** subsection Castability */
    CastabilityParameters castability;

    /** subsection Mold */
    MoldParameters mold;
  };
} // namespace softopt

#endif
