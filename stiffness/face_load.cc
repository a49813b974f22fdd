#include "stiffness/face_load.h"

#include "contact/contact_problem.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace gearstiff::stiffness
{
namespace
{
// Nodes closer than this in z (m) lie on one plane (gmsh places the layers at k·b/L exactly,
// deal.II the Q2 middles at their mean: far below it).
constexpr double plane_tolerance = 1e-9;

long plane_key(double z)
{
  return std::lround(z / plane_tolerance);
}
} // namespace

void append_face_load(const contact::PairResult<3>& contact, int pair, double base_radius,
                      std::vector<FaceLoadPoint>& face_load)
{
  // (roll length, in-plane point, pressure) per plane.
  struct Node
  {
    double roll, x, y, pressure;
  };
  std::map<long, std::pair<double, std::vector<Node>>> planes;
  for (const auto& point : contact.points)
  {
    const double x = point.position[0], y = point.position[1], z = point.position[2];
    const double roll = std::sqrt(std::max(0., x * x + y * y - base_radius * base_radius));
    auto& plane = planes[plane_key(z)];
    plane.first = z;
    plane.second.push_back({roll, x, y, std::max(point.pressure, 0.)});
  }
  for (auto& [key, plane] : planes)
  {
    auto& nodes = plane.second;
    std::sort(nodes.begin(), nodes.end(),
              [](const Node& a, const Node& b) { return a.roll < b.roll; });
    double load = 0.;
    for (std::size_t i = 1; i < nodes.size(); ++i)
      load += 0.5 * (nodes[i - 1].pressure + nodes[i].pressure) *
              std::hypot(nodes[i].x - nodes[i - 1].x, nodes[i].y - nodes[i - 1].y);
    face_load.push_back({pair, plane.first, load});
  }
}

FaceLoadSummary summarise_face_load(const std::vector<FaceLoadPoint>& face_load)
{
  std::map<long, std::pair<double, double>> sum; // key -> (z, Σ w)
  for (const FaceLoadPoint& p : face_load)
  {
    auto& entry = sum[plane_key(p.z)];
    entry.first = p.z;
    entry.second += p.line_load;
  }
  FaceLoadSummary summary;
  for (const auto& [key, entry] : sum)
  {
    summary.z.push_back(entry.first);
    summary.line_load.push_back(entry.second);
  }
  if (summary.z.size() < 2)
    return summary;
  for (std::size_t i = 1; i < summary.z.size(); ++i)
    summary.force +=
        0.5 * (summary.line_load[i - 1] + summary.line_load[i]) * (summary.z[i] - summary.z[i - 1]);
  summary.mean = summary.force / (summary.z.back() - summary.z.front());
  const auto peak = std::max_element(summary.line_load.begin(), summary.line_load.end());
  summary.peak = *peak;
  summary.peak_z = summary.z[peak - summary.line_load.begin()];
  summary.factor = summary.mean > 0. ? summary.peak / summary.mean : 0.;
  return summary;
}
} // namespace gearstiff::stiffness
