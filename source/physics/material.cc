#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <softopt/base/registry.h>
#include <softopt/physics/hyperelastic_parts.h>
#include <softopt/physics/material.h>

namespace softopt
{
  Material::Material(const double initial_shear_modulus,
                     const double poissons_ratio)
    : shear_modulus(initial_shear_modulus)
    , bulk_modulus(2. * initial_shear_modulus * (1. + poissons_ratio) /
                   (3. * (1. - 2. * poissons_ratio)))
  {}



  double
  Material::energy(const Tensor<2, 3> &F, const double p) const
  {
    return isochoric_energy(F) - p * (determinant(F) - 1.) -
           p * p / (2. * bulk_modulus);
  }



  Tensor<2, 3>
  Material::first_piola(const Tensor<2, 3> &F, const double p) const
  {
    return isochoric_stress(F) + HyperelasticParts::volumetric_stress(-p, F);
  }



  Tensor<4, 3>
  Material::tangent(const Tensor<2, 3> &F, const double p) const
  {
    return isochoric_tangent(F) +
           HyperelasticParts::volumetric_tangent(-p, 0., F);
  }



  Tensor<2, 3>
  Material::pressure_coupling(const Tensor<2, 3> &F) const
  {
    return -determinant(F) * transpose(invert(F));
  }



  Tensor<2, 3>
  Material::cauchy_stress(const Tensor<2, 3> &F, const double p) const
  {
    return first_piola(F, p) * transpose(F) / determinant(F);
  }



  namespace Materials
  {
    using Models = Registry<Registration>;



    bool
    register_material(const Registration &registration)
    {
      return Models::add(registration);
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      prm.declare_entry("Model",
                        "neo-Hookean",
                        Patterns::Selection(Models::selection()),
                        "The isochoric part W_iso of the strain energy; the "
                        "volumetric part and the condensed pressure are the "
                        "same for every model:" +
                          Models::documentation());
      prm.declare_entry("Poisson's ratio",
                        "0.49",
                        Patterns::Double(),
                        "Poisson's ratio nu in (-1, 0.5) at small strain, for "
                        "every model: the bulk modulus is K = 2 G_0 (1 + nu) / "
                        "(3 (1 - 2 nu)) with G_0 the model's shear modulus at "
                        "small strain (K = E / (3 (1 - 2 nu))); 0.49 for PVS.");
      for (const auto &[name, model] : Models::all())
        model.declare_parameters(prm);
      prm.leave_subsection();
    }



    std::shared_ptr<const Material>
    create(ParameterHandler &prm, const InputFile &input)
    {
      prm.enter_subsection("Material");
      const std::string name = prm.get("Model");
      const double      nu   = prm.get_double("Poisson's ratio");
      AssertThrow(nu > -1 && nu < 0.5,
                  ExcMessage(input.where("Material", "Poisson's ratio") +
                             ": must lie in (-1, 0.5), got " +
                             Utilities::to_string(nu) +
                             " (0.5 itself is incompressible, which this "
                             "mixed formulation approaches but cannot "
                             "reach)."));
      auto material = Models::find(name,
                                   "material model",
                                   input.where("Material", "Model"))
                        .create(prm, input, nu);
      prm.leave_subsection();
      return material;
    }



    std::shared_ptr<const Material>
    create(const std::string                        &model,
           const std::map<std::string, std::string> &entries)
    {
      ParameterHandler prm;
      declare_parameters(prm);
      prm.enter_subsection("Material");
      prm.set("Model", model);
      for (const auto &[entry, value] : entries)
        prm.set(entry, value);
      prm.leave_subsection();
      return create(prm, InputFile::in_code("material " + model));
    }
  } // namespace Materials
} // namespace softopt
