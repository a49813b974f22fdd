// The names the dynamics library gives its own fields in an InputError: "<struct>.<member>" of
// the inputs its caller filled — the train's (kinematics/fields.h: "train.<member>"), the
// simulation settings ("simulation.time_step"), the ISO 6336-1 method B inputs
// ("iso6336.face_width"), the speed sweep ("speed_sweep.points") and the two meshes of a
// lateral stage ("train_mesh1.stiffness": 1 the sun mesh, 2 the ring mesh), the gears and
// meshes of a torsional GearTrain ("gear2.inertia", "mesh1.damping"). Library code names
// its fields, never the parameter paths users write ("Simulation/time step"): app/dynamics maps
// every field to its parameter (dynamics_field_names.cc), and tools/house_counts.py fails when
// dynamics/ spells a user parameter path.
#pragma once

#include "kinematics/fields.h"

#include <string>
#include <vector>

namespace gearstiff::dynamics::field
{
using kinematics::field::train;
// The train members the dynamics names beyond kinematics::field::train_fields().
inline const std::vector<std::string>& train_fields()
{
  static const std::vector<std::string> members = {
      "masses",          "carrier_radii",     "base_diameters",       "bearing_stiffness",
      "bearing_damping", "suspended_members", "planet_pin_stiffness", "pressure_angle",
      "planet_angles",   "planet_pin_errors", "face_widths",          "bore_diameters"};
  return members;
}

inline std::string simulation(const std::string& member)
{
  return "simulation." + member;
}
inline const std::vector<std::string>& simulation_fields()
{
  static const std::vector<std::string> members = {
      "time_step",  "simulated_time",     "output_stride", "output_interval",
      "integrator", "relative_tolerance", "hht_alpha",     "steady_state_start"};
  return members;
}

inline std::string iso6336(const std::string& member)
{
  return "iso6336." + member;
}
inline const std::vector<std::string>& iso6336_fields()
{
  static const std::vector<std::string> members = {
      "pinion_teeth", "pinion_speed",     "mesh_stiffness",     "single_stiffness", "face_width",
      "reduced_mass", "tangential_force", "application_factor", "contact_ratio",    "deviations"};
  return members;
}

inline std::string speed_sweep(const std::string& member)
{
  return "speed_sweep." + member;
}
inline const std::vector<std::string>& speed_sweep_fields()
{
  static const std::vector<std::string> members = {"direction", "points"};
  return members;
}

// Mesh `mesh` (0: sun, 1: ring) of a lateral stage: "train_mesh1.damping".
constexpr unsigned int lateral_stage_meshes = 2;
inline std::string train_mesh(unsigned int mesh, const std::string& member)
{
  return "train_mesh" + std::to_string(mesh + 1) + "." + member;
}
inline const std::vector<std::string>& train_mesh_fields()
{
  static const std::vector<std::string> members = {"stiffness", "damping"};
  return members;
}

// Gear `gear` (from 0) of a GearTrain as TorsionalModel names it, "gear2.inertia" ("gear2"
// alone for the gear itself): the command that built the train maps it to the section the gear
// came from ("Gear 2/inertia", app/dynamics/dynamics_field_names.h).
inline std::string train_gear(unsigned int gear, const std::string& member = "")
{
  return "gear" + std::to_string(gear + 1) + (member.empty() ? "" : "." + member);
}
inline const std::vector<std::string>& train_gear_fields()
{
  static const std::vector<std::string> members = {"inertia", "torque", "suspension"};
  return members;
}

// Mesh `mesh` (from 0) of a GearTrain as TorsionalModel, check_nonlinear_mesh and simulate name
// it, "mesh1.contact_ratio"; mapped as train_gear ("Mesh 1/contact ratio").
inline std::string gear_mesh(unsigned int mesh, const std::string& member)
{
  return "mesh" + std::to_string(mesh + 1) + "." + member;
}
inline const std::vector<std::string>& gear_mesh_fields()
{
  static const std::vector<std::string> members = {"gears",
                                                   "driver_base_radius",
                                                   "driven_base_radius",
                                                   "driver_teeth",
                                                   "contact_ratio",
                                                   "approach_ratio",
                                                   "damping",
                                                   "friction_coefficient",
                                                   "friction_arms",
                                                   "stiffness",
                                                   "back_flank_stiffness",
                                                   "backlash",
                                                   "transmission_error",
                                                   "transmission_error_harmonics"};
  return members;
}
} // namespace gearstiff::dynamics::field
