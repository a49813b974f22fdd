#include "fem/cell_shape.h"

#include <Eigen/Dense>
#include <cmath>

namespace gearstiff::fem
{
std::vector<unsigned int> cyclic_corner_order(unsigned int dim)
{
  if (dim == 2)
    return {0, 1, 3, 2};
  return {0, 1, 3, 2, 4, 5, 7, 6};
}

template <int dim>
bool corners_span_a_cell(const std::vector<Eigen::Vector3d>& x)
{
  // Neighbours of each corner, in the order that gives a positive Jacobian for a cell listed
  // counter-clockwise (bottom face counter-clockwise seen from the top in 3D).
  static const std::vector<std::vector<unsigned int>> quad = {{1, 3}, {2, 0}, {3, 1}, {0, 2}};
  static const std::vector<std::vector<unsigned int>> hex = {
      {1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  const auto& neighbours = dim == 2 ? quad : hex;
  int sign = 0;
  for (unsigned int i = 0; i < neighbours.size(); ++i)
  {
    const Eigen::Vector3d e1 = x[neighbours[i][0]] - x[i], e2 = x[neighbours[i][1]] - x[i];
    double jacobian = 0., lengths = e1.norm() * e2.norm();
    if constexpr (dim == 2)
      jacobian = e1.x() * e2.y() - e1.y() * e2.x();
    else
    {
      const Eigen::Vector3d e3 = x[neighbours[i][2]] - x[i];
      jacobian = e1.cross(e2).dot(e3);
      lengths *= e3.norm();
    }
    if (!(std::abs(jacobian) > 1e-8 * lengths))
      return false;
    const int s = jacobian > 0. ? 1 : -1;
    if (sign != 0 && s != sign)
      return false;
    sign = s;
  }
  return true;
}

template bool corners_span_a_cell<2>(const std::vector<Eigen::Vector3d>&);
template bool corners_span_a_cell<3>(const std::vector<Eigen::Vector3d>&);
} // namespace gearstiff::fem
