#ifndef softopt_physics_material_h
#define softopt_physics_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <softopt/base/input.h>
#include <softopt/physics/hyperelastic_parts.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace softopt
{
  using namespace dealii;

  /**
   * A nearly incompressible hyperelastic material in the mixed form of
   * Sussman and Bathe (Eqs. c1, Wmod, p) with the pressure p~ inserted,
   *   W~(F, p~) = W_iso(F) - p~ (J - 1) - p~^2 / (2K),
   * so p~ is the pressure (positive in compression) and dW~/dp~ = 0 is the
   * weak pressure equation of Eq. deltaW01. A material model supplies the
   * isochoric part W_iso (a function of C^ = J^{-2/3} C), its stress and
   * its tangent; the volumetric part and the condensation are the same for
   * every model. Units: MPa.
   *
   * To add a model: copy source/physics/materials/yeoh.cc, change the three
   * functions and the entries, and keep its registration line. The test
   * material_derivatives checks every registered model against finite
   * differences and Hooke's law at small strain.
   */
  class Material
  {
  public:
    /** G_0 in MPa is the shear modulus at small strain (the model's
     * d^2 W_iso at F = I), nu in (-1, 0.5) sets the bulk modulus. */
    Material(const double initial_shear_modulus, const double poissons_ratio);

    virtual ~Material() = default;

    /** G_0: the shear modulus at small strain, MPa. */
    const double shear_modulus;

    /** K = 2 G_0 (1 + nu) / (3 (1 - 2 nu)), MPa. */
    const double bulk_modulus;

    /** W_iso(F), MPa. */
    virtual double
    isochoric_energy(const Tensor<2, 3> &F) const = 0;

    /** dW_iso/dF, MPa. */
    virtual Tensor<2, 3>
    isochoric_stress(const Tensor<2, 3> &F) const = 0;

    /** d^2 W_iso/dF^2, A[i][J][k][L] = dP_iJ / dF_kL, MPa. */
    virtual Tensor<4, 3>
    isochoric_tangent(const Tensor<2, 3> &F) const = 0;

    /** W~(F, p~) in MPa (energy per unit reference volume). */
    double
    energy(const Tensor<2, 3> &F, const double p) const;

    /** P = dW~/dF = dW_iso/dF - p~ J F^{-T}, MPa. */
    Tensor<2, 3>
    first_piola(const Tensor<2, 3> &F, const double p) const;

    /** A = dP/dF (material and geometric stiffness together, the
     * B^T D B + G^T Y G of Eq. LinMat). */
    Tensor<4, 3>
    tangent(const Tensor<2, 3> &F, const double p) const;

    /** dP/dp~ = -J F^{-T}: the coupling K_up of Eq. LinMat. */
    Tensor<2, 3>
    pressure_coupling(const Tensor<2, 3> &F) const;

    /** The Cauchy stress sigma = P F^T / J in MPa. */
    Tensor<2, 3>
    cauchy_stress(const Tensor<2, 3> &F, const double p) const;
  };

  namespace Materials
  {
    /** How a material model is named, documented, declared and made. */
    struct Registration
    {
      std::string name;
      std::string description;
      /** Declares the model's own entries in subsection Material. */
      std::function<void(ParameterHandler &)> declare_parameters;
      /** Makes the model from the entries of subsection Material, with
       * nu read already. */
      std::function<std::shared_ptr<const Material>(ParameterHandler &,
                                                    const InputFile &,
                                                    double poissons_ratio)>
        create;
    };

    /** Adds a model to the registry (called by the registration macro). */
    bool
    register_material(const Registration &registration);

    /** Declares subsection Material: "Model", "Poisson's ratio" and every
     * registered model's entries. */
    void
    declare_parameters(ParameterHandler &prm);

    /** Makes the model subsection Material names (throws a message naming
     * the file and entry on bad input). */
    std::shared_ptr<const Material>
    create(ParameterHandler &prm, const InputFile &input);

    /** The same from entries given here (tests, scripts): entries not given
     * keep their defaults, e.g. create("Yeoh", {{"Yeoh coefficients",
     * "0.2, 0.01, 0"}}). */
    std::shared_ptr<const Material>
    create(const std::string                        &model,
           const std::map<std::string, std::string> &entries = {});
  } // namespace Materials
} // namespace softopt

/** Registers a material class under @p name (one line per model, inside
 * namespace softopt). The class has a static declare_parameters(prm) and a
 * constructor (prm, input, poissons_ratio). */
#define SOFTOPT_REGISTER_MATERIAL(classname, name, description)           \
  namespace                                                              \
  {                                                                      \
    const bool classname##_registered =                                  \
      softopt::Materials::register_material(                             \
        {name,                                                           \
         description,                                                    \
         &classname::declare_parameters,                                 \
         [](dealii::ParameterHandler &prm,                               \
            const softopt::InputFile &input,                             \
            const double              poissons_ratio)                    \
           -> std::shared_ptr<const softopt::Material> {                 \
           return std::make_shared<classname>(prm, input, poissons_ratio); \
         }});                                                            \
  }

#endif
