#ifndef softopt_app_settings_h
#define softopt_app_settings_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/geometry/geometry.h>
#include <softopt/path/newton_solver.h>
#include <softopt/path/path_following.h>
#include <softopt/physics/material_parameters.h>

#include <memory>
#include <string>

namespace softopt
{
  /**
   * Every entry of a parameter file, one subsection per class, plus the
   * top-level entries. The classes declare and parse their own entries;
   * this only gathers them.
   */
  struct Settings
  {
    /** Declares every entry (for @p input's numbered subsections too). */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and checks @p file; throws a message naming the file, entry
     * and what is wrong. */
    explicit Settings(const std::string &file);

    std::unique_ptr<InputFile> input;
    ParameterHandler           prm;

    /** Top level. */
    std::string output_directory;
    std::string command;
    bool        print_timings = true;

    /** subsection Output */
    enum class VtuOutput
    {
      every_step,
      targets,
      none
    } vtu_output = VtuOutput::every_step;

    Geometry           geometry;
    MaterialParameters material;
    PathFollowing      loading;
    NewtonSolver       newton;
  };
} // namespace softopt

#endif
