#include <deal.II/base/exceptions.h>

#include <softopt/functionals/direction_field.h>

#include <map>

namespace softopt
{
  namespace DirectionFields
  {
    namespace
    {
      std::map<std::string, Registration> &
      registry()
      {
        static std::map<std::string, Registration> fields;
        return fields;
      }
    } // namespace



    bool
    register_field(const Registration &registration)
    {
      registry()[registration.name] = registration;
      return true;
    }



    void
    declare_parameters(ParameterHandler &prm, const std::string &default_field)
    {
      std::string names, docs;
      for (const auto &[name, field] : registry())
        {
          names += (names.empty() ? "" : "|") + name;
          docs += "\n  " + name + ": " + field.description;
        }
      prm.declare_entry("Direction field",
                        default_field,
                        Patterns::Selection(names),
                        "The direction field v(X) on the design surface:" +
                          docs);
      for (const auto &[name, field] : registry())
        field.declare_parameters(prm);
    }



    std::unique_ptr<DirectionField>
    create(ParameterHandler  &prm,
           const InputFile   &input,
           const std::string &subsection)
    {
      const std::string name = prm.get("Direction field");
      const auto        it   = registry().find(name);
      AssertThrow(it != registry().end(),
                  ExcMessage(input.where(subsection, "Direction field") +
                             ": unknown direction field \"" + name + "\"."));
      return it->second.create(prm, input, subsection);
    }
  } // namespace DirectionFields
} // namespace softopt
