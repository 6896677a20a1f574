#ifndef softopt_optimization_checkpoint_h
#define softopt_optimization_checkpoint_h

#include <deal.II/lac/petsc_vector.h>

#include <softopt/optimization/mma.h>
#include <softopt/optimization/secant_predictor.h>

#include <map>
#include <string>

namespace softopt
{
  using namespace dealii;

  /**
   * The whole state of the design loop at the top of an iteration, written
   * to and read from a directory "checkpoint" in the output directory: the
   * iteration number, the design d, the initial coordinates X_o (changed by
   * mesh updates), the shape field psi (the filter's Newton starts there)
   * MMA's previous iterates and asymptotes, and the equilibrium states at
   * the targets (the next design warm-starts from them) with the warm
   * start's secant (the last two accepted designs), one binary file per
   * rank; and the file of the mesh, if the design was remeshed.
   * A new checkpoint is written beside the old one and then renamed over
   * it, so a run killed while writing keeps the previous checkpoint. A
   * restart needs the same parameter file and number of MPI ranks.
   */
  namespace Checkpoint
  {
    using Vector = dealii::PETScWrappers::MPI::Vector;

    /** The checkpoint directory in @p output_directory. */
    std::string
    directory(const std::string &output_directory);

    void
    save(const std::string &output_directory,
         const unsigned int iteration,
         const Vector      &d,
         const Vector      &X_o,
         const Vector      &psi,
         const MMA         &mma,
         const std::map<double, Vector> &states,
         const SecantPredictor          &secant,
         const std::string              &mesh_file);

    /** The mesh file the checkpoint in @p output_directory was written on,
     * if the run remeshed the design ("" otherwise: the parameter file's
     * mesh); save() stores its name, the file being in the output
     * directory. A restart builds its mesh from it. */
    std::string
    mesh_file(const std::string &output_directory);

    /** For a restart: sets @p mesh_file_name (the parameter file's Mesh
     * file) to the checkpoint's mesh_file() if it names one. */
    void
    select_mesh(const std::string &output_directory, std::string &mesh_file_name);

    /** Reads the vectors (set up with the partition of this run; the
     * states like @p state_template) and MMA's state, and returns the
     * iteration to continue with. Throws a message
     * if there is no checkpoint or it does not fit this run. */
    unsigned int
    load(const std::string &output_directory,
         Vector            &d,
         Vector            &X_o,
         Vector            &psi,
         MMA               &mma,
         const Vector      &state_template,
         std::map<double, Vector> &states,
         SecantPredictor          &secant);
  } // namespace Checkpoint
} // namespace softopt

#endif
