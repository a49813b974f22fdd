// A mesh stiffness written by the FE commands, read as plain data: the summary that
// `gearstiff stiffness` (Stiffness/mode = sweep) and `gearstiff cai` write with -o
// (summary.json; the same object as their --json output). It names the pair it belongs to
// (values pinion_teeth, wheel_teeth — negative for an internal wheel —, transverse_module and
// centre_distance in mm, contact_ratio) and carries either the sweep's table stiffness_sweep
// (columns mesh_position [base pitches] and stiffness [N/um]), the whole-revolution table
// revolution_stiffness of `gearstiff faults` (columns mesh_position, stiffness, lost_contact,
// period: a table over P base pitches, P the faulty gear's tooth count, rows without contact at
// k = 0; docs/faults.md) or the calibrated Cai curve (cai_scale [N/µm], cai_c0..cai_c2). JSON
// through boost::property_tree (header-only): no stiffness module, no deal.II.
#pragma once

#include "dynamics/mesh_stiffness.h"
#include "dynamics/nonlinear_mesh.h"

#include <limits>
#include <optional>
#include <string>

namespace gearstiff::dynamics
{
struct StiffnessFilePair
{
  int pinion_teeth = 0;        // [-] the gear that drives in the FE load case
  int wheel_teeth = 0;         // [-] negative: internal
  double module = 0.;          // [m] transverse module
  double centre_distance = 0.; // [m] working centre distance
  double contact_ratio = 0.;   // [-] ε_α of the FE pair
  // [-] ε_f = AC/p_bt of the FE pair (start of contact to the pitch point, pinion driving);
  // NaN when the file predates it (the train then keeps the standard-tooth value).
  double approach_ratio = std::numeric_limits<double>::quiet_NaN();
  // [m] r_b1 of the FE pinion (values/pinion_base_radius); NaN when the file has none
  double pinion_base_radius = std::numeric_limits<double>::quiet_NaN();
  // [N·m] T1 the FE solved k(x) at (values/pinion_torque); NaN for a Cai summary or an older file
  double pinion_torque = std::numeric_limits<double>::quiet_NaN();
  std::string describe() const; // "z 20/10, m 2 mm, a 30 mm"
  // [N] the normal tooth force along the line of action of that load case, T1/r_b1; NaN when
  // the file states either. A modified pair's k(x) and TE hold at this force only.
  double tooth_force() const { return pinion_torque / pinion_base_radius; }
};

struct StiffnessFile
{
  std::string command; // "stiffness" or "cai"
  StiffnessFilePair pair;
  MeshStiffness stiffness; // k(x) with the pinion driving (x as in mesh_stiffness.h)
  // A sweep's column transmission_error [um] (the loaded static TE s(x) at the FE load) split
  // into k(x) and the unloaded TE e(x) (nonlinear_mesh.h); empty for a Cai summary.
  std::optional<LoadedTransmissionErrorSplit> transmission_error;
};

// Reads `path`; InputError naming `parameter` for a missing or unreadable file, a summary
// without the pair values or without a stiffness (neither table nor Cai values), and a table
// that does not cover one mesh cycle: positions taken modulo one base pitch (a revolution
// table: modulo its period), at least 3 distinct, and no gap between neighbours around the
// cycle wider than twice the mean spacing (a sweep over part of a base pitch leaves the
// wrap-around gap open); a revolution table also for a period that is not the same on every
// row or is neither gear's tooth count, and for a row flagged lost_contact with a stiffness.
StiffnessFile read_stiffness_file(const std::string& path, const std::string& parameter);

// Whether the file's pair is the mesh of gears a and b (signed teeth, transverse module [m],
// working centre distance [m]: kinematics::working_centre_distance, the reference m·|z_a + z_b|/2
// without profile shifts): returns 0 when gear a is the FE pinion, 1 when gear b is. InputError
// naming `parameter` with both descriptions otherwise (teeth, module or centre distance differ:
// a table of another pair, or of this pair with other profile shifts).
unsigned int match_stiffness_file(const StiffnessFile& file, int teeth_a, int teeth_b,
                                  double module, double centre_distance,
                                  const std::string& parameter);
} // namespace gearstiff::dynamics
