#include <deal.II/base/exceptions.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <softopt/base/subprocess.h>
#include <softopt/geometry/gmsh_mesh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <array>
#include <cstdlib>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace softopt
{
  bool
  PointLess::operator()(const Point<3> &a, const Point<3> &b) const
  {
    return std::lexicographical_compare(&a[0], &a[0] + 3, &b[0], &b[0] + 3);
  }



  std::pair<Point<3>, Point<3>>
  EdgeMidpoints::key(const Point<3> &a, const Point<3> &b)
  {
    return PointLess()(a, b) ? std::make_pair(a, b) : std::make_pair(b, a);
  }



  Point<3>
  EdgeMidpoints::operator()(const Point<3> &a, const Point<3> &b) const
  {
    const auto it = midpoints.find(key(a, b));
    return it != midpoints.end() ? it->second : Point<3>((a + b) / 2.);
  }



  void
  EdgeMidpoints::add(const Point<3> &a, const Point<3> &b, const Point<3> &m)
  {
    midpoints[key(a, b)] = m;
  }



  std::size_t
  EdgeMidpoints::size() const
  {
    return midpoints.size();
  }



  unsigned int
  GmshMesh::Element::n_corners() const
  {
    return (type == 4 || type == 11) ? 4 : 3;
  }



  GmshMesh
  read_gmsh_mesh(const std::string &file)
  {
    std::ifstream in(file);
    AssertThrow(in.good(), ExcMessage("Cannot read the mesh <" + file + ">."));
    const auto fail = [&](const std::string &what) {
      AssertThrow(false, ExcMessage("The mesh <" + file + "> " + what));
    };

    std::string line;
    std::getline(in, line);
    double version = 0;
    int    binary  = 1;
    in >> version >> binary;
    if (line != "$MeshFormat" || version < 2 || version >= 3 || binary != 0)
      fail("is not in gmsh's format 2.2 (ASCII).");

    // The node counts of the element types softopt accepts, and of those it
    // skips (points, lines); anything else is refused.
    const std::map<int, unsigned int> n_nodes = {
      {2, 3}, {4, 4}, {9, 6}, {11, 10}, {15, 1}, {1, 2}, {8, 3}};
    GmshMesh mesh;
    while (in >> line)
      if (line == "$Nodes")
        {
          long n;
          in >> n;
          for (long i = 0; i < n; ++i)
            {
              long     id;
              Point<3> p;
              in >> id >> p[0] >> p[1] >> p[2];
              mesh.nodes[id] = p;
            }
        }
      else if (line == "$Elements")
        {
          long n;
          in >> n;
          for (long i = 0; i < n; ++i)
            {
              GmshMesh::Element e;
              int               n_tags;
              in >> e.number >> e.type >> n_tags;
              e.tags.resize(n_tags);
              for (auto &t : e.tags)
                in >> t;
              const auto count = n_nodes.find(e.type);
              if (count == n_nodes.end())
                fail("holds elements of gmsh type " + std::to_string(e.type) +
                     "; softopt needs linear or quadratic tetrahedra with "
                     "triangular boundary faces.");
              e.nodes.resize(count->second);
              for (auto &v : e.nodes)
                {
                  in >> v;
                  if (in && mesh.nodes.count(v) == 0)
                    fail("has element " + std::to_string(e.number) +
                         " with node " + std::to_string(v) +
                         ", which is not among its $Nodes.");
                }
              if (e.type == 2 || e.type == 4 || e.type == 9 || e.type == 11)
                mesh.elements.push_back(std::move(e));
            }
        }
    if (!in.eof())
      fail("could not be parsed.");
    return mesh;
  }



  void
  write_gmsh_mesh(const GmshMesh &mesh, const std::string &file)
  {
    std::ofstream out(file);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
        << mesh.nodes.size() << "\n"
        << std::setprecision(17);
    for (const auto &[id, p] : mesh.nodes)
      out << id << " " << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << "$EndNodes\n$Elements\n" << mesh.elements.size() << "\n";
    long number = 0;
    for (const auto &e : mesh.elements)
      {
        out << ++number << " " << e.type << " " << e.tags.size();
        for (const auto t : e.tags)
          out << " " << t;
        for (const auto v : e.nodes)
          out << " " << v;
        out << "\n";
      }
    out << "$EndElements\n";
    AssertThrow(out.good(), ExcMessage("Cannot write the mesh <" + file + ">."));
  }



  void
  check_tetrahedra(const GmshMesh &mesh, const std::string &file)
  {
    // The corner volume (b - a) x (c - a) . (d - a) / 6 in gmsh's node order,
    // which deal.II keeps: positive for a valid tetrahedron. Degenerate:
    // below 1e-10 of the cube of its longest edge (a repeated node gives 0).
    unsigned int inverted = 0, degenerate = 0;
    std::string  first_inverted, first_degenerate;
    for (const auto &e : mesh.elements)
      {
        if (e.n_corners() != 4)
          continue;
        std::array<Point<3>, 4> x;
        for (unsigned int v = 0; v < 4; ++v)
          x[v] = mesh.nodes.at(e.nodes[v]);
        const double volume =
          scalar_product(cross_product_3d(x[1] - x[0], x[2] - x[0]), x[3] - x[0]) / 6;
        double longest = 0;
        for (unsigned int a = 0; a < 4; ++a)
          for (unsigned int b = a + 1; b < 4; ++b)
            longest = std::max(longest, x[a].distance(x[b]));
        const bool is_degenerate = std::abs(volume) <= 1e-10 * std::pow(longest, 3);
        if (!is_degenerate && volume > 0)
          continue;
        std::ostringstream where;
        where << "element " << e.number << " (nodes";
        for (unsigned int v = 0; v < 4; ++v)
          where << " " << e.nodes[v];
        where << ") at (" << (x[0] + x[1] + x[2] + x[3]) / 4 << "), volume "
              << volume;
        if (is_degenerate && degenerate++ == 0)
          first_degenerate = where.str();
        else if (!is_degenerate && inverted++ == 0)
          first_inverted = where.str();
      }
    const auto count = [](const unsigned int n) {
      return n == 1 ? std::string("1 tetrahedron is ") :
                      std::to_string(n) + " tetrahedra are ";
    };
    std::string message;
    if (inverted > 0)
      message += count(inverted) +
                 "inside out (negative volume), the first " +
                 first_inverted +
                 "; listing two corners of each the other way round (and "
                 "their midside nodes to match) would fix them. ";
    if (degenerate > 0)
      message += count(degenerate) +
                 "degenerate (no volume: a repeated node or "
                 "four corners in a plane), the first " +
                 first_degenerate + "; no reordering fixes these. ";
    AssertThrow(message.empty(),
                ExcMessage("The mesh <" + file + "> cannot be used: " +
                           Utilities::trim(message)));
  }



  std::pair<unsigned int, unsigned int>
  nearest_edge(const std::vector<Point<3>> &corners, const Point<3> &m)
  {
    double                                best = std::numeric_limits<double>::max();
    std::pair<unsigned int, unsigned int> edge{0, 0};
    for (unsigned int a = 0; a < corners.size(); ++a)
      for (unsigned int b = a + 1; b < corners.size(); ++b)
        if (const double d = m.distance((corners[a] + corners[b]) / 2.); d < best)
          {
            best = d;
            edge = {a, b};
          }
    return edge;
  }



  EdgeMidpoints
  split_quadratic_gmsh_mesh(const std::string &file,
                            const std::string &linear_file)
  {
    const GmshMesh mesh = read_gmsh_mesh(file);

    // The linear mesh: corner nodes, renumbered from 1; the midside nodes
    // are recorded by their edge.
    GmshMesh      linear;
    EdgeMidpoints midpoints;
    unsigned int  n_tetrahedra = 0;
    for (const auto &e : mesh.elements)
      {
        const unsigned int    n_corners = e.n_corners();
        std::vector<Point<3>> corners;
        for (unsigned int v = 0; v < n_corners; ++v)
          {
            corners.push_back(mesh.nodes.at(e.nodes[v]));
            linear.nodes.emplace(e.nodes[v], Point<3>());
          }
        for (unsigned int m = n_corners; m < e.nodes.size(); ++m)
          {
            const Point<3> &x = mesh.nodes.at(e.nodes[m]);
            const auto [a, b] = nearest_edge(corners, x);
            midpoints.add(corners[a], corners[b], x);
          }
        n_tetrahedra += (n_corners == 4);
      }
    AssertThrow(n_tetrahedra > 0,
                ExcMessage("The mesh <" + file +
                           "> holds no tetrahedra (a gmsh file without a "
                           "Physical Volume holds none)."));
    check_tetrahedra(mesh, file);

    std::map<long, long> number;
    {
      std::map<long, Point<3>> renumbered;
      for (const auto &[id, p] : linear.nodes)
        {
          const long n   = renumbered.size() + 1;
          number[id]     = n;
          renumbered[n]  = mesh.nodes.at(id);
        }
      linear.nodes = std::move(renumbered);
    }
    for (const auto &e : mesh.elements)
      {
        GmshMesh::Element corner_element{e.number, e.n_corners() == 4 ? 4 : 2, e.tags, {}};
        for (unsigned int v = 0; v < e.n_corners(); ++v)
          corner_element.nodes.push_back(number.at(e.nodes[v]));
        linear.elements.push_back(std::move(corner_element));
      }
    write_gmsh_mesh(linear, linear_file);
    return midpoints;
  }



  std::string
  run_gmsh(std::vector<std::string> arguments, const std::string &output)
  {
    const std::string log = output + ".log";
    arguments.insert(arguments.begin(), "gmsh");
    for (const std::string a : {"-v", "3", "-o"})
      arguments.push_back(a);
    arguments.push_back(output);
    const int          status = run_program(arguments, log);
    std::ifstream      log_in(log);
    std::ostringstream log_text;
    // Not "log_text << log_in.rdbuf()": an empty log sets log_text's
    // failbit, and every line below would then be lost.
    log_text << std::string(std::istreambuf_iterator<char>(log_in), {});
    std::filesystem::remove(log);
    if (status == 0 && std::ifstream(output).good())
      return "";
    // Say why gmsh stopped: its log is empty when it was killed or could
    // not start, and a bare "could not mesh" sends the user to the geometry.
    if (status == not_found)
      log_text << "gmsh is not in PATH (apt-get install gmsh)\n";
    else if (status == cannot_start)
      log_text << "gmsh could not be started, or its log <" << log
               << "> not written\n";
    else if (status == killed)
      log_text << "gmsh was killed by a signal before it finished (out of "
                  "memory? `dmesg` names the kernel's OOM kills; run the "
                  "meshing alone or with less beside it)\n";
    else if (status != 0)
      log_text << "gmsh exited with status " << status << "\n";
    else
      log_text << "gmsh exited with status 0 but wrote no <" << output
               << ">\n";
    return "(command: " + command_line(arguments) + "):\n" + log_text.str();
  }



  std::set<std::string>
  geo_constants(const std::string &geo_file)
  {
    std::ifstream in(geo_file);
    AssertThrow(in, ExcMessage("Cannot read <" + geo_file + ">."));
    std::string text((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
    // Without comments and strings, which may hold brackets and commas.
    std::string code;
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text.compare(i, 2, "//") == 0)
        i = std::min(text.find('\n', i), text.size()) - 1;
      else if (text.compare(i, 2, "/*") == 0)
        i = std::min(text.find("*/", i + 2), text.size() - 2) + 1;
      else if (text[i] == '"')
        {
          // Past the closing quote (a \" inside does not close).
          for (++i; i < text.size() && text[i] != '"'; ++i)
            if (text[i] == '\\')
              ++i;
        }
      else
        code += text[i];

    // DefineConstant[ name = value, name = {value, options}, ... ];
    std::set<std::string> names;
    const std::string     keyword = "DefineConstant";
    for (auto at = code.find(keyword); at != std::string::npos;
         at      = code.find(keyword, at + 1))
      {
        if (at > 0 && (std::isalnum(code[at - 1]) || code[at - 1] == '_'))
          continue; // part of another name
        std::size_t i = code.find('[', at + keyword.size());
        if (i == std::string::npos)
          break;
        int         depth = 0;
        std::string item;
        for (++i; i < code.size(); ++i)
          {
            const char c = code[i];
            if ((c == ',' || c == ']') && depth == 0)
              {
                const auto eq = item.find('=');
                if (eq != std::string::npos)
                  names.insert(Utilities::trim(item.substr(0, eq)));
                item.clear();
                if (c == ']')
                  break;
                continue;
              }
            depth += (c == '{' || c == '[' || c == '(') - (c == '}' || c == ')');
            if (c == ']')
              --depth;
            item += c;
          }
      }
    return names;
  }

} // namespace softopt
