// The per-gear text of the modification and fault entries of Gear pair/Pinion and Gear pair/Wheel,
// shared by app/scenes/tooth_modification_parameters.h and app/scenes/tooth_fault_parameters.h
// (apart from both, so that neither includes the other's header while the modification file
// calls the fault file).
#pragma once

#include <map>
#include <string>

namespace gearstiff::app
{
// The entries of one gear as written (name → text), so that a variant can override some.
using ModificationText = std::map<std::string, std::string>;
struct PairModificationText
{
  ModificationText pinion, wheel;
};
} // namespace gearstiff::app
