#ifndef softopt_physics_state_transfer_h
#define softopt_physics_state_transfer_h

#include <softopt/physics/hyperelastic_problem.h>

#include <map>

namespace softopt
{
  /** What transfer_states() did. */
  struct StateTransfer
  {
    /** The states on the new mesh, at the same load factors (empty if a
     * point of the new mesh lies outside the old body: then nothing is
     * carried). */
    std::map<double, HyperelasticProblem::Vector> states;
    /** New points (nodes and cell centroids) that no old cell holds
     * within the tolerance. */
    unsigned long n_not_found = 0;
  };

  /**
   * The equilibrium states of a design on its old mesh, carried to a new
   * mesh of the same body (a remesh, a finer mesh of the schedule): the
   * displacement u of each state at the nodes of the new mesh and the
   * element pressure p~ at the centroid of each new cell, read through the
   * old mapping (the design configuration X that both meshes share). Every
   * rank searches its old cells for every rank's points; the rank whose
   * cell holds a point best evaluates it. The result is a start for Newton
   * on the new mesh, not an equilibrium there.
   *
   * New points may lie outside the old body where the new boundary is a
   * chord of the old curved one: up to 0.5 outside a cell in barycentric
   * coordinates they take the value extrapolated from it; farther out,
   * nothing is carried (n_not_found). Collective.
   */
  StateTransfer
  transfer_states(const HyperelasticProblem                           &old_problem,
                  const std::map<double, HyperelasticProblem::Vector> &old_states,
                  const HyperelasticProblem                           &new_problem,
                  const Mapping<3>                                    &new_mapping);
} // namespace softopt

#endif
