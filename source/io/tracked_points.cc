#include <softopt/io/csv_writer.h>
#include <softopt/io/tracked_points.h>

#include <algorithm>

namespace softopt
{
  namespace
  {
    /** A length in mm to the micrometre. */
    std::string
    format_mm(const double x)
    {
      return CsvWriter::fixed(x, 3);
    }

    std::string
    format_point(const Point<3> &p)
    {
      return "(" + format_mm(p[0]) + ", " + format_mm(p[1]) + ", " +
             format_mm(p[2]) + ")";
    }
  } // namespace



  bool
  TrackedPoints::TrackedNode::far() const
  {
    return node.distance > std::max(1.0, 0.5 * node.face_size);
  }



  TrackedPoints::TrackedPoints(const HyperelasticProblem     &problem,
                               const DesignConfiguration     &design,
                               const std::vector<NamedPoint> &requested)
  {
    std::vector<Point<3>> points;
    for (const auto &p : requested)
      points.push_back(p.position);
    const auto found = nearest_surface_nodes(problem, design, design.positions(), points);
    for (unsigned int k = 0; k < requested.size(); ++k)
      nodes.push_back({requested[k].name, requested[k].position, found[k]});
  }



  void
  TrackedPoints::print(const ConditionalOStream &out) const
  {
    std::string text;
    for (const auto &tracked : nodes)
      {
        const SurfaceNode &node = tracked.node;
        text += "Tracked point " + tracked.name + ": requested " +
                format_point(tracked.requested) + " mm, surface node " +
                format_point(node.position) + " mm at distance " +
                format_mm(node.distance) + " mm\n";
        if (tracked.far())
          text += "  Warning: farther than max(1 mm, half the longest edge of "
                  "its boundary face = " +
                  format_mm(0.5 * node.face_size) +
                  " mm): the point is probably not on the surface; check its "
                  "coordinates (mm, design configuration) in \"Tracked "
                  "points\".\n";
      }
    out << text << std::flush;
  }



  std::vector<std::string>
  TrackedPoints::csv_columns() const
  {
    std::vector<std::string> columns;
    for (const auto &tracked : nodes)
      for (const char *c :
           {"_X_mm", "_Y_mm", "_Z_mm", "_ux_mm", "_uy_mm", "_uz_mm"})
        columns.push_back(tracked.name + c);
    return columns;
  }



  std::vector<std::string>
  TrackedPoints::csv_entries(const HyperelasticProblem::Vector &a) const
  {
    std::vector<std::string> entries;
    for (const auto &tracked : nodes)
      {
        const Tensor<1, 3> u = nodal_value(a, tracked.node.displacement_dofs);
        for (unsigned int c = 0; c < 3; ++c)
          entries.push_back(CsvWriter::format(tracked.node.position[c]));
        for (unsigned int c = 0; c < 3; ++c)
          entries.push_back(CsvWriter::format(u[c]));
      }
    return entries;
  }
} // namespace softopt
