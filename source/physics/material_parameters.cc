#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <softopt/physics/material_parameters.h>

namespace softopt
{
  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus",
                      "1.2",
                      Patterns::Double(),
                      "Young's modulus E of the elastomer in MPa (in the limit "
                      "of small strain); the paper's PVS has 1.2.");
    prm.declare_entry("Poisson's ratio",
                      "0.49",
                      Patterns::Double(),
                      "Poisson's ratio nu in (-1, 0.5): the bulk modulus is "
                      "K = E / (3 (1 - 2 nu)); 0.49 for PVS.");
    prm.leave_subsection();
  }



  void
  MaterialParameters::parse_parameters(ParameterHandler &prm,
                                       const InputFile  &input)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    AssertThrow(youngs_modulus > 0,
                ExcMessage(input.where("Material", "Young's modulus") +
                           ": must be positive (MPa), got " +
                           Utilities::to_string(youngs_modulus) + "."));
    AssertThrow(poissons_ratio > -1 && poissons_ratio < 0.5,
                ExcMessage(input.where("Material", "Poisson's ratio") +
                           ": must lie in (-1, 0.5), got " +
                           Utilities::to_string(poissons_ratio) +
                           " (0.5 itself is incompressible, which this mixed "
                           "formulation approaches but cannot reach)."));
  }
} // namespace softopt
