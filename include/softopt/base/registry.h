#ifndef softopt_base_registry_h
#define softopt_base_registry_h

#include <deal.II/base/exceptions.h>

#include <map>
#include <string>

namespace softopt
{
  /**
   * The classes a parameter file can name (direction fields, material
   * models), each added by a registration line in its own source file.
   * @p Registration has at least the members name and description.
   */
  template <typename Registration>
  class Registry
  {
  public:
    /** Adds (or replaces) an entry; returns true for the static
     * initializer of the registration macro. */
    static bool
    add(const Registration &registration)
    {
      entries()[registration.name] = registration;
      return true;
    }

    /** Every entry, sorted by name. */
    static const std::map<std::string, Registration> &
    all()
    {
      return entries();
    }

    /** "a|b|c", for Patterns::Selection. */
    static std::string
    selection()
    {
      std::string names;
      for (const auto &[name, entry] : entries())
        names += (names.empty() ? "" : "|") + name;
      return names;
    }

    /** One line "  name: description" per entry, for an entry's doc. */
    static std::string
    documentation()
    {
      std::string docs;
      for (const auto &[name, entry] : entries())
        docs += "\n  " + name + ": " + entry.description;
      return docs;
    }

    /** The entry @p name; throws "@p where: unknown @p what "name"." */
    static const Registration &
    find(const std::string &name,
         const std::string &what,
         const std::string &where)
    {
      const auto it = entries().find(name);
      AssertThrow(it != entries().end(),
                  dealii::ExcMessage(where + ": unknown " + what + " \"" +
                                     name + "\"."));
      return it->second;
    }

  private:
    static std::map<std::string, Registration> &
    entries()
    {
      static std::map<std::string, Registration> registered;
      return registered;
    }
  };
} // namespace softopt

#endif
