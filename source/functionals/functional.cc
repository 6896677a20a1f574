#include <deal.II/base/exceptions.h>

#include <softopt/functionals/design_surface.h>
#include <softopt/functionals/direction_field.h>
#include <softopt/functionals/functional.h>

namespace softopt
{
  Functional::Functional(const std::string &name,
                         const Kind         kind,
                         const double       load_factor)
    : name_(name)
    , kind_(kind)
    , load_factor_(load_factor)
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



  double
  Functional::load_factor() const
  {
    return load_factor_;
  }



  namespace
  {
    CellKernels::DirectionFunction
    as_function(const std::shared_ptr<DirectionField> &field)
    {
      return {[field](const Point<3> &X) { return field->value(X); },
              [field](const Point<3> &X) { return field->gradient(X); }};
    }

    /** (d_top area - top d_area) / area^2, the derivative of top / area. */
    void
    quotient_derivative(const double                      top,
                        const double                      area,
                        const PETScWrappers::MPI::Vector &d_top,
                        const PETScWrappers::MPI::Vector &d_area,
                        const double                      factor,
                        PETScWrappers::MPI::Vector       &result)
    {
      result = d_top;
      result *= factor / area;
      result.add(-factor * top / (area * area), d_area);
    }

    /**
     * A weighted mean over the design surface, minus an offset:
     *   objective  g = w / |dOmega^d| int u . v dS            (Eq. g0),
     *   constraint f = 1 / |dOmega^d| int (u . s)^2 dS - eps_u (Eq. constraint).
     */
    class SurfaceMean : public Functional
    {
    public:
      /** Which moment of u . v is averaged. */
      enum class Moment
      {
        linear,
        quadratic
      };

      SurfaceMean(const std::string                     &name,
                  const Kind                             kind,
                  const double                           load_factor,
                  const Moment                           moment,
                  const double                           weight,
                  const double                           offset,
                  const std::shared_ptr<DirectionField> &field)
        : Functional(name, kind, load_factor)
        , moment(moment)
        , weight(weight)
        , offset(offset)
        , direction(as_function(field))
      {}

      double
      evaluate(const HyperelasticProblem        &problem,
               const DesignConfiguration        &design,
               const PETScWrappers::MPI::Vector &a,
               PETScWrappers::MPI::Vector       *d_da,
               PETScWrappers::MPI::Vector       *d_dX) const override
      {
        const bool derivatives = d_da != nullptr;
        const auto s =
          integrate_over_design_surface(problem, design, a, direction, derivatives);
        const bool   linear = moment == Moment::linear;
        const double top    = linear ? s.linear : s.quadratic;
        if (derivatives)
          {
            *d_da = linear ? s.d_linear_da : s.d_quadratic_da;
            *d_da *= weight / s.area;
            quotient_derivative(top,
                                s.area,
                                linear ? s.d_linear_dX : s.d_quadratic_dX,
                                s.d_area_dX,
                                weight,
                                *d_dX);
          }
        return weight * top / s.area - offset;
      }

    private:
      const Moment                         moment;
      const double                         weight;
      const double                         offset;
      const CellKernels::DirectionFunction direction;
    };

    /** w V_c^p: the cavity volume at a target, times a weight. */
    class CavityVolume : public Functional
    {
    public:
      CavityVolume(const std::string &name, const double load_factor, const double weight)
        : Functional(name, Kind::objective, load_factor)
        , weight(weight)
      {}

      double
      evaluate(const HyperelasticProblem        &problem,
               const DesignConfiguration        &design,
               const PETScWrappers::MPI::Vector &a,
               PETScWrappers::MPI::Vector       *d_da,
               PETScWrappers::MPI::Vector       *d_dX) const override
      {
        const double V = cavity_volume(problem, design, a, d_da, d_dX);
        if (d_da != nullptr)
          {
            *d_da *= weight;
            *d_dX *= weight;
          }
        return weight * V;
      }

    private:
      const double weight;
    };

    void
    declare_objective(ParameterHandler &prm)
    {
      prm.declare_entry("Weight",
                        "-1",
                        Patterns::Double(),
                        "The weight w_i of Eq. g0 (dimensionless; negative "
                        "to maximize the displacement along the direction "
                        "field, as in the paper). Objectives are minimized "
                        "in min-max form: min max_i g_i.");
      prm.declare_entry("Quantity",
                        "displacement",
                        Patterns::Selection("displacement|cavity volume"),
                        "displacement: g = w / |dOmega^d| int u . v dS over "
                        "the design surface (Eq. g0, mm); cavity volume: "
                        "g = w V_c (mm^3).");
      prm.declare_entry("Load factor",
                        "1",
                        Patterns::Double(0),
                        "The target load factor lambda^i at which the "
                        "objective is evaluated (pressure = load factor x "
                        "Pressure).");
      DirectionFields::declare_parameters(prm, "constant");
    }

    void
    declare_constraint(ParameterHandler &prm)
    {
      prm.declare_entry("Load factor",
                        "1",
                        Patterns::Double(0),
                        "The target load factor lambda^j at which the "
                        "constraint is evaluated.");
      prm.declare_entry("Tolerance",
                        "1",
                        Patterns::Double(0),
                        "epsilon_u of Eq. constraint, in mm^2: the mean of "
                        "(u . s)^2 over the design surface must stay below "
                        "it.");
      DirectionFields::declare_parameters(prm, "constant");
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



    std::vector<std::unique_ptr<Functional>>
    create(ParameterHandler &prm, const InputFile &input)
    {
      std::vector<std::unique_ptr<Functional>> functionals;
      const auto load_factor_of = [&](const std::string &section) {
        const double load_factor = prm.get_double("Load factor");
        AssertThrow(load_factor > 0,
                    ExcMessage(input.where(section, "Load factor") +
                               ": must be positive."));
        return load_factor;
      };
      for (const unsigned int n : input.numbered_subsections("Objective"))
        {
          const std::string section = "Objective " + std::to_string(n);
          prm.enter_subsection(section);
          const double load_factor = load_factor_of(section);
          const double weight = prm.get_double("Weight");
          if (prm.get("Quantity") == "cavity volume")
            functionals.push_back(std::make_unique<CavityVolume>(
              "g_" + std::to_string(n), load_factor, weight));
          else
            functionals.push_back(std::make_unique<SurfaceMean>(
              "g_" + std::to_string(n),
              Functional::Kind::objective,
              load_factor,
              SurfaceMean::Moment::linear,
              weight,
              0.,
              DirectionFields::create(prm, input, section)));
          prm.leave_subsection();
        }
      for (const unsigned int n : input.numbered_subsections("Constraint"))
        {
          const std::string section = "Constraint " + std::to_string(n);
          prm.enter_subsection(section);
          const double load_factor = load_factor_of(section);
          functionals.push_back(std::make_unique<SurfaceMean>(
            "f_" + std::to_string(n),
            Functional::Kind::constraint,
            load_factor,
            SurfaceMean::Moment::quadratic,
            1.,
            prm.get_double("Tolerance"),
            DirectionFields::create(prm, input, section)));
          prm.leave_subsection();
        }
      return functionals;
    }



    std::unique_ptr<Functional>
    cavity_volume(const double load_factor)
    {
      return std::make_unique<CavityVolume>("V", load_factor, 1.);
    }
  } // namespace Functionals
} // namespace softopt
