#ifndef softopt_app_settings_h
#define softopt_app_settings_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/functionals/functional.h>
#include <softopt/geometry/geometry.h>
#include <softopt/path/newton_solver.h>
#include <softopt/path/path_following.h>
#include <softopt/optimization/optimization_parameters.h>
#include <softopt/physics/material.h>
#include <softopt/shape/shape_filter.h>
#include <softopt/solvers/direct_solver.h>

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
    bool        print_timings = true;

    /** subsection Output */
    enum class VtuOutput
    {
      every_step,
      targets,
      none
    } vtu_output = VtuOutput::every_step;

    /** subsection Output: the surface points whose displacement history
     * goes to tracked_points.csv (none: no file). */
    std::vector<NamedPoint> tracked_points;

    Geometry           geometry;
    /** subsection Material: the registered model it names. */
    std::shared_ptr<const Material> material;
    PathFollowing      loading;
    NewtonSolver       newton;
    /** subsection Linear solver */
    DirectSolver::Parameters linear_solver;
    ShapeFilter        shape_filter;
    OptimizationParameters optimization;

    /** The objectives and constraints, in the order of the file. */
    std::vector<std::unique_ptr<Functional>> functionals;
  };
} // namespace softopt

#endif
