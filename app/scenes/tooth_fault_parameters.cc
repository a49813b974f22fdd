#include "app/scenes/tooth_fault_parameters.h"

#include "app/core/parameter_patterns.h"
#include "app/core/parameter_table.h"
#include "app/core/units.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_fault.h"

#include <cmath>
#include <sstream>

namespace gearstiff::app
{
namespace
{
// Name, default and documentation of each entry: the names of issue 31; shapes and sources in
// geometry/tooth_fault.h (docs/references.md §13).
const std::vector<TextEntry> fault_entries = {
    {"faulty tooth", "0",
     "index of the faulty tooth: 0 = the tooth at the pitch point at pinion angle 0, counted "
     "counter-clockwise in the gear's own frame"},
    {"broken tooth", "false", "true: the faulty tooth is removed down to the root circle"},
    {"tip chipping", "0", "height removed at the faulty tooth's tip [mm]"},
    {"tip chipping width", "0",
     "extent of the chipping along the face from the end face z = 0 [mm]: a chipped corner "
     "(3D only); 0 = through the face"},
    {"spall length", "0", "length of the spall along the loaded flank (involute arc) [mm]"},
    {"spall depth", "0", "depth of the spall normal to the flank [mm]; 0 = no spall"},
    {"spall width", "0",
     "width of the spall across the face, centred on the face's middle [mm] (3D only); 0 = "
     "through the face"},
    {"spall position", "reference circle",
     "roll angle of the spall's centre on the loaded flank [deg], or 'reference circle'"},
    {"crack depth", "0", "depth of the root crack along its path [mm]; 0 = no crack"},
    {"crack angle", "45",
     "angle of the crack path to the tooth centre line [deg]; 90 = straight "
     "across the tooth"},
    {"crack start", "critical section",
     "where the crack starts on the loaded flank's fillet: 'critical section' (the 30° tangent "
     "point of ISO 6336-3) or the diameter of a fillet point [mm]"},
    {"crack faces", "contact",
     "'contact': a crack of no width whose faces may close (contact between them, with the "
     "Contact section's friction coefficient; 2D, a 3D model keeps the open slit); 'open': an "
     "open slit 0.04 mm wide"},
    {"crack tip size", "0.01",
     "cell size at the crack tip [mm] (faces in contact: 2x along "
     "the faces, the tip size within 10x of the tip)"},
    {"crack width fraction", "1",
     "share of the face width the crack runs through, from the end face z = 0; 1 = through the "
     "face (below 1: 3D only)"},
    {"crack front", "straight",
     "shape of a partial crack's front across the face: 'straight' (the depth constant over the "
     "crack width fraction) or 'parabolic' (deepest at z = 0, reaching the surface at the end "
     "of the crack width fraction; 3D only)"}};

std::string path_of(bool wheel, const std::string& name)
{
  return std::string("Gear pair/") + (wheel ? "Wheel/" : "Pinion/") + name;
}

// The value as a number; `whole`: an integer.
double value_of(const ModificationText& text, const std::string& name, bool wheel,
                bool whole = false)
{
  std::istringstream stream(text.at(name));
  double value = 0.;
  std::string rest;
  if (!(stream >> value) || (stream >> rest) || !std::isfinite(value) ||
      (whole && value != std::round(value)))
    throw InputError(path_of(wheel, name), "'" + shortened(text.at(name)) + "' is not " +
                                               (whole ? "a whole number" : "a number"));
  return value;
}

// A length in mm ≥ 0, in m.
double length_of(const ModificationText& text, const std::string& name, bool wheel)
{
  const double value = value_of(text, name, wheel);
  if (value < 0.)
    throw InputError(path_of(wheel, name), "must be 0 or positive [mm]");
  return value * mm;
}

bool flag_of(const ModificationText& text, const std::string& name, bool wheel)
{
  const std::string& value = text.at(name);
  if (value == "true" || value == "yes")
    return true;
  if (value == "false" || value == "no")
    return false;
  throw InputError(path_of(wheel, name), "'" + shortened(value) + "' is not true or false");
}

// A partial width (m) in 3D only.
double face_extent(const ModificationText& text, const std::string& name, bool wheel,
                   unsigned int dimension)
{
  const double width = length_of(text, name, wheel);
  if (width > 0. && dimension == 2)
    throw InputError(path_of(wheel, name),
                     "a 2D model has no face width: only 0 (through the face)");
  return width;
}

// `field` = read() unless entry `key` reads `keyword` (the default the field keeps); InputError
// `message` naming the entry unless the number read is positive.
template <typename Read>
void set_positive_unless(double& field, const ModificationText& text, bool wheel,
                         const std::string& key, const std::string& keyword, Read read,
                         const std::string& message)
{
  if (text.at(key) == keyword)
    return;
  field = read();
  if (!(field > 0.))
    throw InputError(path_of(wheel, key), message);
}

geometry::ToothModification spall_of(const ModificationText& text, bool wheel, double depth,
                                     unsigned int dimension)
{
  geometry::ToothModification spall;
  spall.kind = geometry::ModificationKind::spall;
  spall.amount = depth;
  spall.length = length_of(text, "spall length", wheel);
  spall.width = face_extent(text, "spall width", wheel, dimension);
  set_positive_unless(
      spall.position, text, wheel, "spall position", "reference circle",
      [&] { return value_of(text, "spall position", wheel) * degree; },
      "must be a positive roll angle [deg] or 'reference circle'");
  return spall;
}

geometry::ToothModification crack_of(const ModificationText& text, bool wheel, double depth,
                                     unsigned int dimension)
{
  geometry::ToothModification crack;
  crack.kind = geometry::ModificationKind::root_crack;
  crack.amount = depth;
  crack.angle = value_of(text, "crack angle", wheel) * degree;
  set_positive_unless(
      crack.position, text, wheel, "crack start", "critical section",
      [&] { return 0.5 * length_of(text, "crack start", wheel); },
      "must be 'critical section' or a positive diameter [mm]");
  crack.width_fraction = value_of(text, "crack width fraction", wheel);
  if (!(crack.width_fraction > 0. && crack.width_fraction <= 1.))
    throw InputError(path_of(wheel, "crack width fraction"),
                     "must lie in (0, 1]: the share of the face the crack runs through");
  if (crack.width_fraction != 1. && dimension == 2)
    throw InputError(path_of(wheel, "crack width fraction"),
                     "a 2D model has no face width: only 1 (through the face)");
  const std::string& faces = text.at("crack faces");
  if (faces != "contact" && faces != "open")
    throw InputError(path_of(wheel, "crack faces"),
                     "'" + shortened(faces) + "' is not one of contact, open");
  // A 3D model keeps the open slit (the split mesh is 2D only: docs/faults.md).
  crack.crack_contact = faces == "contact" && dimension == 2;
  crack.crack_tip_size = length_of(text, "crack tip size", wheel);
  // A tip cell below 1 µm is beyond the scene's smallest feature; above 0.1 mm it is coarser
  // than the crack-face cells of the default contact sizes.
  if (!(crack.crack_tip_size >= 1e-6 && crack.crack_tip_size <= 0.1e-3))
    throw InputError(path_of(wheel, "crack tip size"), "must lie between 0.001 and 0.1 mm");
  // A crack of a tip cell or less has no faces to mesh or to fit K on: 1e-9 mm failed in the
  // scene and 0.01 mm (one default tip cell) in the crack tip factors (exit 3); 1.5 tip cells
  // ran (measured 2026-12-01, Q1 and Q2).
  if (depth < 2. * crack.crack_tip_size)
    throw InputError(path_of(wheel, "crack depth"),
                     "'" + shortened(text.at("crack depth")) +
                         "' must be at least twice the crack tip size (" +
                         format_number(2. * crack.crack_tip_size / mm, 4) +
                         " mm): a shorter crack has no faces beyond its tip cell");
  const std::string& front = text.at("crack front");
  if (front != "straight" && front != "parabolic")
    throw InputError(path_of(wheel, "crack front"),
                     "'" + shortened(front) + "' is not one of straight, parabolic");
  crack.parabolic_front = front == "parabolic";
  if (crack.parabolic_front && dimension == 2)
    throw InputError(path_of(wheel, "crack front"),
                     "a 2D model has no face width: only straight (through the face)");
  return crack;
}
} // namespace

const std::vector<TextEntry>& tooth_fault_entries()
{
  return fault_entries;
}

void declare_tooth_fault_entries(ParameterHandler& prm)
{
  declare_text_entries(prm, fault_entries);
}

void read_tooth_fault_entries(ParameterHandler& prm, ModificationText& text)
{
  read_text_entries(prm, fault_entries, text);
}

void add_tooth_faults(const ModificationText& text, bool wheel, unsigned int dimension,
                      geometry::GearModifications& modifications)
{
  using geometry::ModificationKind;
  std::vector<geometry::ToothModification> faults;
  if (flag_of(text, "broken tooth", wheel))
    faults.push_back({ModificationKind::broken_tooth});
  if (const double height = length_of(text, "tip chipping", wheel); height > 0.)
  {
    geometry::ToothModification chip;
    chip.kind = ModificationKind::tip_chipping;
    chip.amount = height;
    chip.width = face_extent(text, "tip chipping width", wheel, dimension);
    faults.push_back(chip);
  }
  if (const double depth = length_of(text, "spall depth", wheel); depth > 0.)
    faults.push_back(spall_of(text, wheel, depth, dimension));
  if (const double depth = length_of(text, "crack depth", wheel); depth > 0.)
    faults.push_back(crack_of(text, wheel, depth, dimension));
  // Range-checked as a double, before the cast: 1e20 or 3e9 overflowed an int past the check.
  const double tooth = value_of(text, "faulty tooth", wheel, true);
  if (std::abs(tooth) > geometry::max_pair_index)
    throw InputError(path_of(wheel, "faulty tooth"),
                     "'" + shortened(text.at("faulty tooth")) + "' must lie between -" +
                         std::to_string(geometry::max_pair_index) + " and " +
                         std::to_string(geometry::max_pair_index));
  const int index = static_cast<int>(tooth);
  if (faults.empty())
    return; // no fault: every tooth stays nominal
  auto& list = modifications.by_tooth[index];
  list.insert(list.end(), faults.begin(), faults.end());
}

std::string first_fault_entry(const PairModificationText& text)
{
  for (const bool wheel : {false, true})
  {
    const ModificationText& gear = wheel ? text.wheel : text.pinion;
    if (gear.count("broken tooth") == 0)
      continue;
    if (gear.at("broken tooth") != "false")
      return path_of(wheel, "broken tooth");
    for (const char* name : {"tip chipping", "spall depth", "crack depth"})
    {
      std::istringstream stream(gear.at(name));
      double value = 0.;
      if (!(stream >> value) || value != 0.)
        return path_of(wheel, name);
    }
  }
  return "";
}
} // namespace gearstiff::app
