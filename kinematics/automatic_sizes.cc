#include "kinematics/automatic_sizes.h"

#include "errors/format.h"
#include "kinematics/fields.h"

#include <cmath>

namespace gearstiff::kinematics
{
namespace
{
bool close(double a, double b, double tolerance)
{
  return std::abs(a - b) <= tolerance;
}

bool same_teeth(const GearSpec& a, const GearSpec& b)
{
  const double relative = 1e-9;
  return a.teeth == b.teeth && a.internal == b.internal &&
         close(a.normal_module, b.normal_module, relative * b.normal_module) &&
         close(a.pressure_angle, b.pressure_angle, relative) &&
         close(a.helix_angle, b.helix_angle, relative) &&
         close(a.profile_shift, b.profile_shift, relative) &&
         close(a.addendum_coefficient, b.addendum_coefficient, relative) &&
         close(a.dedendum_coefficient, b.dedendum_coefficient, relative) &&
         close(a.root_radius_coefficient, b.root_radius_coefficient, relative);
}

// 1 µm: far below any size a user changes on purpose, far above the bisection of the published
// tips (1e-15 m).
constexpr double size_tolerance = 1e-6;

// A published tip as the parameter files carried it before `auto` (12 significant digits in
// mm): gmsh meshes the outline differently for a 1e-13 m change of the tip, and the built-in
// case's results stay identical to the earlier releases' (k'_d 396.383135527 N/µm).
double as_declared(double diameter)
{
  return std::stod(format_number(diameter / 1e-3, 12)) * 1e-3;
}
} // namespace

bool has_split_path_teeth(const GearPairSpec& spec)
{
  const GearPairSpec builtin = split_path_pair();
  return same_teeth(spec.pinion, builtin.pinion) && same_teeth(spec.wheel, builtin.wheel);
}

bool is_split_path_pair(const GearPairSpec& spec)
{
  if (!has_split_path_teeth(spec))
    return false;
  const GearPairSpec builtin = split_path_pair();
  const GearPairGeometry published = compute_gear_pair(builtin);
  const auto same_blank = [](const GearSpec& a, const GearSpec& b)
  {
    return close(a.face_width, b.face_width, size_tolerance) &&
           close(a.tip_diameter, b.tip_diameter, size_tolerance);
  };
  return same_blank(spec.pinion, builtin.pinion) && same_blank(spec.wheel, builtin.wheel) &&
         (spec.centre_distance == 0. ||
          close(spec.centre_distance, published.centre_distance, size_tolerance));
}

void resolve_automatic_sizes(GearPairSpec& spec, const AutomaticSizes& automatic,
                             double ring_tip_margin, std::vector<DerivedSize>& derived)
{
  const bool builtin_teeth = has_split_path_teeth(spec);
  const GearPairSpec builtin = split_path_pair();
  const std::string published_tip =
      "the published tip of docs/references.md §1 (this pair's teeth: ε_α = 1.500)";
  const std::string standard_tip = "standard d ± 2·m_n·(h_aP* + x) (ISO 21771)";

  // 0 is the standard tip for compute_gear_pair; the number follows from the geometry below.
  if (automatic.pinion_tip)
    spec.pinion.tip_diameter = builtin_teeth ? as_declared(builtin.pinion.tip_diameter) : 0.;
  if (automatic.wheel_tip)
  {
    if (spec.wheel.internal)
    {
      GearPairSpec trial = spec;
      trial.pinion.bore_diameter = trial.wheel.bore_diameter = 0.;
      spec.wheel.tip_diameter = clearing_ring_tip_diameter(trial, ring_tip_margin);
    }
    else
      spec.wheel.tip_diameter = builtin_teeth ? as_declared(builtin.wheel.tip_diameter) : 0.;
  }
  // The geometry with the tips settled and no bores: root diameters, and the standard tips
  // as numbers.
  GearPairSpec bare = spec;
  bare.pinion.bore_diameter = bare.wheel.bore_diameter = 0.;
  const GearPairGeometry geometry = compute_gear_pair(bare);
  if (automatic.pinion_tip)
    spec.pinion.tip_diameter = geometry.pinion.tip_diameter;
  if (automatic.wheel_tip)
    spec.wheel.tip_diameter = geometry.wheel.tip_diameter;

  if (automatic.pinion_tip)
    derived.push_back({field::gear(false, "tip_diameter"), spec.pinion.tip_diameter,
                       builtin_teeth ? published_tip : standard_tip});
  if (automatic.wheel_tip)
    derived.push_back({field::gear(true, "tip_diameter"), spec.wheel.tip_diameter,
                       spec.wheel.internal
                           ? "the longest ring teeth that clear the pinion's involute by 'Gear "
                             "pair/ring tip margin'"
                           : (builtin_teeth ? published_tip : standard_tip)});

  const std::string builtin_bore = "the bore of the built-in case (this pair's teeth; not "
                                   "published, docs/references.md §1)";
  if (automatic.pinion_bore)
  {
    spec.pinion.bore_diameter =
        builtin_teeth ? builtin.pinion.bore_diameter : 0.5 * geometry.pinion.root_diameter;
    derived.push_back({field::gear(false, "bore_diameter"), spec.pinion.bore_diameter,
                       builtin_teeth ? builtin_bore : "half the root diameter d_f/2"});
  }
  if (automatic.wheel_bore)
  {
    const double m_n = spec.wheel.normal_module;
    if (spec.wheel.internal)
      spec.wheel.bore_diameter =
          geometry.wheel.root_diameter + 2. * automatic_ring_rim_modules * m_n;
    else
      spec.wheel.bore_diameter =
          builtin_teeth ? builtin.wheel.bore_diameter : 0.5 * geometry.wheel.root_diameter;
    derived.push_back({field::gear(true, "bore_diameter"), spec.wheel.bore_diameter,
                       spec.wheel.internal
                           ? "the ring's outer diameter: root diameter + 2·4·m_n (a rim of four "
                             "modules)"
                       : builtin_teeth ? builtin_bore
                                       : "half the root diameter d_f/2"});
  }
}

std::string derived_sizes_text(const std::vector<DerivedSize>& derived)
{
  std::string text;
  for (const DerivedSize& size : derived)
    text += (text.empty() ? "" : "; ") + size.parameter + " = " +
            format_number(size.value * 1e3, 6) + " mm (" + size.rule + ")";
  return text;
}
} // namespace gearstiff::kinematics
