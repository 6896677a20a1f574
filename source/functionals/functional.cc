#include <deal.II/base/exceptions.h>

#include <softopt/functionals/direction_field.h>
#include <softopt/functionals/functional.h>

#include <cmath>

namespace softopt
{
  Functional::Functional(const std::string              &name,
                         const Kind                      kind,
                         std::unique_ptr<const Quantity> quantity,
                         const double                    scale,
                         const double                    offset)
    : name_(name)
    , kind_(kind)
    , quantity(std::move(quantity))
    , scale(scale)
    , offset(offset)
  {}



  const std::string &
  Functional::name() const
  {
    return name_;
  }



  Functional::Kind
  Functional::kind() const
  {
    return kind_;
  }



  const std::vector<double> &
  Functional::load_factors() const
  {
    return quantity->load_factors();
  }



  bool
  Functional::along_load_path() const
  {
    return quantity->along_load_path();
  }



  double
  Functional::magnitude(const double value) const
  {
    return std::abs(value + offset);
  }



  double
  Functional::evaluate(const HyperelasticProblem &problem,
                       const DesignConfiguration &design,
                       const States              &states,
                       Derivatives               *derivatives) const
  {
    const double Q = quantity->value(problem, design, states, derivatives);
    if (derivatives != nullptr && scale != 1.)
      {
        for (auto &d : derivatives->d_da)
          d *= scale;
        derivatives->d_dX *= scale;
      }
    return scale * Q - offset;
  }



  double
  Functional::evaluate_at(const HyperelasticProblem &problem,
                          const DesignConfiguration &design,
                          const Vector              &a) const
  {
    return evaluate(problem, design, States(load_factors().size(), &a), nullptr);
  }



  namespace
  {
    /** The entries every Objective and Constraint subsection has: its
     * load factor, the quantity with the entries of every registered one,
     * and the direction field that several of them read. */
    void
    declare_common(ParameterHandler &prm, const std::string &default_quantity)
    {
      prm.declare_entry("Load factor",
                        "1",
                        Patterns::Double(0),
                        "The target load factor lambda at whose state the "
                        "quantity is evaluated (pressure = load factor x "
                        "Pressure).");
      Quantities::declare_parameters(prm, default_quantity);
      DirectionFields::declare_parameters(prm, "constant");
    }

    void
    declare_objective(ParameterHandler &prm)
    {
      prm.declare_entry("Weight",
                        "-1",
                        Patterns::Double(),
                        "The weight w_i of Eq. g0: g_i = w_i Q (dimensionless; "
                        "negative to maximize Q, e.g. the displacement along "
                        "the direction field, as in the paper). Objectives are "
                        "minimized in min-max form: min max_i g_i.");
      declare_common(prm, "displacement");
    }

    void
    declare_constraint(ParameterHandler &prm)
    {
      prm.declare_entry("Tolerance",
                        "1",
                        Patterns::Double(0),
                        "The bound of the constraint f_j = Q - Tolerance <= 0, "
                        "in the unit of Q: epsilon_u of Eq. constraint in mm^2 "
                        "for the squared displacement (its mean over the design "
                        "surface must stay below it). The optimizer sees f_j / "
                        "Tolerance, the violation relative to the bound, so a "
                        "bound of 1e-4 is held as firmly as one of 10 "
                        "(Tolerance 0: f_j as it is).");
      declare_common(prm, "squared displacement");
    }
  } // namespace



  namespace Functionals
  {
    void
    declare_parameters(ParameterHandler &prm, const InputFile *input)
    {
      const auto numbers = [&](const std::string &prefix) {
        return input != nullptr ? input->numbered_subsections(prefix) :
                                  std::vector<unsigned int>{1};
      };
      for (const unsigned int n : numbers("Objective"))
        {
          prm.enter_subsection("Objective " + std::to_string(n));
          declare_objective(prm);
          prm.leave_subsection();
        }
      for (const unsigned int n : numbers("Constraint"))
        {
          prm.enter_subsection("Constraint " + std::to_string(n));
          declare_constraint(prm);
          prm.leave_subsection();
        }
    }



    std::vector<std::unique_ptr<const Functional>>
    create(ParameterHandler &prm, const InputFile &input)
    {
      std::vector<std::unique_ptr<const Functional>> functionals;
      const auto quantity = [&](const std::string &section) {
        const double load_factor = prm.get_double("Load factor");
        AssertThrow(load_factor > 0,
                    ExcMessage(input.where(section, "Load factor") +
                               ": must be positive."));
        return Quantities::create(prm, input, section, load_factor);
      };
      for (const unsigned int n : input.numbered_subsections("Objective"))
        {
          const std::string section = "Objective " + std::to_string(n);
          prm.enter_subsection(section);
          functionals.push_back(std::make_unique<Functional>(
            "g_" + std::to_string(n),
            Functional::Kind::objective,
            quantity(section),
            prm.get_double("Weight"),
            0.));
          prm.leave_subsection();
        }
      for (const unsigned int n : input.numbered_subsections("Constraint"))
        {
          const std::string section = "Constraint " + std::to_string(n);
          prm.enter_subsection(section);
          functionals.push_back(std::make_unique<Functional>(
            "f_" + std::to_string(n),
            Functional::Kind::constraint,
            quantity(section),
            1.,
            prm.get_double("Tolerance")));
          prm.leave_subsection();
        }
      return functionals;
    }
  } // namespace Functionals
} // namespace softopt
