#include "app/kinematics/kinematics_parameters.h"

#include "app/core/field_names.h"
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "errors/errors.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <string>

namespace gearstiff::app
{
namespace
{
// m, along the line of action: 2% of a 2.5 mm module, well above the bisection's 1e-12 m and
// below any contact size, so the ring tip ends just outside the planet's fillet.
constexpr double default_ring_tip_margin = 0.05e-3;

void declare_gear(dealii::ParameterHandler& prm, const kinematics::GearSpec& gear)
{
  prm.declare_entry("teeth", std::to_string(gear.teeth), Integer(1),
                    "number of teeth [-], positive also for an internal gear");
  prm.declare_entry("module", format_number(gear.normal_module / mm, 12), Double(0.),
                    "normal module m_n [mm]");
  prm.declare_entry("pressure angle", format_number(gear.pressure_angle / degree, 12),
                    Double(0., 45.), "normal pressure angle of the basic rack α_n [deg]");
  prm.declare_entry("helix angle", format_number(gear.helix_angle / degree, 12), Double(-60., 60.),
                    "helix angle β at the reference circle [deg], 0 for spur gears");
  prm.declare_entry("profile shift", format_number(gear.profile_shift, 12), Double(-5., 5.),
                    "profile shift coefficient x [-] (DIN 3960: > 0 thickens the tooth)");
  prm.declare_entry("face width", format_number(gear.face_width / mm, 12), Double(0.),
                    "face width b [mm]");
  prm.declare_entry("tip diameter", "auto", Anything(),
                    "tip diameter d_a [mm]; 0 = standard d ± 2·m_n·(h_aP* + x); auto = the "
                    "published tip for the teeth of the built-in case (docs/references.md §1: "
                    "ε_α = 1.500), else standard, and for an internal wheel the longest ring teeth "
                    "that clear the pinion's involute by 'Gear pair/ring tip margin'");
  prm.declare_entry("tip rounding radius", format_number(gear.tip_rounding_radius / mm, 12),
                    Double(0.),
                    "radius ρ_a of the tip edge's rounding [mm], in the transverse section (a "
                    "helical gear's too): a circular arc tangent to the flank and to the tip "
                    "circle, the flank ending at the tip form diameter d_Fa, which bounds the path "
                    "of contact; 0 = the sharp edge");
  prm.declare_entry("internal", gear.internal ? "true" : "false", Bool(),
                    "ring gear (teeth inside); only the wheel may be internal");
  prm.declare_entry("addendum coefficient", format_number(gear.addendum_coefficient, 12),
                    Double(0.), "basic rack addendum h_aP/m_n [-] (standard tip diameter only)");
  prm.declare_entry("dedendum coefficient", format_number(gear.dedendum_coefficient, 12),
                    Double(0.), "basic rack dedendum h_fP/m_n [-] (ISO 53 A: 1.25)");
  prm.declare_entry("root radius coefficient", format_number(gear.root_radius_coefficient, 12),
                    Double(0.),
                    "basic rack root radius ρ_fP/m_n [-] (ISO 53 A: 0.38; at most what keeps the "
                    "rack tooth's two tip rounds apart, 0.318 at a 25° pressure angle)");
  prm.declare_entry("bore diameter", "auto", Anything(),
                    "bore diameter of the gear body [mm] (FE models), for an internal wheel its "
                    "outer diameter; 0 = not given; auto = 20/40 mm for the teeth of the built-in "
                    "case (not published), else half the root diameter d_f/2, and for an internal "
                    "wheel d_f + 2·4·m_n (a rim of four modules)");
  prm.declare_entry("web thickness", format_number(gear.web_thickness / mm, 12), Double(0.),
                    "web thickness b_s [mm] for ISO C_R; 0 = solid blank");
  prm.declare_entry("rim thickness", format_number(gear.rim_thickness / mm, 12), Double(0.),
                    "rim thickness s_R under the root [mm] for ISO C_R (webbed blanks)");
}

// "auto" (returns true, `diameter` untouched), or a diameter >= 0 in mm, stored in SI
// (InputError naming the parameter otherwise).
bool parse_automatic_diameter(const std::string& text, bool wheel, const std::string& key,
                              double& diameter)
{
  return read_length_or_auto(text, gear_pair_parameter(wheel, key), "diameter", diameter);
}

// `automatic_tip`/`automatic_bore` are set when the diameter reads "auto" (resolved once both
// gears are known).
kinematics::GearSpec parse_gear(dealii::ParameterHandler& prm, bool wheel, bool& automatic_tip,
                                bool& automatic_bore)
{
  kinematics::GearSpec gear;
  gear.teeth = static_cast<unsigned int>(prm.get_integer("teeth"));
  gear.normal_module = prm.get_double("module") * mm;
  // DIN 780 / ISO 54 modules run from 0.05 mm to 60 mm: a module far outside is a unit slip
  // (0.003 for 3 mm in metres), blamed on the module rather than on what it makes too small.
  const double module_mm = gear.normal_module / mm;
  if (module_mm > 0. && module_mm < 0.05)
    throw InputError(gear_pair_parameter(wheel, "module"),
                     format_number(module_mm, 6) +
                         " mm is below every standard module (DIN 780: 0.05 to 60 mm); modules "
                         "are in mm (metres given? " +
                         format_number(module_mm * 1e3, 6) + " mm)");
  if (module_mm > 100.)
    throw InputError(gear_pair_parameter(wheel, "module"),
                     format_number(module_mm, 6) +
                         " mm is above every standard module (DIN 780: 0.05 to 60 mm); modules "
                         "are in mm (micrometres given? " +
                         format_number(module_mm * 1e-3, 6) + " mm)");
  gear.pressure_angle = prm.get_double("pressure angle") * degree;
  gear.helix_angle = prm.get_double("helix angle") * degree;
  gear.profile_shift = prm.get_double("profile shift");
  gear.face_width = prm.get_double("face width") * mm;
  automatic_tip =
      parse_automatic_diameter(prm.get("tip diameter"), wheel, "tip diameter", gear.tip_diameter);
  gear.tip_rounding_radius = prm.get_double("tip rounding radius") * mm;
  gear.internal = prm.get_bool("internal");
  gear.addendum_coefficient = prm.get_double("addendum coefficient");
  gear.dedendum_coefficient = prm.get_double("dedendum coefficient");
  gear.root_radius_coefficient = prm.get_double("root radius coefficient");
  automatic_bore = parse_automatic_diameter(prm.get("bore diameter"), wheel, "bore diameter",
                                            gear.bore_diameter);
  gear.web_thickness = prm.get_double("web thickness") * mm;
  gear.rim_thickness = prm.get_double("rim thickness") * mm;
  return gear;
}
} // namespace

void declare_gear_pair_parameters(dealii::ParameterHandler& prm)
{
  const kinematics::GearPairSpec pair = kinematics::split_path_pair();
  prm.enter_subsection("Gear pair");
  prm.declare_entry("centre distance", format_number(pair.centre_distance / mm, 12), Double(0.),
                    "working centre distance a_w [mm]; 0 = zero backlash from the profile shifts");
  prm.declare_entry("ring tip margin", format_number(default_ring_tip_margin / mm, 12), Double(0.),
                    "for Wheel/tip diameter = auto: distance along the line of action from the "
                    "pinion's form circle to the start of contact A [mm]");
  prm.enter_subsection("Pinion");
  declare_gear(prm, pair.pinion);
  prm.leave_subsection();
  prm.enter_subsection("Wheel");
  declare_gear(prm, pair.wheel);
  prm.leave_subsection();
  prm.leave_subsection();

  prm.enter_subsection("ISO 6336");
  prm.declare_entry("C_M", "0.8", Double(0., 2.),
                    "theoretical correction factor C_M [-] (0.8 for solid discs)");
  prm.declare_entry("specific load", "0", Double(0.),
                    "F_t·K_A/b [N/mm] for the ISO load factor; 0 = not given");
  prm.leave_subsection();
}

std::string gear_pair_parameter(bool wheel, const std::string& key)
{
  return std::string("Gear pair/") + (wheel ? "Wheel/" : "Pinion/") + key;
}

kinematics::GearPairSpec parse_gear_pair_parameters(dealii::ParameterHandler& prm)
{
  std::vector<kinematics::DerivedSize> derived;
  return parse_gear_pair_parameters(prm, derived);
}

kinematics::GearPairSpec parse_gear_pair_parameters(dealii::ParameterHandler& prm,
                                                    std::vector<kinematics::DerivedSize>& derived)
{
  kinematics::GearPairSpec pair;
  kinematics::AutomaticSizes automatic;
  prm.enter_subsection("Gear pair");
  pair.centre_distance = prm.get_double("centre distance") * mm;
  const double ring_tip_margin = prm.get_double("ring tip margin") * mm;
  prm.enter_subsection("Pinion");
  pair.pinion = parse_gear(prm, false, automatic.pinion_tip, automatic.pinion_bore);
  prm.leave_subsection();
  prm.enter_subsection("Wheel");
  pair.wheel = parse_gear(prm, true, automatic.wheel_tip, automatic.wheel_bore);
  prm.leave_subsection();
  prm.leave_subsection();
  // The rules of kinematics/automatic_sizes.h; InputError naming the parameter for a pair the
  // geometry refuses.
  kinematics::resolve_automatic_sizes(pair, automatic, ring_tip_margin, derived);
  for (kinematics::DerivedSize& size : derived)
    size.parameter = parameter_of_field(size.parameter);
  return pair;
}

kinematics::IsoStiffnessOptions parse_iso_parameters(dealii::ParameterHandler& prm)
{
  kinematics::IsoStiffnessOptions options;
  prm.enter_subsection("ISO 6336");
  options.theoretical_correction = prm.get_double("C_M");
  options.specific_load = prm.get_double("specific load") * 1e3; // N/mm → N/m
  prm.leave_subsection();
  return options;
}

namespace
{
// The Train entries that hold kinematics::GearTrainText, one a member: name, member,
// documentation. The members and their axes, then (after the torque entries, which keeps the
// order of the parameter list) their inertias and masses.
struct TrainTextEntry
{
  const char* name;
  std::string kinematics::GearTrainText::*text;
  const char* documentation;
};

using Text = kinematics::GearTrainText;
const TrainTextEntry train_structure_entries[] = {
    {"gears", &Text::gears,
     "toothed members, 'name: teeth, ...' [-]; negative teeth = internal gear"},
    {"modules", &Text::modules,
     "'name: module, ...' [mm] (optional: tooth forces, planet orbit radii, the check that a "
     "planet's meshes agree on its axis)"},
    {"carriers", &Text::carriers, "toothless members (carriers, shafts), 'name, ...'"},
    {"planets", &Text::planets,
     "members whose axis rides on a carrier, 'name: carrier*copies, ...'"},
    {"meshes", &Text::meshes,
     "'a-b/frame, ...': gears a and b mesh with both axes on frame (a carrier); 'a-b' alone: "
     "fixed axes in the housing"},
    {"connections", &Text::connections, "rigidly joined members, 'a=b, ...'"},
    {"fixed", &Text::fixed, "members held still, 'name, ...'"},
    {"inputs", &Text::inputs, "driven members and their speeds, 'name: speed, ...' [rpm]"},
    {"output", &Text::output, "output member (ratio, statics)"},
    {"profile shifts", &Text::profile_shifts,
     "'name: x, ...' [-] (optional, default 0): the working centre distances (planet orbits, "
     "an FE table's pair) follow from them at the dynamics command's Train/pressure angle "
     "(20° in the kinematics command)"}};
const TrainTextEntry train_mass_entries[] = {
    {"inertias", &Text::inertias, "'name: J, ...' [kg·m²], one copy about its own axis (optional)"},
    {"masses", &Text::masses,
     "'name: m, ...' [kg], one copy, counts where its axis moves (optional)"}};
} // namespace

namespace
{
// The names of a 'name: value, ...' or 'name, ...' list.
std::set<std::string> listed_names(const std::string& text)
{
  std::set<std::string> names;
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ',');)
  {
    item = item.substr(0, item.find(':'));
    const auto first = item.find_first_not_of(" \t");
    if (first != std::string::npos)
      names.insert(item.substr(first, item.find_last_not_of(" \t") + 1 - first));
  }
  return names;
}
} // namespace

void declare_train_parameters(dealii::ParameterHandler& prm)
{
  const kinematics::GearTrainText train = kinematics::builtin_train("bi-planetary");
  prm.enter_subsection("Train");
  for (const TrainTextEntry& entry : train_structure_entries)
    prm.declare_entry(entry.name, train.*entry.text, Anything(), entry.documentation);
  prm.declare_entry(
      "input torque", "120.2", Double(),
      "torque on the first input [N·m] (docs/references.md §2: 120.2); 0 = no statics");
  prm.declare_entry("friction coefficient", "0.08", friction_coefficient_pattern(),
                    "μ_z for the pair efficiencies [-] (docs/references.md §2: 0.08; was `tooth "
                    "friction coefficient`)");
  for (const TrainTextEntry& entry : train_mass_entries)
    prm.declare_entry(entry.name, train.*entry.text, Anything(), entry.documentation);
  prm.declare_entry("reduce inertia to", "", Anything(),
                    "member the inertia is reduced to; empty = the first input");
  prm.leave_subsection();
}

TrainParameters parse_train_parameters(dealii::ParameterHandler& prm)
{
  TrainParameters p;
  prm.enter_subsection("Train");
  for (const TrainTextEntry& entry : train_structure_entries)
    p.text.*entry.text = prm.get(entry.name);
  for (const TrainTextEntry& entry : train_mass_entries)
    p.text.*entry.text = prm.get(entry.name);
  p.input_torque = prm.get_double("input torque");
  p.tooth_friction = prm.get_double("friction coefficient");
  p.reduce_to = prm.get("reduce inertia to");
  prm.leave_subsection();
  // Optional lists left at defaults that name the built-in train's members (1 … 7, h, H) mean
  // nothing once Train/gears and carriers name others (issue 44: "Train/modules: unknown member
  // '1'" for a user who never set modules): such a default is read as empty.
  const kinematics::GearTrainText builtin = kinematics::builtin_train("bi-planetary");
  const std::set<std::string> members = listed_names(p.text.gears + "," + p.text.carriers);
  for (std::string Text::*text :
       {&Text::modules, &Text::profile_shifts, &Text::inertias, &Text::masses})
  {
    if (p.text.*text != builtin.*text)
      continue;
    const std::set<std::string> named = listed_names(p.text.*text);
    if (!std::includes(members.begin(), members.end(), named.begin(), named.end()))
      p.text.*text = "";
  }
  return p;
}
} // namespace gearstiff::app
