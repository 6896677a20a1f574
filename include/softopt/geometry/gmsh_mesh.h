#ifndef softopt_geometry_gmsh_mesh_h
#define softopt_geometry_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace softopt
{
  using namespace dealii;

  /** Exact lexicographic order of points (for maps keyed by nodes). */
  struct PointLess
  {
    bool
    operator()(const Point<3> &a, const Point<3> &b) const;
  };

  /**
   * The triangles and tetrahedra (linear or quadratic) of a gmsh mesh in
   * format 2.2, with its nodes by tag; points and lines are dropped.
   */
  struct GmshMesh
  {
    struct Element
    {
      /** gmsh's element number. */
      long              number = 0;
      /** gmsh's type: 2, 4 (linear triangle, tetrahedron), 9, 11
       * (quadratic). */
      int               type;
      /** Physical tag, elementary tag, ... */
      std::vector<long> tags;
      /** Corners first, then midside nodes. */
      std::vector<long> nodes;

      unsigned int
      n_corners() const;
    };

    std::map<long, Point<3>> nodes;
    std::vector<Element>     elements;
  };

  /** Reads @p file (gmsh's format 2.2, ASCII). Throws a message naming it
   * for another format or element types other than points, lines,
   * triangles and tetrahedra. */
  GmshMesh
  read_gmsh_mesh(const std::string &file);

  /** Throws a message naming @p file and the first of its inside-out or
   * degenerate (zero-volume) tetrahedra, if it has any. */
  void
  check_tetrahedra(const GmshMesh &mesh, const std::string &file);

  /** Writes @p mesh to @p file in gmsh's format 2.2 (ASCII, every digit). */
  void
  write_gmsh_mesh(const GmshMesh &mesh, const std::string &file);

  /**
   * The edge (local corner indices a < b) of an element with @p corners
   * whose straight midpoint is nearest to the midside node @p m: how a
   * midside node is matched to its edge whatever the element type's node
   * order.
   */
  std::pair<unsigned int, unsigned int>
  nearest_edge(const std::vector<Point<3>> &corners, const Point<3> &m);

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
                 const std::pair<Point<3>, Point<3>> &y) const
      {
        return PointLess()(x.first, y.first) ||
               (!PointLess()(y.first, x.first) && PointLess()(x.second, y.second));
      }
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
   * Runs gmsh with @p arguments (each one argument, no shell: see
   * run_program()), writing @p output (on the calling rank only). Returns
   * "" if gmsh succeeded and wrote @p output, else the command, gmsh's
   * log and how gmsh ended (killed by a signal, its exit status), for a
   * message.
   */
  std::string
  run_gmsh(std::vector<std::string> arguments, const std::string &output);

  /** The names a gmsh .geo file declares with DefineConstant[...], the
   * numbers gmsh's -setnumber can set. */
  std::set<std::string>
  geo_constants(const std::string &geo_file);
} // namespace softopt

#endif
