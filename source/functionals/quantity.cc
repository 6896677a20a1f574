#include <deal.II/base/exceptions.h>

#include <softopt/base/registry.h>
#include <softopt/functionals/quantity.h>

namespace softopt
{
  Quantity::Quantity(const std::vector<double> &load_factors)
    : load_factors_(load_factors)
  {
    Assert(!load_factors.empty(), ExcMessage("A quantity needs a load factor."));
  }



  const std::vector<double> &
  Quantity::load_factors() const
  {
    return load_factors_;
  }



  namespace Quantities
  {
    using Registered = Registry<Registration>;



    bool
    register_quantity(const Registration &registration)
    {
      return Registered::add(registration);
    }



    void
    declare_parameters(ParameterHandler &prm, const std::string &default_quantity)
    {
      prm.declare_entry("Quantity",
                        default_quantity,
                        Patterns::Selection(Registered::selection()),
                        "What is measured (Q below):" + Registered::documentation());
      for (const auto &[name, quantity] : Registered::all())
        quantity.declare_parameters(prm);
    }



    std::unique_ptr<Quantity>
    create(ParameterHandler  &prm,
           const InputFile   &input,
           const std::string &subsection,
           const double       load_factor)
    {
      return Registered::find(prm.get("Quantity"),
                              "quantity",
                              input.where(subsection, "Quantity"))
        .create(prm, input, subsection, load_factor);
    }
  } // namespace Quantities
} // namespace softopt
