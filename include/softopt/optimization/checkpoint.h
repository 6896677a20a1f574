#ifndef softopt_optimization_checkpoint_h
#define softopt_optimization_checkpoint_h

#include <deal.II/lac/petsc_vector.h>

#include <softopt/optimization/design_iterate.h>

#include <map>
#include <string>

namespace softopt
{
  using namespace dealii;

  /**
   * The design run's state at the top of an iteration, its DesignIterate
   * and the iteration number, written to and read from a directory
   * "checkpoint" in the output directory: one binary file per rank with the
   * iteration, the vectors (d, the accepted d, X_o, psi, the states at the
   * targets, the secant's history) and MMA's state, and the file of the
   * mesh, if the design was remeshed. A new checkpoint is written beside
   * the old one and then renamed over it, so a run killed while writing
   * keeps the previous checkpoint. A restart needs the same parameter file
   * and number of MPI ranks.
   */
  namespace Checkpoint
  {
    using Vector = dealii::PETScWrappers::MPI::Vector;

    /** The checkpoint directory in @p output_directory. */
    std::string
    directory(const std::string &output_directory);

    /** Writes @p x at the top of @p iteration. */
    void
    save(const std::string   &output_directory,
         const unsigned int   iteration,
         const DesignIterate &x);

    /** The mesh file the checkpoint in @p output_directory was written on,
     * if the run remeshed the design ("" otherwise: the parameter file's
     * mesh); save() stores its name, the file being in the output
     * directory. A restart builds its mesh from it. */
    std::string
    mesh_file(const std::string &output_directory);

    /** Reads the checkpoint into @p x, which must have the layout of the
     * checkpoint's mesh (DesignProblem::initial_iterate() on mesh_file(),
     * with an MMA), the states like @p state_template; returns the
     * iteration to continue with. Throws a message if there is no
     * checkpoint or it does not fit this run. */
    unsigned int
    load(const std::string &output_directory,
         const Vector      &state_template,
         DesignIterate     &x);
  } // namespace Checkpoint
} // namespace softopt

#endif
