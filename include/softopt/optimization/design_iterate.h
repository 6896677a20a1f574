#ifndef softopt_optimization_design_iterate_h
#define softopt_optimization_design_iterate_h

#include <deal.II/lac/petsc_vector.h>

#include <softopt/optimization/mma.h>
#include <softopt/optimization/secant_predictor.h>

#include <map>
#include <optional>
#include <string>

namespace softopt
{
  /**
   * The state of a design run at the top of an iteration: everything needed
   * to continue it, and nothing that can be derived from it. A copy is a
   * snapshot (undo of a mesh update, a refused step); Checkpoint writes and
   * reads it whole. DesignProblem evaluates it; ShapeOptimizer moves it
   * along. The vectors live on the P2 vector DoFs of its mesh (d, psi, X_o)
   * or on the physics' DoFs (the states), in mm.
   */
  struct DesignIterate
  {
    using Vector = PETScWrappers::MPI::Vector;

    /** The mesh file the run is on: empty for the parameter file's Mesh
     * file, else a new mesh of the design ("Remesh below quality"). */
    std::string mesh_file;

    /** X_o, the initial design coordinates (the mesh, moved by every mesh
     * update of Section 5). */
    Vector X_o;

    /** The design variables to evaluate next (MMA's proposal). */
    Vector d;

    /** The design variables of the last accepted design (a refused d is
     * halved towards them). */
    Vector accepted;

    /** psi(accepted), the shape field of the last accepted design: X =
     * X_o + psi. */
    Vector psi;

    /** The equilibrium states of the last accepted design at the target
     * load factors (empty: the next evaluation follows the path from
     * zero). */
    std::map<double, Vector> states;

    /** The warm start's secant through the last two accepted designs. */
    SecantPredictor secant;

    /** MMA's previous iterates and asymptotes on d (none before the loop
     * starts and after a new mesh until the loop sets up a fresh one). */
    std::optional<MMA> mma;
  };
} // namespace softopt

#endif
