// The load share of one tooth pair in a stiffness result, as the sweep comparisons read it.
#pragma once

#include "stiffness/mesh_stiffness.h"

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
} // namespace gearstiff::test_support
