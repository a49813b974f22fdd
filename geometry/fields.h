// The names the geometry library gives its own fields in an InputError: "<struct>.<member>" of
// the struct its caller filled (SceneMeshSettings and MeshOptions "mesh.contact_size",
// AbaqusDeckSpec "deck.thickness", CycloidDiscSpec "disc.roller_radius", ...). Library code
// names its fields, never the parameter paths users write ("Mesh/contact size"): app/ maps
// every field to its parameter (app/scenes/geometry_field_names.cc,
// app/cycloid/cycloid_field_names.cc), and tools/house_counts.py fails when geometry/ spells a
// user parameter path. The gear-pair scene's own fields are geometry::scene_field
// (geometry/scene_gear_pair.h); a gear's fields are kinematics::field::gear.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace gearstiff::geometry::field
{
// A member of the mesh settings (SceneMeshSettings, MeshOptions): "mesh.layers".
inline std::string mesh(const std::string& member)
{
  return "mesh." + member;
}
inline const std::vector<std::string>& mesh_fields()
{
  static const std::vector<std::string> members = {"dimension",    "face_width",   "layers",
                                                   "contact_size", "body_size",    "growth_rate",
                                                   "rim_size",     "memory_limit", "file"};
  return members;
}

// A member of AbaqusDeckSpec or of the deck's inputs (the output torque, the slice thickness).
inline std::string deck(const std::string& member)
{
  return "deck." + member;
}
inline const std::vector<std::string>& deck_fields()
{
  static const std::vector<std::string> members = {"surface_parts", "contact_pairs", "rigid_bodies",
                                                   "fixed_bores",   "output_torque", "thickness"};
  return members;
}

// A member of CycloidDiscSpec: "disc.eccentricity".
inline std::string disc(const std::string& member)
{
  return "disc." + member;
}
inline const std::vector<std::string>& disc_fields()
{
  static const std::vector<std::string> members = {"rollers", "roller_circle_radius",
                                                   "eccentricity", "roller_radius", "rotation"};
  return members;
}

// An input of the profile correction of a cycloid disc (corrected_cycloid_disc).
inline std::string correction(const std::string& member)
{
  return "correction." + member;
}
inline const std::vector<std::string>& correction_fields()
{
  static const std::vector<std::string> members = {"contact_arc_ratios", "clearance_limit"};
  return members;
}

// A member of CycloidSceneSpec: "cycloid_scene.output_pins".
inline std::string cycloid_scene(const std::string& member)
{
  return "cycloid_scene." + member;
}
inline const std::vector<std::string>& cycloid_scene_fields()
{
  static const std::vector<std::string> members = {"output_pins",
                                                   "output_pin_bodies",
                                                   "output_pin_radius",
                                                   "output_pin_bore_radius",
                                                   "output_pin_hole_radius",
                                                   "output_pin_circle_radius",
                                                   "pin_force",
                                                   "disc",
                                                   "bore_radius",
                                                   "roller_pin_radius",
                                                   "disc_width",
                                                   "roller_force",
                                                   "contact_clearance"};
  return members;
}

// A member of CylindersSceneSpec: "cylinders.radius_1".
inline std::string cylinders(const std::string& member)
{
  return "cylinders." + member;
}
inline const std::vector<std::string>& cylinders_fields()
{
  static const std::vector<std::string> members = {
      "radius_1", "radius_2",      "bore_radius_1", "bore_radius_2",
      "length",   "young_modulus", "poisson_ratio", "force_per_length"};
  return members;
}

// A member of InvoluteToothSpec, "tooth.tip_diameter": the generator knows one tooth, not
// which gear; the gear-pair scene renames its fields to the gear's (tooth_field_of_gear).
inline const std::string tooth_prefix = "tooth.";
inline std::string tooth(const std::string& member)
{
  return tooth_prefix + member;
}

// The gear a tooth modification or fault belongs to, as the prefix of its fields ("pinion",
// "wheel"): what ToothProfiles, check_modifications, check_faults and fault_fills take.
inline std::string modified_gear(bool wheel)
{
  return wheel ? "wheel" : "pinion";
}
// The field of a per-gear modification or fault entry, the gear's own field as
// kinematics::field::gear names it: gear_entry("wheel", "tip relief length") =
// "wheel.tip_relief_length". app/scenes maps every entry it declares for "Gear pair/Pinion" and
// "Gear pair/Wheel".
inline std::string gear_entry(const std::string& gear, std::string words)
{
  std::replace(words.begin(), words.end(), ' ', '_');
  return gear + "." + words;
}
} // namespace gearstiff::geometry::field
