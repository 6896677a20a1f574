#ifndef softopt_physics_material_parameters_h
#define softopt_physics_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>

namespace softopt
{
  /** The elastomer (subsection "Material"); the paper's PVS by default. */
  struct MaterialParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    /** E in MPa. */
    double youngs_modulus = 1.2;

    /** nu in (-1, 0.5). */
    double poissons_ratio = 0.49;
  };
} // namespace softopt

#endif
