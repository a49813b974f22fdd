#include "app/scenes/tooth_modification_parameters.h"

#include "app/core/field_names.h"
#include "app/core/number_text.h"
#include "app/core/parameter_patterns.h"
#include "app/core/parameter_table.h"
#include "app/core/units.h"
#include "app/scenes/tooth_fault_parameters.h"
#include "errors/errors.h"
#include "geometry/fields.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace gearstiff::app
{
namespace
{
// The entries of one gear, ISO 21771 terms (docs/references.md §8).
const std::vector<TextEntry> entries = {
    {"tip relief", "0", "C_a, material removed normal to the flank at the tip [µm]; 0 = none"},
    {"tip relief length", "auto",
     "L_a along the path of contact from the tip [mm]; auto = from the start of single-tooth "
     "contact (long relief)"},
    {"tip relief shape", "linear", "linear | parabolic | arc"},
    {"root relief", "0",
     "C_f, removed normal to the flank at the root form circle [µm]; the fillet takes what the "
     "flank loses at the form circle (any modification's), blended to 0 at the root, so the "
     "outline has no step there"},
    {"root relief length", "auto",
     "L_f along the path of contact from the root form circle [mm]; auto = to the start of "
     "single-tooth contact"},
    {"root relief shape", "linear", "linear | parabolic | arc"},
    {"profile crowning", "0",
     "C_α, removed at both ends of the active profile, parabolic, 0 in its middle [µm]"},
    {"profile slope", "0",
     "f_Hα over the active profile [µm]; > 0 removes at the tip, < 0 at the root"},
    {"lead crowning", "0", "C_β over the face width [µm] (3D only)"},
    {"lead slope", "0", "f_Hβ over the face width [µm] (3D only)"},
    {"end relief", "0", "C_I = C_II at both ends of the face [µm] (3D only)"},
    {"end relief length", "0",
     "L_I, length of the end relief from each end [mm], in (0, half the face width] (3D only)"},
    {"modified flanks", "both",
     "loaded: the modifications act on the loaded flank only; both: on both flanks"}};

const char* const lead_entries[] = {"lead crowning", "lead slope", "end relief"};

std::string gear_path(bool wheel, const std::string& name)
{
  return std::string("Gear pair/") + (wheel ? "Wheel/" : "Pinion/") + name;
}

double number(const ModificationText& text, const std::string& name, bool wheel)
{
  const std::string& value = text.at(name);
  const std::optional<double> result = number_in(value);
  if (!result || !std::isfinite(*result))
    throw InputError(gear_path(wheel, name), "'" + value + "' is not a number");
  return *result;
}

// A relief length: "auto" (−1) or a length ≥ 0 in mm, in m.
double relief_length(const ModificationText& text, const std::string& name, bool wheel)
{
  if (text.at(name) == "auto")
    return -1.;
  const double length = number(text, name, wheel);
  if (!(length >= 0.))
    throw InputError(gear_path(wheel, name), "must be auto or a length >= 0 [mm]");
  return length * mm;
}

std::string trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator))
    parts.push_back(trim(part));
  return parts;
}
// The lead modifications of one gear (3D; geometry/tooth_modification_lead.h), in m.
geometry::LeadModification parse_lead(const ModificationText& text, bool wheel,
                                      geometry::ModifiedFlanks flanks)
{
  geometry::LeadModification lead;
  lead.crowning = number(text, "lead crowning", wheel) * 1e-6;
  lead.slope = number(text, "lead slope", wheel) * 1e-6;
  lead.end_relief = number(text, "end relief", wheel) * 1e-6;
  lead.end_relief_length = number(text, "end relief length", wheel) * mm;
  lead.flanks = flanks;
  for (const auto& [amount, name] :
       {std::pair{lead.crowning, "lead crowning"}, std::pair{lead.end_relief, "end relief"},
        std::pair{lead.end_relief_length, "end relief length"}})
    if (amount < 0.)
      throw InputError(gear_path(wheel, name), "must be 0 or positive");
  return lead;
}

// The fields the geometry names a gear's modification or fault by ("wheel.tip_relief_length",
// geometry::field::gear_entry) as the entries of "Gear pair/Pinion" and "Gear pair/Wheel".
ParameterNames tooth_modification_field_names()
{
  ParameterNames names;
  for (const bool wheel : {false, true})
    for (const auto* list : {&entries, &tooth_fault_entries()})
      for (const TextEntry& entry : *list)
        names[geometry::field::gear_entry(geometry::field::modified_gear(wheel), entry.name)] =
            gear_path(wheel, entry.name);
  return names;
}

const FieldNamesRegistration tooth_modification_fields("tooth modifications",
                                                       tooth_modification_field_names);
} // namespace

void declare_tooth_modification_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Gear pair");
  for (const char* gear : {"Pinion", "Wheel"})
  {
    prm.enter_subsection(gear);
    declare_text_entries(prm, entries);
    declare_tooth_fault_entries(prm); // issue 31, app/scenes/tooth_fault_parameters.cc
    prm.leave_subsection();
  }
  prm.leave_subsection();
}

PairModificationText read_tooth_modification_text(ParameterHandler& prm)
{
  PairModificationText text;
  prm.enter_subsection("Gear pair");
  for (const bool wheel : {false, true})
  {
    prm.enter_subsection(wheel ? "Wheel" : "Pinion");
    read_text_entries(prm, entries, wheel ? text.wheel : text.pinion);
    read_tooth_fault_entries(prm, wheel ? text.wheel : text.pinion);
    prm.leave_subsection();
  }
  prm.leave_subsection();
  return text;
}

geometry::GearModifications parse_gear_modifications(const ModificationText& text, bool wheel,
                                                     unsigned int dimension)
{
  using geometry::ModificationKind;
  geometry::GearModifications modifications;
  const geometry::ModifiedFlanks flanks = geometry::parse_modified_flanks(
      text.at("modified flanks"), gear_path(wheel, "modified flanks"));
  for (const char* name : lead_entries)
    if (number(text, name, wheel) != 0. && dimension == 2)
      throw InputError(gear_path(wheel, name), "a lead modification needs the 3D model (Mesh/"
                                               "dimension = 3): a 2D model has no face width to "
                                               "vary over");
  modifications.lead = parse_lead(text, wheel, flanks);
  for (const auto& [kind, name] :
       {std::pair{ModificationKind::tip_relief, "tip relief"},
        std::pair{ModificationKind::root_relief, "root relief"},
        std::pair{ModificationKind::profile_crowning, "profile crowning"},
        std::pair{ModificationKind::profile_slope, "profile slope"}})
  {
    geometry::ToothModification m;
    m.kind = kind;
    m.amount = number(text, name, wheel) * 1e-6;
    m.flanks = flanks;
    if (m.kind != ModificationKind::profile_slope && m.amount < 0.)
      throw InputError(gear_path(wheel, name), "must be 0 or positive (material removed, µm)");
    const bool relief =
        kind == ModificationKind::tip_relief || kind == ModificationKind::root_relief;
    if (relief)
    {
      const std::string length = std::string(name) + " length";
      m.length = relief_length(text, length, wheel);
      m.shape = geometry::parse_relief_shape(text.at(std::string(name) + " shape"),
                                             gear_path(wheel, std::string(name) + " shape"));
    }
    if (m.amount != 0.)
      modifications.all_teeth.push_back(m);
  }
  if (text.count("faulty tooth") > 0) // the fault entries were read (read_tooth_fault_entries)
    add_tooth_faults(text, wheel, dimension, modifications);
  return modifications;
}

std::vector<ModificationVariant> parse_modification_variants(const std::string& text,
                                                             const PairModificationText& base,
                                                             const std::string& parameter)
{
  std::vector<ModificationVariant> variants;
  if (trim(text).empty())
    return variants;
  const std::vector<std::string> listed = split(text, ';');
  for (std::size_t i = 0; i < listed.size(); ++i)
  {
    const std::string& variant = listed[i];
    // An empty entry (';;') ran as an unnamed copy of the base.
    if (variant.empty())
      throw InputError(parameter, "entry " + std::to_string(i + 1) +
                                      " between ';' is empty: give 'name = value, ...' or "
                                      "remove the ';'");
    ModificationVariant v{variant, base};
    for (const std::string& assignment : split(variant, ','))
    {
      const auto equals = assignment.find('=');
      if (equals == std::string::npos)
        throw InputError(parameter, "'" + assignment + "' is not 'name = value'");
      std::string name = trim(assignment.substr(0, equals));
      const std::string value = trim(assignment.substr(equals + 1));
      std::vector<ModificationText*> gears{&v.text.pinion, &v.text.wheel};
      for (const auto& [prefix, gear] :
           {std::pair{"Pinion/", &v.text.pinion}, std::pair{"Wheel/", &v.text.wheel}})
        if (name.rfind(prefix, 0) == 0)
        {
          name = name.substr(std::string(prefix).size());
          gears = {gear};
        }
      if (base.pinion.count(name) == 0)
        throw InputError(parameter, "'" + name + "' is not a tooth modification entry");
      for (ModificationText* gear : gears)
        (*gear)[name] = value;
    }
    variants.push_back(v);
  }
  return variants;
}

std::string first_modified_entry(const PairModificationText& text)
{
  for (const bool wheel : {false, true})
    for (const char* name : {"tip relief", "root relief", "profile crowning", "profile slope",
                             "lead crowning", "lead slope", "end relief"})
    {
      const std::string& value = (wheel ? text.wheel : text.pinion).at(name);
      char* end = nullptr;
      const double amount = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || amount != 0.)
        return gear_path(wheel, name);
    }
  return first_fault_entry(text);
}
} // namespace gearstiff::app
