#ifndef softopt_base_input_h
#define softopt_base_input_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace softopt
{
  using namespace dealii;

  /**
   * The parameter file being read: its path (for messages and for resolving
   * relative paths) and the numbered subsections it contains.
   */
  class InputFile
  {
  public:
    /** Checks that @p path can be read; throws a message naming it if not. */
    explicit InputFile(const std::string &path);

    /** Entries that come from code rather than a file (tests, scripts):
     * messages name @p description instead of a file. */
    static InputFile
    in_code(const std::string &description);

    /** The path as given on the command line. */
    const std::string &path() const;

    /** @p relative resolved against the folder of the parameter file. */
    std::string resolve(const std::string &relative) const;

    /**
     * The numbers N of the subsections "@p prefix N" at the top level of the
     * file (for example "Objective 1", "Objective 2"), sorted. How many
     * objectives a case has follows from these, with no count entry.
     */
    std::vector<unsigned int>
    numbered_subsections(const std::string &prefix) const;

    /** "file, subsection "S", entry "E"" for error messages. */
    std::string
    where(const std::string &subsection, const std::string &entry) const;

  private:
    InputFile() = default;

    std::string file_path;
    std::string folder;
  };

  /** A comma-separated list of boundary ids ("2, 3"). Throws naming @p where. */
  std::vector<types::boundary_id>
  parse_boundary_ids(const std::string &text, const std::string &where);

  /**
   * The components fixed on each Dirichlet boundary, from the syntax
   * "id: components; id: components" with components from x, y, z:
   * "1: xyz" clamps boundary 1, "5: x" fixes only the x displacement
   * (a symmetry plane normal to x).
   */
  std::map<types::boundary_id, std::array<bool, 3>>
  parse_dirichlet_boundaries(const std::string &text, const std::string &where);

  /** A list of real numbers ("0.25, 1"). */
  std::vector<double>
  parse_doubles(const std::string &text, const std::string &where);

  /** Three comma-separated numbers ("1, 0, 0"). */
  Tensor<1, 3>
  parse_vector(const std::string &text, const std::string &where);

  /** The pattern of an entry holding three comma-separated numbers. */
  Patterns::List
  vector_pattern();

  /** A point with a name, in mm ("tip: 60, 0, 11.5"). */
  struct NamedPoint
  {
    std::string name;
    Point<3>    position;
  };

  /**
   * Named points from the syntax "name: x, y, z; name: x, y, z" (mm), for
   * example "tip: 60, 0, 11.5; side: 30, 0, 11.5". Names are letters, digits,
   * '_' and '-' (they become CSV column names) and must be distinct. An
   * empty text gives no points. Throws naming @p where.
   */
  std::vector<NamedPoint>
  parse_named_points(const std::string &text, const std::string &where);
} // namespace softopt

#endif
