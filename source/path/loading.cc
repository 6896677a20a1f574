#include <deal.II/base/exceptions.h>

#include <softopt/path/loading.h>

namespace softopt
{
  void
  Loading::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("Pressure",
                      "15",
                      Patterns::Double(),
                      "The cavity pressure (relative to the atmosphere) at "
                      "load factor 1, in kPa.");
    prm.declare_entry("Target load factors",
                      "1",
                      Patterns::List(Patterns::Double(0), 1),
                      "Load factors at which the path must land exactly (the "
                      "last one ends the path); dimensionless, pressure = "
                      "load factor x Pressure.");
    prm.declare_entry("Maximum cavity volume ratio",
                      "0",
                      Patterns::Double(0),
                      "The path stops once the cavity volume exceeds this "
                      "multiple of its initial volume (0: no limit).");
    PathFollowing::Parameters::declare_parameters(prm);
    prm.leave_subsection();
  }



  void
  Loading::parse_parameters(ParameterHandler &prm, const InputFile &input)
  {
    prm.enter_subsection("Loading");
    pressure_kPa         = prm.get_double("Pressure");
    target_load_factors  = parse_doubles(prm.get("Target load factors"),
                                        input.where("Loading", "Target load factors"));
    maximum_volume_ratio = prm.get_double("Maximum cavity volume ratio");
    path.parse_parameters(prm, input);
    path.full_load_kPa = pressure_kPa;
    prm.leave_subsection();

    // No load, no response: every design would be the same.
    AssertThrow(pressure_kPa != 0,
                ExcMessage(input.where("Loading", "Pressure") +
                           ": the pressure must not be 0 (nothing would "
                           "deform; a negative pressure is a vacuum)."));
    for (const double t : target_load_factors)
      AssertThrow(t > 0,
                  ExcMessage(input.where("Loading", "Target load factors") +
                             ": every target load factor must be positive."));
    AssertThrow(maximum_volume_ratio == 0 || maximum_volume_ratio > 1,
                ExcMessage(input.where("Loading", "Maximum cavity volume ratio") +
                           ": must be 0 (no limit) or larger than 1."));
  }
} // namespace softopt
