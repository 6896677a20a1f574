#ifndef softopt_geometry_gmsh_mesh_h
#define softopt_geometry_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <map>
#include <string>
#include <utility>

namespace softopt
{
  using namespace dealii;

  /**
   * The midside nodes of a quadratic gmsh mesh, keyed by the end points of
   * their edge (the smaller point, lexicographically, first). gmsh places
   * them on the CAD surfaces, so a P2 position field through them follows
   * curved boundaries; deal.II itself reads only the corner nodes.
   */
  class EdgeMidpoints
  {
  public:
    /** The midside node of the edge between @p a and @p b, or the straight
     * midpoint if the mesh had none there. */
    Point<3>
    operator()(const Point<3> &a, const Point<3> &b) const;

    /** Records the midside node @p m of the edge between @p a and @p b. */
    void
    add(const Point<3> &a, const Point<3> &b, const Point<3> &m);

    /** The number of edges with a recorded midside node. */
    std::size_t
    size() const;

  private:
    struct Less
    {
      bool
      operator()(const std::pair<Point<3>, Point<3>> &x,
                 const std::pair<Point<3>, Point<3>> &y) const;
    };
    static std::pair<Point<3>, Point<3>>
    key(const Point<3> &a, const Point<3> &b);

    std::map<std::pair<Point<3>, Point<3>>, Point<3>, Less> midpoints;
  };

  /**
   * Reads a gmsh file in format 2.2 (ASCII) with linear (4-node) or
   * quadratic (10-node) tetrahedra and 3- or 6-node boundary triangles, and
   * writes @p linear_file: the same mesh with corner nodes only, which
   * deal.II's GridIn reads. Returns the midside nodes. Throws a message
   * naming @p file for anything else.
   */
  EdgeMidpoints
  split_quadratic_gmsh_mesh(const std::string &file,
                            const std::string &linear_file);

  /**
   * Runs gmsh with @p arguments, writing @p output (on the calling rank
   * only). Returns "" if gmsh succeeded and wrote @p output, else the
   * command and gmsh's log, for a message.
   */
  std::string
  run_gmsh(const std::string &arguments, const std::string &output);
} // namespace softopt

#endif
