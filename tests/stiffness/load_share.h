// The load share of one tooth pair in a stiffness result, as the sweep comparisons read it.
#pragma once

#include "stiffness/mesh_stiffness.h"

#include <algorithm>
#include <cmath>

namespace gearstiff::test_support
{
// Share [-] of the pair with index `pair` (−1, 0, 1 …) in `r`; 0 when that pair carries nothing.
inline double share_of(const stiffness::GearMeshStiffnessResult& r, int pair)
{
  for (const auto& load : r.pairs)
    if (load.pair == pair)
      return load.load_share;
  return 0.;
}

// The largest difference [-] of a pair's share between two results of one position (pairs −2 … 2:
// every pair a sweep of ε_α < 4 loads).
inline double largest_share_difference(const stiffness::GearMeshStiffnessResult& a,
                                       const stiffness::GearMeshStiffnessResult& b)
{
  double largest = 0.;
  for (const int j : {-2, -1, 0, 1, 2})
    largest = std::max(largest, std::abs(share_of(b, j) - share_of(a, j)));
  return largest;
}
} // namespace gearstiff::test_support
