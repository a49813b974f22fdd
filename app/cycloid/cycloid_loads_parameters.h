// Parameter-file form of the cycloid load analysis (stiffness/cycloid_loads.h, cycloid_sweep.h)
// for `gearstiff cycloid-loads`: the ring ("Cycloid disc"), the disc's bore, output pins and
// width ("Cycloid scene", mm), the mesh ("Mesh"), the FE model ("Finite elements", "Linear
// solver", "Contact") and the load case, profiles, sweep and torque ramp ("Cycloid loads").
// Defaults: the drive of docs/references.md §4 (Chmurawa & Łokiec) with M_c = 440 N·m per disc,
// plane stress, frictionless, nominal and ε = 0.27 corrected profiles.
#pragma once

#include "stiffness/cycloid_loads.h"

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace gearstiff::app
{
struct CycloidLoadsParameters
{
  stiffness::CycloidLoadSettings settings; // nominal disc, SI, scene_file left empty
  bool nominal = true, corrected = true;   // profiles to solve
  double contact_arc_ratio = 0.27;         // -, ε of the corrected profile, in (0, 0.5)
  double clearance_limit = 0.01e-3;        // m, Δr of the correction
  unsigned int sweep_positions = 0;        // -, crank angles of the sweep (0: none)
  double sweep_span = 0.;                  // rad, span of the sweep
  bool torsional = true;                   // solve the torque levels of stiffness / lost motion
  unsigned int torque_steps = 0;           // -, extra steps of the ramp −M_c → +M_c
  bool write_vtu = false;
};

void declare_cycloid_loads_parameters(dealii::ParameterHandler& prm);
// InputError naming the parameter for values the patterns cannot reject.
CycloidLoadsParameters parse_cycloid_loads_parameters(dealii::ParameterHandler& prm);
} // namespace gearstiff::app
