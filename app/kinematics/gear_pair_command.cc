// `gearstiff gear-pair [pair.prm]`: involute pair geometry (ISO 21771) and ISO 6336-1 method B
// stiffness. Default: the split-path pair of docs/references.md §1, reported beside the published
// values.
//
//   gearstiff gear-pair
//   gearstiff gear-pair --set "Gear pair/Pinion/profile shift=0.4" --set "Gear pair/Wheel/profile
//   shift=-0.4" gearstiff gear-pair pair.prm --json -o results/
#include "app/core/command.h"
#include "app/core/units.h"
#include "app/kinematics/kinematics_parameters.h"
#include "kinematics/gear_pair.h"
#include "kinematics/iso_stiffness.h"

#include <chrono>
#include <cmath>

namespace gearstiff::app
{
namespace
{
const std::string split_path_source = "docs/references.md §1 (Reszuta & Drewniak 2015)";

// A value of the report, compared with its published reference when the pair is the built-in
// one (`published`) and a reference exists (not NaN).
struct PublishedValue
{
  Report& report;
  bool published;
  void operator()(const std::string& key, double v, double reference, const std::string& unit,
                  const std::string& description, const std::string& source) const
  {
    if (published && !std::isnan(reference))
      report.add_compared_value(key, v, reference, unit, description, source);
    else
      report.add_value(key, v, unit, description);
  }
};

// Each gear's diameters and tip thickness.
void report_gears(const kinematics::GearPairGeometry& pair, const PublishedValue& value)
{
  Report& report = value.report;
  const double none = std::nan("");
  for (const bool wheel : {false, true})
  {
    const kinematics::GearGeometry& g = wheel ? pair.wheel : pair.pinion;
    const std::string p = wheel ? "wheel_" : "pinion_";
    const std::string name = wheel ? "wheel" : "pinion";
    report.add_value(p + "reference_diameter", g.reference_diameter / mm, "mm",
                     name + " reference diameter d");
    value(p + "base_radius", 0.5 * g.base_diameter / mm, wheel ? none : 24.667, "mm",
          name + " base radius r_b", split_path_source);
    report.add_value(p + "tip_diameter", g.tip_diameter / mm, "mm", name + " tip diameter d_a");
    if (g.tip_form_diameter != g.tip_diameter) // a rounded tip edge (the sharp one: d_a)
      report.add_value(p + "tip_form_diameter", g.tip_form_diameter / mm, "mm",
                       name + " tip form diameter d_Fa (where the flank meets the tip rounding)");
    report.add_value(p + "root_diameter", g.root_diameter / mm, "mm", name + " root diameter d_f");
    report.add_value(p + "form_diameter", g.form_diameter / mm, "mm",
                     name + " form diameter d_Ff (rack-generated involute limit)");
    report.add_value(p + "active_profile_start", g.active_profile_start / mm, "mm",
                     name + " start of active profile d_Nf");
    report.add_value(p + "tip_thickness", g.tip_thickness / mm, "mm",
                     name + " normal tooth thickness at the tip s_an");
  }
}

// The pair: centre distance, pressure angle, pitch, contact path and ratios, clearances,
// contact zones.
void report_pair(const kinematics::GearPairGeometry& pair, const PublishedValue& value)
{
  Report& report = value.report;
  const bool published = value.published;
  value("centre_distance", pair.centre_distance / mm, 97.5, "mm", "centre distance a_w",
        split_path_source);
  value("working_pressure_angle", pair.working_pressure_angle / degree, 20., "deg",
        "working transverse pressure angle α_wt", split_path_source);
  report.add_value("backlash", pair.backlash / mm, "mm", "normal backlash j_bn");
  value("transverse_base_pitch", pair.transverse_base_pitch / mm, 7.380, "mm",
        "transverse base pitch p_et", split_path_source);
  value("path_of_contact", pair.path_of_contact / mm, 11.068, "mm", "path of contact g_α",
        split_path_source + "; printed g_α = 1.4997·p_et, ε_α = 1.500 exactly here");
  value("transverse_contact_ratio", pair.transverse_contact_ratio, 1.500, "-",
        "transverse contact ratio ε_α", split_path_source);
  report.add_value("overlap_ratio", pair.overlap_ratio, "-", "overlap ratio ε_β");
  report.add_value("contact_start", pair.contact_start / mm, "mm",
                   "contact start A along the line of action from T1");
  report.add_value("pitch_point", pair.pitch_point / mm, "mm", "pitch point C from T1");
  report.add_value("contact_end", pair.contact_end / mm, "mm", "contact end E from T1");
  report.add_value("tip_clearance_pinion", pair.tip_clearance_pinion / mm, "mm",
                   "pinion tip to wheel root clearance");
  report.add_value("tip_clearance_wheel", pair.tip_clearance_wheel / mm, "mm",
                   "wheel tip to pinion root clearance");
  if (published)
    report.add_text("tip_diameters", "built-in case: both standard tip radii reduced by the same "
                                     "amount so that ε_α = 1.500 (docs/references.md §1 note)");
  for (std::size_t i = 0; i < pair.warnings.size(); ++i)
    report.add_text("warning_" + std::to_string(i + 1), pair.warnings[i]);

  ReportTable& zones = report.add_table(
      "contact_zones", {"start", "end", "pairs", "pinion_roll_start", "pinion_roll_end"},
      {"mm", "mm", "-", "deg", "deg"});
  for (const kinematics::ContactZone& zone : pair.contact_zones)
    zones.add_row({zone.start / mm, zone.end / mm, double(zone.pairs),
                   zone.pinion_roll_start / degree, zone.pinion_roll_end / degree});
}

// ISO 6336-1 method B.
void report_iso(const kinematics::IsoStiffness& iso, const kinematics::IsoStiffnessOptions& options,
                const PublishedValue& value)
{
  Report& report = value.report;
  const bool published = value.published;
  report.add_value("iso_flexibility", iso.flexibility * 1e9, "mm·µm/N", "ISO q'");
  report.add_value("iso_theoretical_single_stiffness", iso.theoretical_single * 1e-9, "N/(mm·µm)",
                   "ISO c'_th");
  report.add_value("iso_C_M", iso.theoretical_correction, "-", "ISO C_M");
  report.add_value("iso_C_R", iso.blank_factor, "-", "ISO C_R");
  report.add_value("iso_C_B", iso.basic_rack_factor, "-", "ISO C_B (basic rack)");
  report.add_value("iso_single_stiffness", iso.single * 1e-9, "N/(mm·µm)", "ISO c'");
  value("iso_single_stiffness_times_width", iso.single_per_width * 1e-6,
        kinematics::split_path_published::single_pair_stiffness * 1e-6, "N/µm", "ISO c'·b",
        "ANSYS single-pair k'_j, " + split_path_source);
  if (options.specific_load > 0.)
  {
    report.add_value("iso_load_factor", iso.load_factor, "-",
                     "ISO (F_t·K_A/b / 100 N/mm)^0.25 below 100 N/mm");
    report.add_value("iso_single_stiffness_loaded", iso.single_loaded * 1e-9, "N/(mm·µm)",
                     "ISO c' with the load factor");
  }
  report.add_value("iso_mesh_stiffness_alpha", iso.mesh_alpha * 1e-9, "N/(mm·µm)",
                   "ISO c_γα = c'·(0.75·ε_α + 0.25)");
  report.add_value("iso_mesh_stiffness_beta", iso.mesh_beta * 1e-9, "N/(mm·µm)",
                   "ISO c_γβ = 0.85·c_γα");
  report.add_value("iso_mesh_stiffness_alpha_times_width", iso.mesh_alpha_per_width * 1e-6, "N/µm",
                   "ISO c_γα·b");
  for (const kinematics::ValidityCheck& check : iso.validity)
    report.add_text("iso_validity: " + check.condition,
                    std::string(check.satisfied ? "met" : "NOT MET") + " (" +
                        std::to_string(check.value) + ")");
  if (published)
    report.add_text("iso_note", "the paper takes C_B = 1 (rack h_fP = 1.2·m_n) and gets c' ≈ 13.8 "
                                "N/(mm·µm), c'·b ≈ 330 N/µm; the built-in ISO 53 A rack "
                                "(h_fP = 1.25·m_n) gives C_B = 0.975");
}

void run(dealii::ParameterHandler& prm, CommandContext& context)
{
  std::vector<kinematics::DerivedSize> derived;
  const kinematics::GearPairSpec spec = parse_gear_pair_parameters(prm, derived);
  const kinematics::IsoStiffnessOptions options = parse_iso_parameters(prm);
  const auto start = std::chrono::steady_clock::now();
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec);
  const kinematics::IsoStiffness iso = kinematics::iso_mesh_stiffness(pair, options);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The published values belong to the built-in pair alone, recognised by its geometry.
  const PublishedValue value{context.report, kinematics::is_split_path_pair(spec)};
  if (!derived.empty())
    context.report.add_text("derived sizes", kinematics::derived_sizes_text(derived));
  report_gears(pair, value);
  report_pair(pair, value);
  report_iso(iso, options, value);
  context.report.add_value(
      "cost", elapsed * 1e6, "µs",
      "wall time: closed-form geometry and ISO formulas, one Newton solve for inv α_wt");
}

const CommandRegistration registration(Command{
    "gear-pair", "involute gear pair geometry, contact zones and ISO 6336-1 stiffness",
    "Involute gear pair (spur/helical, external/internal) after ISO 21771: radii, working "
    "pressure\n"
    "angle from the profile shifts, centre distance, base pitch, path of contact, ε_α, ε_β, the\n"
    "single/double contact zones along the line of action, tip thickness, undercut and\n"
    "interference checks; then ISO 6336-1 method B stiffness c', c_γα, c_γβ with C_M, C_R, C_B "
    "and\n"
    "the validity ranges. Default: the split-path pair of docs/references.md §1 (Reszuta & "
    "Drewniak\n"
    "2015), compared with the published values.",
    declare_gear_pair_parameters, run});
} // namespace
} // namespace gearstiff::app
