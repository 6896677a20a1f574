#ifndef softopt_optimization_problem_parameters_h
#define softopt_optimization_problem_parameters_h

#include <softopt/functionals/functional.h>
#include <softopt/geometry/geometry.h>
#include <softopt/optimization/optimization_parameters.h>
#include <softopt/path/loading.h>
#include <softopt/path/newton_solver.h>
#include <softopt/physics/material.h>
#include <softopt/shape/shape_filter.h>
#include <softopt/solvers/direct_solver.h>

#include <memory>
#include <vector>

namespace softopt
{
  /**
   * The entries that define a design problem, as plain values: the body and
   * its boundaries, the material, the load, the solvers' settings, the shape
   * filter, the design loop and the functionals. The problem classes
   * (DesignProblem, the analysis) read them and build their own solvers
   * from them; nothing changes them after parsing.
   */
  struct ProblemParameters
  {
    /** subsection Geometry */
    Geometry geometry;
    /** subsection Material: the registered model it names. */
    std::shared_ptr<const Material> material;
    /** subsection Loading */
    Loading loading;
    /** subsection Newton */
    NewtonSolver newton;
    /** subsection Linear solver */
    DirectSolver::Parameters linear_solver;
    /** subsection Shape filter */
    ShapeFilter::Parameters shape_filter;
    /** subsection Optimization */
    OptimizationParameters optimization;
    /** The objectives and constraints, in the order of the file. */
    std::vector<std::unique_ptr<const Functional>> functionals;
  };
} // namespace softopt

#endif
