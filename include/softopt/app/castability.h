#ifndef softopt_app_castability_h
#define softopt_app_castability_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <softopt/base/input.h>
#include <softopt/io/output_directory.h>
#include <softopt/shape/design_configuration.h>

#include <string>

namespace softopt
{
  struct Settings;

  /** subsection "Castability": what a cast part needs of a design. */
  struct CastabilityParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const InputFile &input);

    /** Walls thinner than this (mm) get a warning. */
    double minimum_wall_thickness = 1;
    /** Gaps outside the part narrower than this (mm) get a warning. */
    double minimum_gap = 1;
    /** How far apart the points of the surface are measured (mm; 0: the
     * faces' nodes; surface_subdivisions()). */
    double sampling_size = 0;
  };

  /**
   * The castability checks of a design (issue 22): the minimum wall
   * thickness (wall_thickness(), a warning below "Minimum wall thickness",
   * and wall_thickness.vtu to look at in ParaView), the minimum gap
   * outside a whole part (a warning below "Minimum gap", gap.vtu) and the
   * self-intersections of its surface (refused if any). Writes
   * castability.csv (check,value,unit,x_mm,y_mm,z_mm,verdict) into @p out
   * and prints one line per check. Collective.
   */
  void
  check_castability(const Settings            &settings,
                    const DesignConfiguration &design,
                    const OutputDirectory     &out,
                    ConditionalOStream        &pcout);

  /** The final design of the case's output directory (its design.msh) if
   * there is one, else "" (the case's own mesh). Collective. */
  std::string
  final_design_mesh(const Settings &settings, const MPI_Comm comm);

  /**
   * "softopt check-design CASE.prm": the castability checks of the final
   * design of the case's output directory (its design.msh) if there is
   * one, else of the case's mesh. Returns the exit code (0: the checks
   * ran, whatever their verdicts).
   */
  int
  run_check_design(const Settings &settings, const MPI_Comm comm);
} // namespace softopt

#endif
