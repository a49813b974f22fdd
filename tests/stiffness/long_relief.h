// The tip relief the micro-geometry tests use on external and internal pairs.
#pragma once

#include "geometry/tooth_modification.h"

namespace gearstiff::test_support
{
// Linear "long" tip relief of `amount` [m] (removed normal to the flank at the tip), its length
// `auto`: from the start of single-tooth contact.
inline geometry::ToothModification long_relief(double amount)
{
  geometry::ToothModification m;
  m.kind = geometry::ModificationKind::tip_relief;
  m.amount = amount;
  m.length = -1.;
  return m;
}
} // namespace gearstiff::test_support
