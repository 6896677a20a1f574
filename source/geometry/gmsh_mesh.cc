#include <deal.II/base/exceptions.h>

#include <softopt/geometry/gmsh_mesh.h>

#include <array>
#include <cstdlib>
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
  EdgeMidpoints::Less::operator()(const std::pair<Point<3>, Point<3>> &x,
                                  const std::pair<Point<3>, Point<3>> &y) const
  {
    for (unsigned int d = 0; d < 3; ++d)
      if (x.first[d] != y.first[d])
        return x.first[d] < y.first[d];
    for (unsigned int d = 0; d < 3; ++d)
      if (x.second[d] != y.second[d])
        return x.second[d] < y.second[d];
    return false;
  }



  std::pair<Point<3>, Point<3>>
  EdgeMidpoints::key(const Point<3> &a, const Point<3> &b)
  {
    const bool a_first =
      std::lexicographical_compare(&a[0], &a[0] + 3, &b[0], &b[0] + 3);
    return a_first ? std::make_pair(a, b) : std::make_pair(b, a);
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



  EdgeMidpoints
  split_quadratic_gmsh_mesh(const std::string &file,
                            const std::string &linear_file)
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

    std::unordered_map<long, Point<3>> nodes;
    struct Element
    {
      int               type;
      std::vector<long> tags;
      std::vector<long> nodes;
    };
    std::vector<Element> elements;
    // The node counts of the element types softopt accepts, and of those it
    // skips (points, lines); anything else is refused.
    const std::map<int, unsigned int> n_nodes = {
      {2, 3}, {4, 4}, {9, 6}, {11, 10}, {15, 1}, {1, 2}, {8, 3}};

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
              nodes[id] = p;
            }
        }
      else if (line == "$Elements")
        {
          long n;
          in >> n;
          for (long i = 0; i < n; ++i)
            {
              long    id;
              Element e;
              int     n_tags;
              in >> id >> e.type >> n_tags;
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
                in >> v;
              if (e.type == 2 || e.type == 4 || e.type == 9 || e.type == 11)
                elements.push_back(std::move(e));
            }
        }
    if (!in.eof())
      fail("could not be parsed.");

    // Corner nodes are renumbered from 1 in the linear mesh; midside nodes
    // are matched to the edge whose straight midpoint is nearest (robust
    // against the node ordering of the element type).
    std::map<long, long> corner_number;
    EdgeMidpoints        midpoints;
    unsigned int         n_tetrahedra = 0;
    for (const auto &e : elements)
      {
        const unsigned int n_corners = (e.type == 4 || e.type == 11) ? 4 : 3;
        n_tetrahedra += (n_corners == 4);
        for (unsigned int v = 0; v < n_corners; ++v)
          corner_number.emplace(e.nodes[v], 0);
        for (unsigned int m = n_corners; m < e.nodes.size(); ++m)
          {
            const Point<3> &x         = nodes.at(e.nodes[m]);
            double          best      = std::numeric_limits<double>::max();
            std::array<unsigned int, 2> edge{{0, 0}};
            for (unsigned int a = 0; a < n_corners; ++a)
              for (unsigned int b = a + 1; b < n_corners; ++b)
                {
                  const double d = x.distance(
                    (nodes.at(e.nodes[a]) + nodes.at(e.nodes[b])) / 2.);
                  if (d < best)
                    {
                      best = d;
                      edge = {{a, b}};
                    }
                }
            midpoints.add(nodes.at(e.nodes[edge[0]]),
                          nodes.at(e.nodes[edge[1]]),
                          x);
          }
      }
    if (n_tetrahedra == 0)
      fail("holds no tetrahedra (a gmsh file without a Physical Volume "
           "holds none).");

    std::ofstream out(linear_file);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
        << corner_number.size() << "\n"
        << std::setprecision(17);
    long number = 0;
    for (auto &[id, new_id] : corner_number)
      {
        new_id          = ++number;
        const auto &p   = nodes.at(id);
        out << new_id << " " << p[0] << " " << p[1] << " " << p[2] << "\n";
      }
    out << "$EndNodes\n$Elements\n" << elements.size() << "\n";
    number = 0;
    for (const auto &e : elements)
      {
        const bool tet = (e.type == 4 || e.type == 11);
        out << ++number << " " << (tet ? 4 : 2) << " " << e.tags.size();
        for (const auto t : e.tags)
          out << " " << t;
        for (unsigned int v = 0; v < (tet ? 4u : 3u); ++v)
          out << " " << corner_number.at(e.nodes[v]);
        out << "\n";
      }
    out << "$EndElements\n";
    AssertThrow(out.good(),
                ExcMessage("Cannot write the temporary mesh <" + linear_file +
                           ">."));
    return midpoints;
  }



  std::string
  run_gmsh(const std::string &arguments, const std::string &output)
  {
    const std::string  log = output + ".log";
    const std::string  command =
      "gmsh " + arguments + " -v 3 -o \"" + output + "\" > \"" + log + "\" 2>&1";
    const int          status = std::system(command.c_str());
    std::ifstream      log_in(log);
    std::ostringstream log_text;
    log_text << log_in.rdbuf();
    std::filesystem::remove(log);
    if (status == 0 && std::ifstream(output).good())
      return "";
    return "(command: " + command + "):\n" + log_text.str();
  }
} // namespace softopt
