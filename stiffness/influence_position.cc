// One position of the influence-coefficient sweep (stiffness/influence_position.h).
#include "stiffness/influence_position.h"

#include "stiffness/face_load.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearstiff::stiffness::influence
{
using namespace dealii;

namespace
{
// Cells of the near-field strip across a contact whose gap is not a Hertz parabola: over
// ±(3·a + shift) about 20 cells across a Hertz zone of half the total load (docs/ltca.md).
constexpr int strip_cells = 96;

// The slope dS/dℓ of one gear's removal as the contact zone |x| < a sees it: the mean over the
// zone weighted by a Hertz pressure, x mapped to ℓ + x·k (k = r_b/ρ, the involute's roll per
// tangential offset). Off a kink it is the flank's slope; with a relief's start (a kink) inside
// the zone it lies between the two sides as the pressure does, so the force line's turn and the
// strip's frame follow the mean normal of the loaded surface (docs/ltca.md §5), not one side of
// the kink.
double zone_slope(const PairSeparation& separation, double at, bool wheel, double k,
                  double half_width)
{
  // 200 cells over 2a (~1 µm each for a = 0.08 mm); the slope by a 10 nm central difference,
  // far below the cells, so a kink falls between the differences of at most one cell.
  constexpr int cells = 200;
  constexpr double step = 1e-8;
  double sum = 0., weights = 0.;
  for (int i = 0; i < cells; ++i)
  {
    const double x = half_width * (-1. + (i + 0.5) * 2. / cells);
    const double weight = std::sqrt(1. - x * x / (half_width * half_width));
    const double l = at + x * k;
    sum += weight * (separation.removal(l + step, wheel) - separation.removal(l - step, wheel)) /
           (2. * step);
    weights += weight;
  }
  return sum / weights;
}

} // namespace

PairLine pair_line(const PositionModel& model, double at, double relative_radius,
                   double total_force)
{
  const PairFrame& frame = model.frame;
  const PairSeparation& separation = model.separation;
  PairLine line;
  if (!separation.modified())
    return line;
  // Roll per tangential offset: x moves gear i's touching point by x·r_bi/ρ_i of roll (arc
  // length ρ²/(2r_b) of the involute), to ℓ + x·r_bi/ρ_i in ℓ's terms.
  const double rho_1 = at, rho_2 = std::abs(at - frame.t2);
  const double k_1 = frame.pinion_base_radius() / rho_1, k_2 = frame.wheel_base_radius() / rho_2;
  const LineContact whole =
      hertz_line_contact(total_force, model.face_width, relative_radius, model.pinion, model.wheel);
  // The force line: each flank's slope dS/dℓ as the loaded surface sees it turns it (the
  // levers) and tilts it (τ).
  const auto set_force_line = [&](double slope_1, double slope_2)
  {
    line.pinion_lever = 1. - slope_1;
    line.wheel_lever = 1. + slope_2;
    // Signed distances σ_i = m·(O_i − T) of the centres from the line: Δ(σ_2 − σ_1) = −dψ·u·(O_2
    // − O_1) for a line turned by dψ (m = (cos ψ, −sin ψ), u = (sin ψ, cos ψ)).
    Tensor<1, 2> m;
    m[0] = frame.u[1];
    m[1] = -frame.u[0];
    const Eigen::Vector2d t1 = geometry::line_of_action_point(frame.pair, 0.);
    const Point<2> on_line(t1.x(), t1.y());
    const double sigma_1 = m * (Point<2>() - on_line), sigma_2 = m * (frame.wheel_centre - on_line);
    line.tilt = -(sigma_2 * slope_2 + sigma_1 * slope_1) / (frame.u * frame.wheel_centre);
  };
  const auto modification_gap = [&](double x)
  {
    return separation.removal(at + x * k_1, false) - separation.removal(at, false) +
           separation.removal(at + x * k_2, true) - separation.removal(at, true);
  };
  // The pair touches where the modified flanks' gap is smallest (geometry::touching_point: a
  // slope β moves the point by βR and lowers the gap by β²R/2), not at x = 0. Measured
  // 2026-12-05 on the tip-relief tests (μ 0): the exact path's meshed flanks first touch within
  // 0.005 µm of that gap (0.1–0.16 µm below the removal at ℓ on the built-in pair's 10 µm
  // reliefs, 0.5 µm on the planet–ring pair's 8 µm, R 24 mm); taking the removal at ℓ instead
  // (before) put the planet–ring pair's double contacts 4.4–6.0 % soft. Until then the strip's
  // gap left the slope's line out; with the drop in the gap it keeps it (docs/ltca.md §5).
  const geometry::FlankTouch touch = separation.touching(at);
  line.lowered = touch.separation - separation(at);
  // The strip is centred on the touching point c, where the FE coefficients are read
  // (touching_flanks): its layer's depth points lie under c and its gap is g(c + x) − g(c).
  // Centred on x = 0 instead (measured 2026-12-05, invariants case 1 of seed 20261201: z 39/76,
  // m 1.25 mm, 9.9 µm long reliefs, h 0.15 mm, c −0.055 mm), the depth points lay off the zone's
  // centre by c and k came out 1.1 % soft at a position whose relief's start lay 0.15 mm behind.
  // It spans the Hertz zone, the shift βR by the slope at x = 0 and the way to c.
  const double c = touch.offset;
  const double step = 1e-6; // m: the reliefs' slopes are constant over mm
  const double shift =
      std::abs(modification_gap(step) - modification_gap(-step)) / (2. * step) * relative_radius;
  const double span = 3. * whole.half_width + std::max(shift, std::abs(c));
  // Not a parabola (plus a line, which only shifts the zone by βR ≈ 30 µm): a kink inside the
  // strip or a curvature of the modification 1e-3 of the flanks'.
  const double bend = 0.5 * std::abs(modification_gap(c + span) + modification_gap(c - span) -
                                     2. * modification_gap(c));
  if (!(bend > 1e-3 * span * span / (2. * relative_radius)))
  {
    // A parabola plus a line: the slope is the line's. Its mean over the Hertz zone, not a central
    // difference at x = 0, which takes one side of a kink lying within the zone (measured
    // 2026-12-02, tip-relief test position 15: 1.46 % / 0.106 µm with one side, 1.30 % / 0.094 µm
    // with the zone's mean).
    set_force_line(zone_slope(separation, at, false, k_1, whole.half_width),
                   zone_slope(separation, at, true, k_2, whole.half_width));
    return line;
  }
  line.strip.half_span = span;
  line.strip.relative_radius = relative_radius;
  const auto gap = [&](double x) { return x * x / (2. * relative_radius) + modification_gap(x); };
  const double cell = 2. * span / strip_cells;
  for (int i = 0; i < strip_cells; ++i)
    line.strip.gap.push_back(gap(c - span + (i + 0.5) * cell) - gap(c));
  // The slopes weighted by the strip's own pressure (under the largest load, as the strip is
  // sized), not by a Hertz ellipse over the unmodified zone: where a rounded tip's arc begins
  // inside that zone the arc falls away by x²/(2r) and carries little, and the ellipse's mean
  // took its steep slope at full weight. Measured 2026-12-05 (μ 0, 32 positions, 2D, against the
  // exact rolling sweep at h_c 0.015 mm): the planet–ring pair with the planet's tip rounded
  // (r 0.6 mm) was −2.51 % at the position whose contact reaches the arc, its torque ratio
  // +0.8 % off the kinematic one where the exact path's moved +0.03 %; now −0.09 % (docs/ltca.md
  // §5 "The slopes the strip's pressure sees").
  const std::vector<double> pressure =
      strip_cell_pressures(total_force, model.face_width, line.strip, model.pinion, model.wheel);
  double sum_1 = 0., sum_2 = 0., weights = 0.;
  constexpr double slope_step = 1e-8; // m of roll: as zone_slope
  for (int i = 0; i < strip_cells; ++i)
  {
    if (!(pressure[i] > 0.))
      continue;
    const double x = c - span + (i + 0.5) * cell;
    for (const bool wheel : {false, true})
    {
      const double l = at + x * (wheel ? k_2 : k_1);
      (wheel ? sum_2 : sum_1) +=
          pressure[i] *
          (separation.removal(l + slope_step, wheel) - separation.removal(l - slope_step, wheel)) /
          (2. * slope_step);
    }
    weights += pressure[i];
  }
  set_force_line(sum_1 / weights, sum_2 / weights);
  return line;
}

std::array<double, 2> touching_flanks(const PairFrame& frame, const PairSeparation& separation,
                                      double at)
{
  if (!separation.modified())
    return {{at, at}};
  const double offset = separation.touching(at).offset;
  const double rho_1 = at, rho_2 = std::abs(at - frame.t2);
  const auto on_path = [&](double l)
  { return std::clamp(l, frame.pair.contact_start, frame.pair.contact_end); };
  return {{on_path(at + offset * frame.pinion_base_radius() / rho_1),
           on_path(at + offset * frame.wheel_base_radius() / rho_2)}};
}

template <int dim>
GearMeshStiffnessResult position_result(const PositionModel& model, double position,
                                        const std::vector<int>& pairs,
                                        const std::vector<Unknown>& unknowns,
                                        const MeshContactSolution& solution, double torque)
{
  const kinematics::GearPairGeometry& pair = model.frame.pair;
  const double r_b2 = model.frame.wheel_base_radius();
  GearMeshStiffnessResult r = result_at(model.frame, dim, position, pairs.size(), torque, solution,
                                        std::min_element(unknowns.begin(), unknowns.end(),
                                                         [](const Unknown& a, const Unknown& b)
                                                         { return a.touching < b.touching; })
                                            ->touching);
  // Every force on its pair's force line, at the lever arm r_b2·μ_j about the wheel
  // (geometry/scene_gear_pair.h: an external wheel's centre lies across the line of action from
  // the pinion's, a ring's on its side; a helical pair's lever ratios carry cos β_b), and its
  // friction force across it at the arm ρ₂ (pair_friction).
  double wheel_moment = 0., total = 0.;
  // 3D: the mesh forces on the pinion as the exact path sums them (stiffness/mesh_stiffness.cc,
  // mesh_forces): the normal force N along the pinion's flank normal (−u·cos β_b in the
  // transverse plane, ±sin β_b along z: n_z = φ₁'·((P − O₁) × u)/√(1 + tan²β_b)) at the point
  // where the station's plane meets the contact line, moments about the pinion centre at the
  // middle of the face.
  double axial = 0., moment_x = 0., moment_y = 0.;
  const double turn_rate = model.helix.turn_rate(model.frame, false);
  for (std::size_t item = 0; item < solution.force.size(); ++item)
  {
    const Unknown& unknown = unknowns[item];
    const double force = solution.force[item];
    const double friction = solution.friction.empty() ? 0. : solution.friction[item];
    wheel_moment +=
        (force * unknown.line.wheel_lever + friction * unknown.friction.wheel_arm) * r_b2;
    total += force;
    if (dim != 3)
      continue;
    const Eigen::Vector2d p = geometry::line_of_action_point(pair, unknown.at);
    const double n_z = turn_rate * (p.x() * model.frame.u[1] - p.y() * model.frame.u[0]) /
                       std::sqrt(1. + model.helix.rate * model.helix.rate);
    // The friction force on the pinion: along its flank's `across`, (−u_y, u_x) (pair_friction).
    const double f_x =
        -force * model.helix.cos_base * model.frame.u[0] - friction * model.frame.u[1];
    const double f_y =
        -force * model.helix.cos_base * model.frame.u[1] + friction * model.frame.u[0];
    const double f_z = force * n_z;
    const double z = model.stations.z[unknown.station] - 0.5 * model.face_width;
    axial += f_z;
    moment_x += p.y() * f_z - z * f_y;
    moment_y += z * f_x - p.x() * f_z;
  }
  r.torque_ratio = wheel_moment / torque;
  r.wheel_torque = (pair.spec.wheel.internal ? -1. : 1.) * wheel_moment;
  r.pinion_hub_torque = -torque;
  if (dim == 3)
  {
    r.tangential_force = total * model.helix.cos_base;
    r.axial_force = axial;
    r.tilting_moment = std::hypot(moment_x, moment_y);
  }
  for (const int j : pairs)
  {
    // The pair's force over its stations, its highest peak pressure and widest contact band.
    double force = 0., peak = 0., widest = 0.;
    unsigned int closed = 0;          // the pair's stations in contact
    const Unknown* peak_at = nullptr; // the unknown of the pair's peak pressure
    double peak_offset = 0.;          // m, its peak's tangential offset (LineContact)
    for (std::size_t item = 0; item < unknowns.size(); ++item)
    {
      if (unknowns[item].pair != j)
        continue;
      const std::size_t s = unknowns[item].station;
      force += solution.force[item];
      closed += solution.force[item] > 0.;
      if (peak_at == nullptr || solution.contact[item].peak_pressure > peak)
      {
        peak_at = &unknowns[item];
        peak_offset = solution.contact[item].peak_offset;
      }
      peak = std::max(peak, solution.contact[item].peak_pressure);
      widest = std::max(widest, solution.contact[item].half_width);
      // N/m: the transverse load per unit of face width, as the exact path's plane forces over
      // the plane's width (stiffness/face_load.h): the normal force's transverse part
      // N·cos β_b over the station's width, so that ∫ w dz = F_bt on both paths. (Until session
      // 32 this was N over the width, 1/cos β_b = +3.2 % above the exact path's on the built-in
      // helical pair: measured ∫ w dz 2003 N against its 1937 N and F_bt 1942 N.)
      if (dim == 3)
        r.face_load.push_back(
            {j, model.stations.z[s],
             solution.force[item] * model.helix.cos_base / model.stations.width[s],
             model.stations.width[s]});
    }
    add_pair_load(r, model.frame, position, j, force, total, peak, widest);
    if (dim == 3)
      r.pairs.back().closed_nodes = closed;
    if (peak_at != nullptr)
    {
      // Where the pressure peaks on each flank: the touching point (off ℓ on modified flanks:
      // touching_flanks) moved by the strip's peak offset x, x·r_bi/ρ_i of roll (a contact
      // reaching a relief's start or a rounded tip's arc peaks there; a tip edge at its edge).
      // Measured 2026-12-05 (built-in pair, r 0.5 mm rounded tips, 150 N·m, mesh position
      // 0.3203): the exact path's peak at roll 15.318 mm (E, the arc's start), the touching point
      // 15.237 mm.
      const double shift = peak_at->edge ? 0. : peak_offset;
      r.pairs.back().max_pressure_roll =
          peak_at->flank[0] + shift * model.frame.pinion_base_radius() / peak_at->at;
      r.pairs.back().max_pressure_wheel_roll =
          peak_at->flank[1] +
          shift * model.frame.wheel_base_radius() / std::abs(peak_at->at - model.frame.t2);
      if (dim == 3)
        r.pairs.back().max_pressure_face =
            model.stations.z[peak_at->station] - 0.5 * model.face_width;
    }
  }
  if (dim == 3)
    r.face_load_factor = summarise_face_load(r.face_load).factor;
  return r;
}

template GearMeshStiffnessResult position_result<2>(const PositionModel&, double,
                                                    const std::vector<int>&,
                                                    const std::vector<Unknown>&,
                                                    const MeshContactSolution&, double);
template GearMeshStiffnessResult position_result<3>(const PositionModel&, double,
                                                    const std::vector<int>&,
                                                    const std::vector<Unknown>&,
                                                    const MeshContactSolution&, double);
} // namespace gearstiff::stiffness::influence
