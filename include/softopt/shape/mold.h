#ifndef softopt_shape_mold_h
#define softopt_shape_mold_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <set>
#include <string>
#include <vector>

namespace softopt
{
  using namespace dealii;

  /** The dimensions of a two-part mold with cores (subsection "Mold"). */
  struct MoldDimensions
  {
    /** Normal of the plane that splits the outer mold; the plane contains
     * the actuator's axis (the normal of the clamped base through its
     * centroid). */
    Tensor<1, 3> split_normal;
    /** Mold material around the body on every side, mm. */
    double wall = 5;
    /** Radius of the four spherical registration keys on the split plane. */
    double key_radius = 1.5;
    /** Diameters of the pour opening and of the vent, mm. */
    double pour_diameter = 4;
    double vent_diameter = 1.5;
    /** Diameter of a core's stem, and how far it reaches beyond the mold. */
    double stem_diameter = 4;
    double stem_length   = 10;
    /** An overhang of the part smaller than this (mm, from a half's face)
     * is not an undercut. */
    double undercut_tolerance = 0.1;
  };

  /** A closed triangulated part of the mold. */
  struct MoldPart
  {
    std::string name;
    /** 9 numbers a triangle (its corners), outward. */
    std::vector<double> corners;
    /** Its volume, and the volume of its part inside the mold's box, mm^3. */
    double volume        = 0;
    double volume_in_box = 0;
    bool   closed        = false;
    /** Every edge in two faces and every vertex in one fan of faces, also
     * once the corners are rounded to the floats of an STL file. */
    bool manifold = false;
  };

  /** Faces of a mold half that cannot release along its pull direction. */
  struct Undercut
  {
    std::string  half;
    Tensor<1, 3> pull;
    /** Area of those faces (mm^2) and of the half's molding faces (those on
     * the cast part or a core). */
    double area         = 0;
    double molding_area = 0;
    /** Centroid of the largest such face. */
    Point<3> where;
  };

  /** The parts of a mold for a design, what they fill and what they hold. */
  struct Mold
  {
    /** "cast" (the elastomer: the part with its inlet and the sprues of
     * the pour opening and vent), "core_1", ..., "half_a", "half_b". */
    std::vector<MoldPart> parts;
    /** The box the two halves make together, its volume, mm^3. */
    double box_volume = 0;
    /** The actuator's axis, outward through the clamped base, which is up
     * when casting (pour opening, vent and core stems are there). */
    Tensor<1, 3> axis;
    /** The split plane's normal (unit, perpendicular to the axis): half_b
     * is pulled off along it, half_a against it. */
    Tensor<1, 3>          split_normal;
    std::vector<Undercut> undercuts;
  };

  /**
   * The mold of a design (issue 22): the outer mold as two halves split by
   * a plane through the axis, a wall of dims.wall around the body, four
   * spherical registration keys (on half_a, seats in half_b), a pour
   * opening and a vent on the split plane through the top (the clamped
   * base is cast upwards); each closed cavity a core with a stem along the
   * axis through the base and out of the mold. With exact constructions
   * (CGAL's corefinement on Epeck), so the parts fill the box: cast +
   * cores + halves = box volume to round-off. @p corners, @p boundary_ids:
   * the design's surface triangles (9 numbers each, outward, shared corners
   * equal to the last bit) and their boundary ids. Throws ExcMessage naming
   * the dimension that does not fit.
   */
  Mold
  make_mold(const std::vector<double>                 &corners,
            const std::vector<types::boundary_id>     &boundary_ids,
            const std::set<types::boundary_id>        &clamped_ids,
            const std::set<types::boundary_id>        &cavity_ids,
            const MoldDimensions                      &dims);
} // namespace softopt

#endif
