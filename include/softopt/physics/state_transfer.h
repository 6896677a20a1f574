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
     * node of the new mesh lies outside the old body: then nothing is
     * transferred). */
    std::map<double, HyperelasticProblem::Vector> states;
    /** New nodes that no old cell holds within the tolerance. */
    unsigned long n_not_found = 0;
  };

  /**
   * The equilibrium states of a design on its old mesh, carried to a new
   * mesh of the same body (a remesh, a finer mesh of the schedule): the
   * displacement u of each state is evaluated at the nodes of the new mesh
   * (VectorTools::point_values through the old mapping, the design
   * configuration X that both meshes share), and the element pressure p~
   * at the centroid of each new cell. The result is a start for Newton on
   * the new mesh, not an equilibrium there.
   *
   * New nodes may lie a little outside the old body where the new boundary
   * is a chord of the old curved one: points within 5 % of a cell in
   * reference coordinates take the value extrapolated from the nearest
   * cell. Collective on both problems' communicator.
   */
  StateTransfer
  transfer_states(const HyperelasticProblem                           &old_problem,
                  const std::map<double, HyperelasticProblem::Vector> &old_states,
                  const HyperelasticProblem                           &new_problem,
                  const Mapping<3>                                    &new_mapping);
} // namespace softopt

#endif
