#ifndef softopt_app_verification_parameters_h
#define softopt_app_verification_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>

#include <vector>

namespace softopt
{
  /** subsection "Verification": the finer meshes a final design is
   * analyzed on, to tell how far the optimization mesh can be trusted. */
  struct VerificationParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    /** Element sizes in mm (empty: no verification). */
    std::vector<double> mesh_sizes;

    /** The factors of the verification meshes on disk. */
    bool out_of_core = false;
  };
} // namespace softopt

#endif
