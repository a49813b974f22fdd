#include "geometry/tooth_profile.h"

#include <Eigen/Geometry>

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
} // namespace gearstiff::geometry
