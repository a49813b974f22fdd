// Parameter-file form of the tooth faults (geometry/tooth_fault.h, issue 31), in
// "Gear pair/Pinion" and "Gear pair/Wheel" beside the micro-geometry entries
// (app/scenes/tooth_modification_parameters.h), read into the same per-gear text so that
// `Stiffness/variants` can vary them ("crack depth = 0; crack depth = 1").
//
//   faulty tooth  index of the faulty tooth (0: the tooth at the pitch point at θ = 0, positive
//                 counter-clockwise in the gear's own frame; the scene's pair j meets pinion
//                 tooth j and wheel tooth −j)
//   broken tooth  true | false
//   tip chipping  height removed at the tip [mm] (through the face)
//   spall length, spall depth [mm], spall width [mm] (0 = through the face; nothing else is
//                 modelled), spall position (roll angle of its centre [deg] or "reference circle")
//   crack depth [mm], crack angle [deg to the tooth centre line], crack start ("critical section"
//                 = the 30° tangent point, or the diameter of a fillet point [mm]),
//                 crack width fraction (1 = through the face; nothing else is modelled)
// A size of 0 is no fault: the tooth stays the nominal outline, bit for bit.
#pragma once

#include "app/core/parameter_table.h"
#include "app/scenes/modification_text.h"
#include "geometry/tooth_modification.h"

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace gearstiff::app
{
// The entries of one gear (name, default, documentation).
const std::vector<TextEntry>& tooth_fault_entries();
// The entries, declared inside the current Gear pair/<gear> subsection.
void declare_tooth_fault_entries(dealii::ParameterHandler& prm);
// The entries' text, read inside the current Gear pair/<gear> subsection into `text`.
void read_tooth_fault_entries(dealii::ParameterHandler& prm, ModificationText& text);
// The faults of one gear appended to `modifications.by_tooth[faulty tooth]` (InputError naming
// "Gear pair/<gear>/<entry>" for a malformed or out-of-range value).
void add_tooth_faults(const ModificationText& text, bool wheel, unsigned int dimension,
                      geometry::GearModifications& modifications);
// The parameter path of the first fault entry that is set, "" when none.
std::string first_fault_entry(const PairModificationText& text);
} // namespace gearstiff::app
