#include "geometry/tooth_profile.h"

#include <Eigen/Geometry>
#include <cmath>

namespace gearstiff::geometry
{
std::vector<ProfilePoint> full_outline(const ToothProfile& tooth)
{
  std::vector<ProfilePoint> outline;
  if (tooth.points.size() < 2)
    return outline;
  // The last point of one tooth is the first of the next: drop it to keep the ring closed
  // without a duplicate.
  const std::size_t per_tooth = tooth.points.size() - 1;
  const double tooth_length = tooth.points.back().arc_length - tooth.points.front().arc_length;
  outline.reserve(per_tooth * tooth.teeth);
  for (int k = 0; k < tooth.teeth; ++k)
  {
    const Eigen::Rotation2Dd rotation(k * tooth.angular_pitch);
    for (std::size_t i = 0; i < per_tooth; ++i)
    {
      ProfilePoint point = tooth.points[i];
      point.position = rotation * point.position;
      point.normal = rotation * point.normal;
      point.arc_length += k * tooth_length;
      outline.push_back(point);
    }
  }
  return outline;
}
double arc_length(const std::function<double(double)>& speed, double a, double b)
{
  static const double nodes[5] = {-0.9061798459386640, -0.5384693101056831, 0., 0.5384693101056831,
                                  0.9061798459386640};
  static const double weights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                    0.4786286704993665, 0.2369268850561891};
  const int pieces = 4;
  const double h = (b - a) / pieces;
  double length = 0.;
  for (int p = 0; p < pieces; ++p)
    for (int q = 0; q < 5; ++q)
      length += 0.5 * h * weights[q] * speed(a + (p + 0.5) * h + 0.5 * h * nodes[q]);
  return std::abs(length);
}

} // namespace gearstiff::geometry
