#include <deal.II/base/exceptions.h>

#include <softopt/base/registry.h>
#include <softopt/functionals/direction_field.h>

namespace softopt
{
  namespace DirectionFields
  {
    using Fields = Registry<Registration>;



    bool
    register_field(const Registration &registration)
    {
      return Fields::add(registration);
    }



    void
    declare_parameters(ParameterHandler &prm, const std::string &default_field)
    {
      prm.declare_entry("Direction field",
                        default_field,
                        Patterns::Selection(Fields::selection()),
                        "The direction field v(X) on the design surface:" +
                          Fields::documentation());
      for (const auto &[name, field] : Fields::all())
        field.declare_parameters(prm);
    }



    std::unique_ptr<DirectionField>
    create(ParameterHandler  &prm,
           const InputFile   &input,
           const std::string &subsection)
    {
      return Fields::find(prm.get("Direction field"),
                          "direction field",
                          input.where(subsection, "Direction field"))
        .create(prm, input, subsection);
    }



    std::unique_ptr<DirectionField>
    create_default(const std::string &name)
    {
      ParameterHandler prm;
      declare_parameters(prm, name);
      return create(prm, InputFile::in_code("the default " + name + " field"), "");
    }
  } // namespace DirectionFields
} // namespace softopt
