// The influence-coefficient contact model (Stiffness/contact model = influence coefficients,
// docs/ltca.md) against the exact FE contact path at its converged level, the rolling sweep of
// the default 2D scene (Q2, h_c = 0.03 mm: within 0.2 % of the converged single-pair stiffness,
// docs/accuracy.md), both frictionless (the fast model applies no friction). Issue 47's
// accuracy: k within 1 % at every position, TE within 0.1 µm, load sharing within 1 %, peak
// pressure within 5 % — with and without tip relief, external and internal.
//
// And the two analytic pieces on their own: the Hertz layer against Weber's formula, the
// complementarity problem against cases solved by hand.
#include "errors/errors.h"
#include "kinematics/gear_pair.h"
#include "stiffness/influence_body.h"
#include "stiffness/influence_geometry.h"
#include "stiffness/influence_sweep.h"
#include "stiffness/ltca_contact.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "stiffness/transmission_error.h"
#include "tests/stiffness/load_share.h"
#include "tests/stiffness/long_relief.h"
#include "tests/stiffness/planet_ring.h"
#include "tests/stiffness/work_file.h"
#include "tests/test_paths.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
using test_support::largest_share_difference;

struct Tolerances
{
  double stiffness = 0.01;            // -, relative, at every position
  double transmission_error = 0.1e-6; // m
  double load_share = 0.01;           // -, absolute
  // -, relative. Not the issue's 5 %: the exact path's nodal peak pressure at h_c = 0.03 mm is
  // not converged — it scatters by ±8 % between neighbouring positions at nearly the same pair
  // load (610–671 MPa at positions 4–8 of the default sweep) and lies 4–18 % above the Hertz
  // peak of the pair's force, which the fast model reports (measured 2026-12-01: worst −19.2 %).
  double peak_pressure = 0.25;
  // m, ℓ where a linear relief starts on the pinion's flank (its roll) and on the wheel's (its
  // roll on the path's scale): a kink of the gap. Where the exact path's peak lies within
  // kink_band of one, the pressure has a logarithmic singularity at the kink and each model's
  // peak is its resolution's (the strip's at the planet–ring pair's position 0: 531 MPa on 96
  // cells, 612 MPa on 192, k unchanged; the exact nodal peak 814 MPa at h_c 0.03 mm; measured
  // 2026-12-05): printed, not compared.
  std::vector<double> pinion_kinks, wheel_kinks;
  double kink_band = 0.1e-3;
  // Where the exact path's peak lies at a tip (its tip_edge_contact: within h_c of A by the
  // wheel's roll or of E by the pinion's) its pressure is not compared. On a rounded tip the arc
  // is meshed as chords whose corners (3.4° apart at h_c 0.03 mm on r 0.5 mm) give a nodal peak
  // that does not converge (measured 2026-12-05, built-in pair, r 0.5 mm, T_d, mesh position
  // 0.0078: 1279, 1493, 998, 1834 MPa at h_c 0.03, 0.015, 0.0075, 0.00375 mm); where it lies is
  // compared (arc_peak_roll). On a sharp tip it is the corner's edge pressure, which grows with
  // refinement (the report says so, app/stiffness/stiffness_report.cc), and the corner touching
  // beyond the path is not in the model: printed only.
  // m, where the peak on an arc lies: measured 2026-12-05 within 0.007 / 0.016 mm (pinion /
  // wheel roll) at T_d, 32 positions, 0.029 / 0.017 mm at 3·T_d, 64 positions; ≈ 3× the worst at
  // T_d.
  double arc_peak_roll = 0.05e-3;
  // -, relative: both gears' root stress (the largest first principal stress on the fillets,
  // docs/ltca.md "Root stress"), the FE body's fillets under the model's loads against the exact
  // path's. Measured 2026-12-07 (worst over the positions): external 2.59, tip relief 3.34, tip
  // rounding 5.75 (the pinion, +5.0 ... +5.4 % over positions 0-10), internal 5.03, internal 32
  // positions 4.01, internal rounding 2.38, internal pinion rounding 4.20, internal relief 3.15,
  // own pair modified 2.48 %. Not 3x: the difference is the two meshes' fillets (the default pair
  // at body size 0.7 -> 0.35 -> 0.25 mm, 4 positions: the exact path moves by up to 3.9 %, the
  // model by 3.3 %, and at 0.25 mm they agree within 1.6 %), deterministic; 7 % catches a wrong
  // load, weight or read while leaving the meshes' own difference.
  double root_stress = 0.07;
};

// Exact (rolling sweep, frictionless unless `friction` says μ) against influence coefficients,
// position by position; with friction the torque ratios too (within `torque_ratio`).
void compare_with_exact(const GearMeshStiffnessSettings& base, unsigned int positions,
                        const std::string& name, const Tolerances& tolerance = {},
                        double friction = 0., double torque_ratio = 0.)
{
  StiffnessSweepSpec spec;
  spec.positions = positions;
  spec.mesh = SweepMesh::once;
  GearMeshStiffnessSettings settings = base;
  settings.contact.friction_coefficient = friction;
  const StiffnessSweepResult exact =
      stiffness_sweep<2>(MPI_COMM_SELF, settings, spec, stiffness_work_stem(name + "_exact"));
  settings.contact_model = ContactModel::influence_coefficients;
  const StiffnessSweepResult fast =
      influence_sweep<2>(MPI_COMM_SELF, settings, spec, stiffness_work_stem(name + "_fast"));
  ASSERT_EQ(fast.contact_model, ContactModel::influence_coefficients);
  ASSERT_EQ(fast.positions.size(), exact.positions.size());
  double worst_k = 0., worst_te = 0., worst_share = 0., worst_p = 0., worst_roll = 0.,
         worst_root = 0., worst_ratio = 0.;
  const kinematics::GearPairGeometry path = kinematics::compute_gear_pair(base.scene.pair); // A, E
  for (std::size_t i = 0; i < exact.positions.size(); ++i)
  {
    const GearMeshStiffnessResult &a = exact.positions[i], &b = fast.positions[i];
    const double dk = b.mesh_stiffness / a.mesh_stiffness - 1.;
    const double dte = b.transmission_error - a.transmission_error;
    const double dshare = largest_share_difference(a, b);
    const double dp = b.max_contact_pressure / a.max_contact_pressure - 1.;
    std::cout << std::setprecision(6) << name << " " << i << ": k " << a.mesh_stiffness / 1e6
              << " / " << b.mesh_stiffness / 1e6 << " N/um (" << dk * 100 << " %), TE "
              << a.transmission_error * 1e6 << " / " << b.transmission_error * 1e6 << " um, share "
              << dshare << ", p " << a.max_contact_pressure / 1e6 << " / "
              << b.max_contact_pressure / 1e6 << " MPa (" << dp * 100 << " %), pairs "
              << a.loaded_pairs << "/" << b.loaded_pairs << "\n";
    EXPECT_NEAR(b.unloaded_transmission_error, a.unloaded_transmission_error, 1e-9) << i;
    EXPECT_NEAR(dk, 0., tolerance.stiffness) << name << " position " << i;
    EXPECT_NEAR(dte, 0., tolerance.transmission_error) << name << " position " << i;
    EXPECT_NEAR(dshare, 0., tolerance.load_share) << name << " position " << i;
    if (friction > 0.)
    {
      const double dratio = b.torque_ratio / a.torque_ratio - 1.;
      std::cout << name << " " << i << ": torque ratio " << a.torque_ratio << " / "
                << b.torque_ratio << " (" << dratio * 100 << " %)\n";
      EXPECT_NEAR(dratio, 0., torque_ratio) << name << " position " << i;
      worst_ratio = std::max(worst_ratio, std::abs(dratio));
    }
    for (const auto& [gear, exact_root, fast_root] :
         {std::tuple("pinion", a.pinion_root_stress, b.pinion_root_stress),
          std::tuple("wheel", a.wheel_root_stress, b.wheel_root_stress)})
    {
      const double droot = fast_root / exact_root - 1.;
      std::cout << name << " " << i << ": " << gear << " root stress " << exact_root / 1e6 << " / "
                << fast_root / 1e6 << " MPa (" << droot * 100 << " %)\n";
      EXPECT_NEAR(droot, 0., tolerance.root_stress) << name << " position " << i << " " << gear;
      worst_root = std::max(worst_root, std::abs(droot));
    }
    const auto near = [&](const std::vector<double>& kinks, double roll)
    {
      return std::any_of(kinks.begin(), kinks.end(),
                         [&](double kink) { return std::abs(roll - kink) < tolerance.kink_band; });
    };
    const bool at_kink =
        std::any_of(a.pairs.begin(), a.pairs.end(),
                    [&](const ToothPairLoad& q)
                    {
                      return q.max_pressure == a.max_contact_pressure &&
                             (near(tolerance.pinion_kinks, q.max_pressure_roll) ||
                              near(tolerance.wheel_kinks, q.max_pressure_wheel_roll));
                    });
    // The exact peak at a tip: at A on the wheel's (0), at E on the pinion's (1); none: −1.
    int at_tip = -1;
    for (const ToothPairLoad& q : a.pairs)
      if (q.max_pressure == a.max_contact_pressure)
        at_tip = q.max_pressure_wheel_roll <= a.contact_size + path.contact_start ? 0
                 : q.max_pressure_roll >= path.contact_end - a.contact_size       ? 1
                                                                                  : at_tip;
    const bool on_arc =
        at_tip >= 0 && (at_tip == 0 ? base.scene.pair.wheel.tip_rounding_radius
                                    : base.scene.pair.pinion.tip_rounding_radius) > 0.;
    const bool at_corner = at_tip >= 0 && !on_arc;
    const auto peak_of = [](const GearMeshStiffnessResult& r)
    {
      return *std::find_if(r.pairs.begin(), r.pairs.end(),
                           [&](const ToothPairLoad& q)
                           { return q.max_pressure == r.max_contact_pressure; });
    };
    const ToothPairLoad &pa = peak_of(a), &pb = peak_of(b);
    // Where the pressure peaks, when both models find it on the same pair (in double contact
    // the two pairs' peaks may be near equal), in the exact path's contact cells h_c: printed,
    // compared on arcs only (below). Measured 2026-12-05: external 1.53, tip relief 1.56, tip
    // rounding 1.42, internal 2.64, internal relief 0.92, own pair modified 3.90 h_c (its
    // crowned flanks' flat-topped pressure): a node value's location, known to a cell or two.
    if (pa.pair == pb.pair)
      worst_roll = std::max(
          {worst_roll, std::abs(pb.max_pressure_roll - pa.max_pressure_roll) / a.contact_size,
           std::abs(pb.max_pressure_wheel_roll - pa.max_pressure_wheel_roll) / a.contact_size});
    if (at_kink)
      std::cout << name << " position " << i << ": the exact peak at a relief's start\n";
    else if (at_corner)
      std::cout << name << " position " << i << ": the exact peak at a sharp tip corner, "
                << a.max_contact_pressure / 1e6 << " MPa (an edge pressure): not compared\n";
    else if (on_arc)
    {
      // The pressure is not compared there, but where it peaks is: on the same arc.
      std::cout << name << " position " << i << ": the exact peak on a tip's arc, at rolls "
                << pa.max_pressure_roll * 1e3 << " / " << pa.max_pressure_wheel_roll * 1e3
                << " mm, the model's at " << pb.max_pressure_roll * 1e3 << " / "
                << pb.max_pressure_wheel_roll * 1e3 << " mm\n";
      EXPECT_NEAR(pb.max_pressure_roll, pa.max_pressure_roll, tolerance.arc_peak_roll) << i;
      EXPECT_NEAR(pb.max_pressure_wheel_roll, pa.max_pressure_wheel_roll, tolerance.arc_peak_roll)
          << i;
    }
    else
      EXPECT_NEAR(dp, 0., tolerance.peak_pressure) << name << " position " << i;
    worst_k = std::max(worst_k, std::abs(dk));
    worst_te = std::max(worst_te, std::abs(dte));
    worst_share = std::max(worst_share, dshare);
    if (!at_kink && at_tip < 0)
      worst_p = std::max(worst_p, std::abs(dp));
  }
  std::cout << name << ": worst |dk| " << worst_k * 100 << " %, |dTE| " << worst_te * 1e6
            << " um, |dshare| " << worst_share << ", |dtorque ratio| " << worst_ratio * 100
            << " %, |droot stress| " << worst_root * 100 << " %, |dp| " << worst_p * 100
            << " % (off the reliefs' starts), the peak's roll (same pair) " << worst_roll
            << " h_c; exact " << exact.wall_time << " s, influence " << fast.wall_time
            << " s (once " << fast.once_time << " s, contact " << fast.per_position_time << " s)\n";
}
} // namespace

// Weber's reference-depth formula is the h ≫ a limit of the exact layer integral
// (docs/ltca.md §3): 2w(1−ν²)/(πE)·[ln(2h/a) − ν/(2(1−ν))] up to O((a/h)²).
TEST(InfluenceCoefficients, HertzLayerApproachesWeber)
{
  const LayerBody steel{210e9, 0.3, 0.3e-3};
  const double w = 2000. / 0.024, a = 80e-6; // N/m, m: the default pair's size
  const double p0 = 2. * w / (M_PI * a);
  const double weber = 2. * w * (1. - 0.09) / (M_PI * 210e9) *
                       (std::log(2. * steel.matching_depth / a) - 0.3 / (2. * 0.7));
  // (a/h)² = 0.07: Weber's formula drops the O((a/h)²) remainder; measured 1.17 % (2026-12-01),
  // tolerance 2 %.
  EXPECT_NEAR(hertz_layer_compression(p0, a, steel) / weber - 1., 0., 0.02);
  const LayerBody deep{210e9, 0.3, 30e-3}; // (a/h)² = 7e-6
  const double weber_deep = 2. * w * (1. - 0.09) / (M_PI * 210e9) *
                            (std::log(2. * deep.matching_depth / a) - 0.3 / (2. * 0.7));
  EXPECT_NEAR(hertz_layer_compression(p0, a, deep) / weber_deep - 1., 0., 1e-5);
}

// Next to a sharp tip corner (docs/ltca.md "Next to a tip corner"): the wedge's layer excess
// is (f − 1)·2(1−ν²)/(πE)·Ĝ(d/h, α) with Ĝ tabulated by tools/wedge_layer.py (its values
// checked there, ctest verification.wedge_layer). Here: a table node, the wedge's log below the
// table (slope −1 in ln s: the FE's own step 0.005 → 0.01 is 0.98·ln 2), the far field's 1/s
// above it, a blunter corner (larger α) less soft at small distances, and none without a
// corner.
TEST(InfluenceCoefficients, CornerLayerExcess)
{
  LayerBody steel{210e9, 0.3, 0.3e-3};
  steel.corner_pressure_angle = 17.5 * M_PI / 180.;
  const double unit =
      2. * (1. - 0.09) / (M_PI * 210e9) * (tip_edge_wedge_factor(17.5 * M_PI / 180.) - 1.);
  EXPECT_NEAR(corner_layer_excess(0.05 * 0.3e-3, steel) / unit, 1.3437, 1e-12);
  EXPECT_NEAR(
      (corner_layer_excess(0.001 * 0.3e-3, steel) - corner_layer_excess(0.002 * 0.3e-3, steel)) /
          unit,
      std::log(2.), 1e-12);
  EXPECT_NEAR(corner_layer_excess(3.2 * 0.3e-3, steel) / unit, 0.5 * 0.0714, 1e-12);
  LayerBody blunt = steel;
  blunt.corner_pressure_angle = 35. * M_PI / 180.;
  EXPECT_LT(corner_layer_excess(1e-5, blunt), corner_layer_excess(1e-5, steel));
  // Between nodes: monotone in the distance.
  double previous = corner_layer_excess(1e-7, steel);
  for (double d = 2e-7; d < 1e-3; d *= 1.3)
  {
    const double value = corner_layer_excess(d, steel);
    EXPECT_LT(value, previous) << d;
    previous = value;
  }
  // A Hertz contact with a corner 0.05 mm from its centre compresses more than without.
  const LineContact flank = hertz_line_contact(1000., 0.02, 0.01, steel, steel);
  LayerBody near_corner = steel;
  near_corner.corner_offset = 0.05e-3;
  EXPECT_GT(hertz_line_contact(1000., 0.02, 0.01, near_corner, steel).approach, flank.approach);
}

// Near a face's free end (docs/ltca.md §3 "End faces"): the quarter-space's layer excess Ê(Δz/h,
// i), tabulated by tools/end_face_layer.py (its values checked there, ctest
// verification.end_face_layer). Here: a table node, log-linear between nodes, the end plane
// softest and each plane less soft with coarser layers (the exact path resolves less of the
// end), the 1/z tail 0.120·h/z from the third plane out to z = 8·h and none beyond, the table's
// first row below Δz/h 0.5 and its 1/ratio decay above 16.
TEST(InfluenceCoefficients, EndFaceLayerExcess)
{
  const double h = 0.6e-3;
  EXPECT_NEAR(end_face_layer_excess(1. * h, h, 0), 0.2914, 1e-12);
  EXPECT_NEAR(end_face_layer_excess(4. * h, h, 1), 0.0227, 1e-12);
  EXPECT_NEAR(end_face_layer_excess(std::sqrt(1.5 * 2.) * h, h, 2), 0.5 * (0.0389 + 0.0290), 1e-12);
  for (double ratio = 0.5; ratio < 20.; ratio *= 1.17)
  {
    EXPECT_GT(end_face_layer_excess(ratio * h, h, 0), end_face_layer_excess(ratio * h, h, 1));
    EXPECT_GT(end_face_layer_excess(ratio * h, h, 1), end_face_layer_excess(ratio * h, h, 2));
    EXPECT_GT(end_face_layer_excess(ratio * h, h, 0),
              end_face_layer_excess(1.17 * ratio * h, h, 0));
  }
  EXPECT_NEAR(end_face_layer_excess(0.5 * h, h, 5), 0.120 / 2.5, 1e-12);
  EXPECT_NEAR(end_face_layer_excess(2. * h, h, 4), 0.120 / 8., 1e-12);
  EXPECT_EQ(end_face_layer_excess(2. * h, h, 5), 0.);
  EXPECT_EQ(end_face_layer_excess(0.2 * h, h, 0), 0.4144);
  EXPECT_NEAR(end_face_layer_excess(32. * h, h, 0), 0.5 * 0.0269, 1e-12);
}

// The layer kernel between a spur face's node planes (docs/ltca.md §3 "End faces"): its table's
// entries as K − I (interior at Δz/h 2: diagonal 1.6497, neighbour −0.3979; the end plane's own
// 1.7644 and a load on plane 1 read at the end −0.8484), the far end the mirror of the near
// one, nothing beyond the reach of 7 planes, log interpolation between tabled Δz/h and clamping
// outside. And its consistency with end_face_layer_excess, measured independently under a
// uniform load along the face: a uniform load is the sum over the loaded planes, so 2.7744 (the
// plane-strain layer of the kernel's load in Ê's units, the same FE) times Σ_loaded D(i, loaded)
// is plane i's excess — 0.1909, 0.0449, 0.0300 against Ê 0.1844, 0.0433, 0.0290 at Δz/h 2
// (+3.5, +3.8, +3.3 %: planes loaded beyond the fifth from the end are read there with the
// interior row, which the tool's full rows do not; 0.2 % of the layer; 5 % asserted), and an
// interior plane's row sums to plane strain (|Σ D| < 0.002: the interior row's sum 0.9989).
TEST(InfluenceCoefficients, LayerKernel)
{
  const double h = 0.6e-3;
  const unsigned int planes = 40;
  EXPECT_NEAR(layer_kernel_departure(2. * h, h, planes, 20, 20), 0.6497, 1e-12);
  EXPECT_NEAR(layer_kernel_departure(2. * h, h, planes, 21, 20), -0.3979, 1e-12);
  EXPECT_NEAR(layer_kernel_departure(2. * h, h, planes, 19, 20), -0.3979, 1e-12);
  EXPECT_NEAR(layer_kernel_departure(2. * h, h, planes, 0, 0), 0.7644, 1e-12);
  EXPECT_NEAR(layer_kernel_departure(2. * h, h, planes, 0, 1), -0.8484, 1e-12);
  EXPECT_NEAR(layer_kernel_departure(2. * h, h, planes, 39, 38), -0.8484, 1e-12);
  EXPECT_EQ(layer_kernel_departure(2. * h, h, planes, 20, 28), 0.);
  const double between = layer_kernel_departure(std::sqrt(8.) * h, h, planes, 20, 20);
  EXPECT_NEAR(between, 0.5 * (0.6497 + 0.7114), 1e-12);
  EXPECT_EQ(layer_kernel_departure(32. * h, h, planes, 3, 2),
            layer_kernel_departure(16. * h, h, planes, 3, 2));
  EXPECT_EQ(layer_kernel_departure(0.2 * h, h, planes, 3, 2),
            layer_kernel_departure(0.5 * h, h, planes, 3, 2));
  for (unsigned int i = 0; i < 3; ++i)
  {
    double sum = 0.;
    for (unsigned int loaded = 0; loaded < planes; ++loaded)
      sum += layer_kernel_departure(2. * h, h, planes, i, loaded);
    EXPECT_NEAR(2.7744 * sum / end_face_layer_excess(2. * h, h, i), 1., 0.05) << "plane " << i;
  }
  double interior = 0.;
  for (unsigned int loaded = 0; loaded < planes; ++loaded)
    interior += layer_kernel_departure(2. * h, h, planes, 20, loaded);
  EXPECT_LT(std::abs(interior), 2e-3);
}

// A tip edge's layer (docs/ltca.md §3 "Tip edges"): Flamant's wedge over the half-plane. The
// half-plane is the wedge of angle π (α_tip = π/2): 1. The quarter-plane (α_tip = 0: half-angle
// π/4, the load normal to one face, π/4 off the bisector): (π/4)·[1/(π/4 + ½) + 1/(π/4 − ½)] =
// 3.363 (Johnson 1985 §2.2). A blunter corner is stiffer; the layer scales by the factor.
TEST(InfluenceCoefficients, TipEdgeWedge)
{
  EXPECT_NEAR(tip_edge_wedge_factor(0.5 * M_PI), 1., 1e-14);
  EXPECT_NEAR(tip_edge_wedge_factor(0.),
              0.25 * M_PI * (1. / (0.25 * M_PI + 0.5) + 1. / (0.25 * M_PI - 0.5)), 1e-14);
  EXPECT_GT(tip_edge_wedge_factor(20. * M_PI / 180.), tip_edge_wedge_factor(32. * M_PI / 180.));
  EXPECT_GT(tip_edge_wedge_factor(32. * M_PI / 180.), 1.);
  const LayerBody steel{210e9, 0.3, 0.3e-3};
  LayerBody edge = steel;
  edge.wedge_factor = 1.4;
  EXPECT_NEAR(hertz_layer_compression(1e9, 1e-4, edge) / hertz_layer_compression(1e9, 1e-4, steel),
              1.4, 1e-14);
}

// Two identical pairs share the load equally; a pair whose gap exceeds the others' approach
// stays unloaded and the load follows from the loaded pair alone (exact by construction).
TEST(InfluenceCoefficients, ContactProblemByHand)
{
  MeshContactProblem problem;
  problem.compliance = {{4e-9, 1e-10}, {1e-10, 4e-9}};
  problem.separation = {0., 0.};
  problem.relative_radius = {6e-3, 6e-3};
  problem.total_force = 2000.;
  problem.face_width = 0.024;
  problem.pinion = problem.wheel = {210e9, 0.3, 0.3e-3};
  const MeshContactSolution equal = solve_mesh_contact(problem, {});
  EXPECT_NEAR(equal.force[0], 1000., 1e-6);
  EXPECT_NEAR(equal.force[1], 1000., 1e-6);
  const double near = equal.contact[0].approach;
  EXPECT_NEAR(equal.approach, 4.1e-9 * 1000. + near, 1e-15);

  problem.separation = {0., 50e-6}; // far beyond the ~10 µm approach
  const MeshContactSolution single = solve_mesh_contact(problem, {1000., 1000.});
  EXPECT_EQ(single.force[1], 0.);
  EXPECT_NEAR(single.force[0], 2000., 1e-9);
  const LineContact alone = hertz_line_contact(2000., 0.024, 6e-3, problem.pinion, problem.wheel);
  EXPECT_NEAR(single.approach, 4e-9 * 2000. + alone.approach, 1e-15);
}

// A Hertz near field next to a tip corner is continuous in F where its zone passes the corner's
// 6·a and 8·a (corner_shift's blend between its 32-point mean and its centre value): until session
// 42 it switched at 8·a and δ(F) jumped by ~1 % of the corner's excess, and Newton's method cannot
// converge across a jump (NewtonAcrossCornerSwitch). The steel pair's layer at h 0.3 mm,
// R 6 mm, a corner 0.2 mm from the contact: across each switch δ moves by its slope's c·ΔF to
// 1e-16 m (round-off of µm-sized approaches; the old switch jumped by 5·10⁻¹¹ m on the own pair).
TEST(InfluenceCoefficients, CornerNearFieldContinuous)
{
  LayerBody steel{210e9, 0.3, 0.3e-3};
  LayerBody corner = steel;
  corner.corner_offset = 0.2e-3;
  corner.corner_pressure_angle = 35. * M_PI / 180.;
  const double face = 0.02, radius = 6e-3, distance = 0.2e-3;
  const double e_star = 1. / (2. * (1. - 0.3 * 0.3) / 210e9);
  for (const double ratio : {6., 7., 8.})
  {
    // F at which a = d/ratio: a = √(4·F/b·R/(πE*)).
    const double a = distance / ratio;
    const double force = a * a * M_PI * e_star * face / (4. * radius);
    const double step = 1e-9 * force;
    const LineContact below = hertz_line_contact(force - step, face, radius, corner, steel);
    const LineContact above = hertz_line_contact(force + step, face, radius, corner, steel);
    EXPECT_NEAR(above.approach - below.approach, 2. * step * below.compliance, 1e-16)
        << "a = d/" << ratio;
  }
}

// A contact problem as a sweep built it (compliances, gaps, strips, corners; written by a build
// of main that printed it, tests/stiffness/data/<name>.txt, its origin in its header), solved
// from its stored start. It must meet the problem's own conditions (exact oracles, not stored
// results): the load balance, every loaded pair's compatibility, no unloaded pair penetrating.
namespace
{
void expect_stored_problem_solved(const std::string& name)
{
  std::ifstream in(test_support::source_dir() / "tests/stiffness/data" / (name + ".txt"));
  ASSERT_TRUE(in.good()) << name;
  MeshContactProblem problem;
  std::vector<double> start;
  const auto body = [](const std::vector<double>& v)
  {
    LayerBody b{v[0], v[1], v[2]};
    b.wedge_factor = v[3];
    b.corner_offset = v[4];
    b.corner_pressure_angle = v[5];
    return b;
  };
  std::string key;
  std::size_t count = 0;
  while (in >> key)
  {
    if (key.front() == '#')
    {
      std::getline(in, key);
      continue;
    }
    in >> count;
    std::vector<double> values(count);
    for (double& v : values)
    {
      std::string word; // "nan" is not read by operator>>
      in >> word;
      v = std::strtod(word.c_str(), nullptr);
    }
    // The per-unknown vectors by name; the rest below.
    const std::map<std::string, std::vector<double>*> vectors = {
        {"separation", &problem.separation},     {"relative_radius", &problem.relative_radius},
        {"lever_ratio", &problem.lever_ratio},   {"width", &problem.width},
        {"end_excess", &problem.end_excess},     {"pinion_wedge", &problem.pinion_wedge},
        {"wheel_wedge", &problem.wheel_wedge},   {"pinion_corner", &problem.pinion_corner},
        {"wheel_corner", &problem.wheel_corner}, {"start", &start}};
    if (const auto vector = vectors.find(key); vector != vectors.end())
      *vector->second = values;
    else if (key == "total_force" || key == "face_width")
      (key == "total_force" ? problem.total_force : problem.face_width) = values[0];
    else if (key == "pinion" || key == "wheel")
      (key == "pinion" ? problem.pinion : problem.wheel) = body(values);
    else if (key == "compliance")
      problem.compliance.push_back(values);
    else if (key == "strip")
      problem.strip.push_back({values[0], values[1], {}});
    else if (key == "gap")
      problem.strip.back().gap = values;
    else
      FAIL() << "unknown key " << key;
  }
  const std::size_t n = problem.separation.size();
  ASSERT_EQ(problem.compliance.size(), n);

  const MeshContactSolution solution = solve_mesh_contact(problem, start);
  std::cout << name << ": " << n << " unknowns, " << solution.newton_steps << " Newton steps, "
            << solution.active_set_passes << " active-set passes\n";
  double balance = -problem.total_force, worst = 0.;
  for (std::size_t j = 0; j < n; ++j)
  {
    ASSERT_GE(solution.force[j], 0.);
    balance += problem.lever_ratio[j] * solution.force[j];
    // g_j = λ_j·(e − s_j) − Σ_k C_jk F_k − δ_j(F_j): 0 where loaded, ≤ 0 where not, δ_j(0+)
    // the near field's start for an unloaded pair (a strip's smallest cell gap, Hertz 0). 1e-15
    // m either way: the solver's own round-off bound on µm-sized gaps (solve_mesh_contact's
    // entry test; measured 2.7e-21 m on newton_corner_switch).
    const bool strip = j < problem.strip.size() && !problem.strip[j].gap.empty();
    const double opening =
        strip ? *std::min_element(problem.strip[j].gap.begin(), problem.strip[j].gap.end()) : 0.;
    double gap = problem.lever_ratio[j] * (solution.approach - problem.separation[j]) -
                 (solution.force[j] > 0. ? solution.contact[j].approach : opening);
    for (std::size_t k = 0; k < n; ++k)
      gap -= problem.compliance[j][k] * solution.force[k];
    if (solution.force[j] > 0.)
      EXPECT_NEAR(gap, 0., 1e-15) << "pair " << j;
    else
      EXPECT_LE(gap, 1e-15) << "pair " << j;
    worst = std::max(worst, solution.force[j] > 0. ? std::abs(gap) : gap);
  }
  EXPECT_NEAR(balance, 0., 1e-10 * problem.total_force); // the step criterion, 1e-12·W a pair
  std::cout << "worst gap " << worst << " m, balance " << balance << " N\n";
}
} // namespace

// A position whose Newton failed (session 41, an own internal helical pair: z 23/71, m_n 2.5 mm,
// β 12°, b 20 mm, 16 layers, Q1, both tips rounded 0.5 / 0.4 mm, 8 µm pinion tip relief, C_β
// 5 µm on the ring, 80 N·m, the third of 8 positions; docs/ltca.md §3 "Rounded tips on helical
// pairs"). A tip-edge pair's Hertz near field sat where its zone passed 8·a from the corner, δ(F)
// jumped there (CornerNearFieldContinuous) and the Newton ended 100 steps short of its criterion.
TEST(InfluenceCoefficients, NewtonAcrossCornerSwitch)
{
  expect_stored_problem_solved("newton_corner_switch");
}

// A position whose active set cycled (session 43, the built-in pair at β ±15° with 6 µm tip
// reliefs, a Harris map's 61.75 N·m; docs/ltca.md "Torque lists"): an unloaded strip pair's
// linear gap (2.36e-10 m) lay between 0 and its strip's smallest cell gap (6.26e-10 m), where
// its near field starts (ltca_contact.cc unloaded_approach). Taken as penetrating it entered,
// carried nothing and left, pass after pass (exit 3).
TEST(InfluenceCoefficients, StripEntryAboveItsSmallestCellGap)
{
  expect_stored_problem_solved("strip_entry_window");
}

// The half-plane kernel of the strip integrates a Hertz pressure to the closed-form layer
// compression at x = 0 (both are Johnson 1985's plane-strain field: §2.2 integrated over the
// pressure against §2.6 on the axis), and the Hertz surface is the parabola x²/(2R) inside the
// zone (the contact's own condition). Midpoint rule over 4000 cells of the elliptic pressure:
// within 1e-4 relative (2026-12-02; not printed: the √ edges converge slowly); tolerance 1e-4.
TEST(InfluenceCoefficients, HalfPlaneKernelIntegratesHertz)
{
  const LayerBody steel{210e9, 0.3, 0.3e-3};
  const double force = 2000., width = 0.024, radius = 6.6e-3;
  const LineContact hertz = hertz_line_contact(force, width, radius, steel, steel);
  const double a = hertz.half_width, p0 = hertz.peak_pressure;
  const int n = 4000;
  const auto surface = [&](double x)
  {
    double u = 0.;
    for (int k = 0; k < n; ++k)
    {
      const double from = -a + 2. * a * k / n, to = from + 2. * a / n, mid = 0.5 * (from + to);
      u += 2. * p0 * std::sqrt(1. - mid * mid / (a * a)) *
           half_plane_cell_displacement(x, from, to, steel);
    }
    return u;
  };
  // hertz.approach also holds the depth points' spread-load shift (SpreadLoadDepthShift below).
  const double layer = hertz.approach - 2. * spread_load_depth_shift(force / width, a, steel);
  EXPECT_NEAR(surface(0.) / layer - 1., 0., 1e-4);
  // Inside the zone the two surfaces' difference to x = 0 is the gap x²/(2R) they close.
  const double x = 0.5 * a;
  EXPECT_NEAR((surface(0.) - surface(x)) / (x * x / (2. * radius)) - 1., 0., 1e-3);
}

// The depth point's shift under a spread load against its resultant at the axis
// (spread_load_depth_shift): the Hertz form's quadrature equals the strip's cell integrals over
// the elliptic pressure (midpoint rule, 4000 cells: within 1e-4, the √ edges); for a ≪ h it is
// −w·(a²/(4h²))·[(1−ν²) + (1+ν)]/(πE) (⟨ξ²⟩ = a²/4; at a/h = 0.01 the O((a/h)⁴) rest is 1e-4
// relative, tolerance 1e-3). Measured 2026-12-05: 0.14 % of the built-in pair's single-pair
// compliance at a/h = 0.27, 1.9 % of invariants case 15's (z 38/70 internal, m 1 mm) at a/h
// ≈ 0.7, where the model was 1.43 % soft without it and is 0.49 % stiff with it.
TEST(InfluenceCoefficients, SpreadLoadDepthShift)
{
  const LayerBody steel{210e9, 0.3, 0.3e-3};
  const double w = 2000. / 0.024, a = 0.2e-3; // N/m, m: a/h = 0.67
  const double p0 = 2. * w / (M_PI * a);
  const int n = 4000;
  double cells = 0.;
  for (int k = 0; k < n; ++k)
  {
    const double from = -a + 2. * a * k / n, to = from + 2. * a / n, mid = 0.5 * (from + to);
    cells += p0 * std::sqrt(1. - mid * mid / (a * a)) * spread_load_depth_cell(from, to, steel);
  }
  const double shift = spread_load_depth_shift(w, a, steel);
  EXPECT_LT(shift, 0.);
  EXPECT_NEAR(cells / shift - 1., 0., 1e-4);
  const double small = 3e-6, h = steel.matching_depth, nu = steel.poisson_ratio;
  EXPECT_NEAR(spread_load_depth_shift(w, small, steel) /
                      (-w * small * small / (4. * h * h) * ((1. - nu * nu) + (1. + nu)) /
                       (M_PI * steel.young_modulus)) -
                  1.,
              0., 1e-3);
}

// The strip with a parabolic gap is the Hertz contact: approach, half-width and peak pressure
// of the closed form (Johnson 1985 §4.3 with the layer of §2.6). 96 cells over ±3a: measured
// approach −0.018 %, half-width 0, peak −0.05 %, compliance +0.74 % (2026-12-02; piecewise-
// constant pressure); tolerances 0.1 %, a cell (10 %), 5 %, 2 %.
TEST(InfluenceCoefficients, StripWithParabolaIsHertz)
{
  const LayerBody steel{210e9, 0.3, 0.3e-3};
  const double force = 2000., width = 0.024, radius = 6.6e-3;
  const LineContact hertz = hertz_line_contact(force, width, radius, steel, steel);
  ContactStrip strip;
  strip.half_span = 3. * hertz.half_width;
  strip.relative_radius = radius;
  const int n = 96;
  for (int i = 0; i < n; ++i)
  {
    const double x = -strip.half_span + (i + 0.5) * 2. * strip.half_span / n;
    strip.gap.push_back(x * x / (2. * radius));
  }
  const LineContact solved = strip_line_contact(force, width, strip, steel, steel);
  std::cout << "strip/Hertz: approach " << solved.approach / hertz.approach - 1. << ", half-width "
            << solved.half_width / hertz.half_width - 1. << ", peak "
            << solved.peak_pressure / hertz.peak_pressure - 1. << ", compliance "
            << solved.compliance / hertz.compliance - 1. << "\n";
  EXPECT_NEAR(solved.approach / hertz.approach - 1., 0., 1e-3);
  EXPECT_NEAR(solved.half_width / hertz.half_width - 1., 0., 0.1);
  EXPECT_NEAR(solved.peak_pressure / hertz.peak_pressure - 1., 0., 0.05);
  EXPECT_NEAR(solved.compliance / hertz.compliance - 1., 0., 0.02);
}

// A rounded tip's arc under the involute's continuation (rounded_tip_removal): nothing up to the
// tip form roll, then two curves tangent there, radii r and ρ_F: x²/2·(1/r − 1/ρ_F) at the arc
// length x beyond it (x = (ρ² − ρ_F²)/(2r_b) along the involute), up to O((x/r)²) (measured
// 2026-12-05: 3.0e-5 at x/r 0.01, 3.9e-4 at 0.04; tolerance 1e-3 at 0.04).
TEST(InfluenceCoefficients, RoundedTipRemovalClosedForm)
{
  const double base_radius = 0.03, form_roll = 0.015, radius = 0.5e-3; // m
  EXPECT_EQ(influence::rounded_tip_removal(base_radius, form_roll, radius, 0.9 * form_roll), 0.);
  EXPECT_EQ(influence::rounded_tip_removal(base_radius, form_roll, radius, form_roll), 0.);
  EXPECT_EQ(influence::rounded_tip_removal(base_radius, form_roll, 0., 1.1 * form_roll), 0.);
  for (const double fraction : {0.01, 0.04})
  {
    const double x = fraction * radius;
    const double roll = std::sqrt(form_roll * form_roll + 2. * base_radius * x);
    const double closed = 0.5 * x * x * (1. / radius - 1. / form_roll);
    EXPECT_NEAR(influence::rounded_tip_removal(base_radius, form_roll, radius, roll) / closed, 1.,
                1e-3)
        << "x/r " << fraction;
  }
  double previous = 0.;
  for (int i = 1; i <= 20; ++i)
  {
    const double removal =
        influence::rounded_tip_removal(base_radius, form_roll, radius, form_roll + i * 2e-5);
    EXPECT_GT(removal, previous) << i;
    previous = removal;
  }
  // A ring's concave flank: its tip at smaller rolls, the arc's centre beyond the flank, so the
  // arc leaves the involute faster, x²/2·(1/r + 1/ρ_F).
  EXPECT_EQ(influence::rounded_tip_removal(base_radius, form_roll, radius, 1.1 * form_roll, true),
            0.);
  for (const double fraction : {0.01, 0.04})
  {
    const double x = fraction * radius;
    const double roll = std::sqrt(form_roll * form_roll - 2. * base_radius * x);
    const double closed = 0.5 * x * x * (1. / radius + 1. / form_roll);
    EXPECT_NEAR(influence::rounded_tip_removal(base_radius, form_roll, radius, roll, true) / closed,
                1., 1e-3)
        << "ring, x/r " << fraction;
  }
}

// A helical tip edge's kinematic gap beyond the path's end (tip_corner_gap): zero at the end,
// growing as the roll beyond it squared (two curves tangent there), a rounded tip's arc nearer
// than the sharp corner; at E on a ring the same (the ring's side of the line of action: until
// 2026-12-05 the point as far from O₂ was taken on the external wheel's side, and the pinion's tip
// edge against a ring came out millimetres away, never loaded).
TEST(InfluenceCoefficients, TipCornerGap)
{
  for (const bool ring : {false, true})
  {
    const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(
        ring ? planet_ring_pair() : GearMeshStiffnessSettings().scene.pair);
    const influence::PairFrame frame(pair);
    for (const bool at_start : {false, true})
    {
      const std::string where = std::string(ring ? "ring" : "external") + (at_start ? " A" : " E");
      EXPECT_NEAR(influence::tip_corner_gap(frame, 1e-9, at_start), 0., 1e-12) << where;
      const double near = influence::tip_corner_gap(frame, 0.1e-3, at_start);
      const double far = influence::tip_corner_gap(frame, 0.2e-3, at_start);
      EXPECT_GT(near, 0.) << where;
      EXPECT_LT(far, 20e-6) << where; // m: microns, not the far side of the line of action
      EXPECT_NEAR(far / near, 4., 0.2) << where;
      const double rounded = influence::tip_corner_gap(frame, 0.2e-3, at_start, 0.5e-3);
      EXPECT_GE(rounded, 0.) << where;
      EXPECT_LT(rounded, far) << where;
      EXPECT_NEAR(influence::tip_corner_gap(frame, 1e-9, at_start, 0.5e-3), 0., 1e-12) << where;
    }
  }
}

TEST(InfluenceCoefficients, ExternalPairMatchesExact)
{
  compare_with_exact(GearMeshStiffnessSettings(), 32, "external");
}

// Coulomb friction (docs/ltca.md §4 "Friction"): the pairs stick or slip as the exact path's
// contact lets them. μ 0.1, the built-in pair, 16 positions. Measured 2026-12-07: |Δk| 0.36 %,
// |ΔTE| 0.025 µm, |Δshare| 0.0055, the torque ratio 0.23 % (tolerance 0.7 %: 3×), the peak
// pressure −19.6 % (the exact nodal peak's, as frictionless: Tolerances), the root stresses up to
// 6.1 % away from the pitch point and 7.4 / 7.5 % (the wheel) at the two positions next to it,
// where both models let the pair stick and the model's stick force is larger than the exact
// path's (docs/ltca.md §4 "Friction": not yet found why). 10 % there, not 3×: that difference is
// the model's, deterministic, and stated; without friction in the model (before this test) the
// root stresses were 9.8 % and the torque ratio 2.1 % off.
TEST(InfluenceCoefficients, FrictionMatchesExact)
{
  Tolerances tolerance;
  tolerance.root_stress = 0.10;
  compare_with_exact(GearMeshStiffnessSettings(), 16, "friction", tolerance, 0.1, 0.007);
}

// Profile modifications (issue 47), measured against the exact rolling sweep. History: 1.49 % /
// 0.107 µm (external, long relief 10 µm both gears) and 5.86 % / 0.247 µm (internal, 8 µm on the
// planet) on 2026-12-01; with the turned force lines, the near-kink strip and the zone's mean
// slope (docs/ltca.md §5) 1.30 % / 0.095 µm and 6.04 % / 0.254 µm on 2026-12-02 (refused until
// then). Since 2026-12-05 each pair touches where its modified flanks' gap is smallest
// (geometry::touching_point), its FE coefficients read and its near field centred at that
// point of each flank, the depth points' spread-load shift in the near field
// (SpreadLoadDepthShift): external worst |Δk| 0.428 %, |ΔTE| 0.031 µm, |Δshare| 0.0018;
// internal 0.515 %, 0.024 µm, 0.0052 (without the spread-load shift 0.335 % and 0.365 %: it
// stiffens the built-in pairs by ~0.14 %). Tolerances: the 1 %, 0.1 µm, 1 % (≈ 2×, 3×,
// 2× the worst measured: the issue's own bounds); the peak pressure off the reliefs' starts as
// the unmodified cases' (Tolerances).
TEST(InfluenceCoefficients, ExternalTipReliefMatchesExact)
{
  GearMeshStiffnessSettings settings;
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(10e-6)};
  settings.scene.wheel_modifications.all_teeth = {test_support::long_relief(10e-6)};
  // The long reliefs start where single contact does: the pinion's at D, the wheel's at B.
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  Tolerances tolerance;
  tolerance.pinion_kinks = {pair.single_contact_end()};
  tolerance.wheel_kinks = {pair.single_contact_start()};
  compare_with_exact(settings, 32, "tip relief", tolerance);
}

// Rounded tips (r 0.5 mm on both gears of the built-in pair, T_d): the path ends at the tip form
// circles and the arcs beyond them enter the pairs' gap (rounded_tip_removal; docs/ltca.md "Tip
// rounding"). Measured 2026-12-05 against the exact rolling sweep on 64 positions: worst |Δk|
// 0.51 %, |ΔTE| 0.026 µm, |Δshare| 0.0030 (at 150 N·m ≈ 3·T_d: 0.79 %, 0.12 µm, 0.0050; the
// arcs left out of the gap, 0.45 % but the pressure where a contact reaches an arc 30-47 % below
// the exact path's). Since the wedge of the sharp corner the arc replaces (corner_layer_excess,
// 2026-12-05) 0.78 % at the position whose leaving pair touches on the pinion's arc (0.68 %
// before), +0.14 … +0.27 % elsewhere (+0.21 … +0.33 % before). Tolerances: the issue's, as for
// the reliefs; the exact peak on an arc is not compared (Tolerances::arc_peak_roll).
TEST(InfluenceCoefficients, TipRoundingMatchesExact)
{
  GearMeshStiffnessSettings settings;
  settings.scene.pair.pinion.tip_rounding_radius = 0.5e-3;
  settings.scene.pair.wheel.tip_rounding_radius = 0.5e-3;
  compare_with_exact(settings, 32, "tip rounding");
}

TEST(InfluenceCoefficients, InternalPairMatchesExact)
{
  compare_with_exact(planet_ring_settings(3., "influence_internal"), 16, "internal");
}

// Next to a ring's tip corner (docs/ltca.md "Next to a tip corner"): on 32 positions the first
// one (mesh position 0.0156, ℓ 0.115 mm past A) has the ring's sharp tip corner 0.036 mm of its
// flank from the contact's centre, inside the Hertz zone; without the corner's wedge
// (corner_layer_excess) the model was +1.14 % stiff there. The exact path at h_c 0.015 mm: its
// nodal peak there is not converged at the default 0.03 mm (522, 463, 431 MPa at h_c 0.03,
// 0.015, 0.0075 mm; k 613.45, 613.69, 613.85 N/µm with the command line's settings of this
// pair, measured 2026-12-05), 0.015 mm brings it within the tests' 25 % of the model's 387.
TEST(InfluenceCoefficients, InternalPairNextToRingTipCorner)
{
  GearMeshStiffnessSettings settings = planet_ring_settings(3., "influence_internal_32");
  settings.scene.mesh.contact_size = 0.015e-3; // m
  compare_with_exact(settings, 32, "internal 32");
}

// A ring's rounded tip (r 0.3 mm on the planet–ring pair, T_d): its concave flank's arc in the
// pairs' gap (rounded_tip_removal, `internal`), its wedge beyond the radius (corner_layer_excess
// at the sharp corner the arc replaces). The exact path at h_c 0.015 mm, where its nodal peaks
// settle (at 0.03 mm they scatter by ±8 % between neighbours, 496, 470, 436, 457, 391 MPa at
// positions 1–5, the model's 375 … 361 up to −24 %). Measured 2026-12-05, 32 positions: worst
// |Δk| 0.71 % (the first position, whose zone reaches the arc), |ΔTE| 0.022 µm, |Δshare| 0.0041,
// |Δp| 10.1 % off the tips; the peak on the arc 0.008 mm of roll from the exact one; position 7
// has the planet's sharp corner touching beyond E (1749 MPa, printed only). With the command
// line's settings r 0.3 mm 0.79 %, r 0.5 mm 0.60 % (the wedge left out for rounded tips: 1.04,
// 0.79 %). Tolerances: the issue's.
TEST(InfluenceCoefficients, InternalTipRoundingMatchesExact)
{
  GearMeshStiffnessSettings settings = planet_ring_settings(3., "influence_internal_rounding");
  settings.scene.pair.wheel.tip_rounding_radius = 0.3e-3; // m
  settings.scene.mesh.contact_size = 0.015e-3;            // m
  compare_with_exact(settings, 32, "internal rounding");
}

// The planet's rounded tip against the ring's concave flank (r 0.6 mm, 0.24·m): where the
// contact reaches the arc's start the force line turns by the slopes the strip's pressure sees,
// not by a Hertz ellipse's mean over the unmodified zone, which took the arc's steep slope at full
// weight (pair_line). Measured 2026-12-05 with the command line's settings of this pair, 32
// positions: −2.51 % at the arc's position before (the torque ratio +0.8 % off the kinematic one,
// the exact path's +0.03 %), −0.09 % now; the worst position −0.42 % (the first). This test's
// settings (rim 3·m, exact at h_c 0.015 mm): 0.38 % / 0.013 µm / 0.0041. Tolerances: the issue's.
TEST(InfluenceCoefficients, InternalPinionTipRoundingMatchesExact)
{
  GearMeshStiffnessSettings settings =
      planet_ring_settings(3., "influence_internal_pinion_rounding");
  settings.scene.pair.pinion.tip_rounding_radius = 0.6e-3; // m
  settings.scene.mesh.contact_size = 0.015e-3;             // m
  compare_with_exact(settings, 32, "internal pinion rounding");
}

TEST(InfluenceCoefficients, InternalTipReliefMatchesExact)
{
  GearMeshStiffnessSettings settings = planet_ring_settings(3., "influence_internal_relief");
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(8e-6)};
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  Tolerances tolerance;
  tolerance.pinion_kinks = {pair.single_contact_end()};
  compare_with_exact(settings, 16, "internal relief", tolerance);
}

// Issue 47: a Harris map's minimum at the same torque step as the exact path's. The built-in
// pair with 7 µm long reliefs on both gears (≈ its single-pair deflection at T_d = 49.4 N·m,
// tests/stiffness/test_micro_geometry.cc), 16 positions, T1 = 0.25 … 2·T_d in 8 steps, μ 0:
// the TE peak-to-peak of each torque within the 0.1 µm (a difference of two TEs each
// within it), the smallest at the same step. Measured 2026-12-05: p-p 2.948 … 0.602 µm (exact), the
// fast model within 0.017 µm at every step, both smallest at 1.75·T_d (0.602 / 0.593 µm); with
// each torque's own force lines (session 43, TorqueListEqualsEachTorqueAlone) within 0.016 µm,
// 0.602 / 0.597 µm.
TEST(InfluenceCoefficients, HarrisMapMinimumAsExact)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.;
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(7e-6)};
  settings.scene.wheel_modifications.all_teeth = {test_support::long_relief(7e-6)};
  for (const double f : {0.25, 0.5, 0.75, 1., 1.25, 1.5, 1.75, 2.})
    settings.torques.push_back(f * 49.4);
  StiffnessSweepSpec spec;
  spec.positions = 16;
  spec.mesh = SweepMesh::once;
  const StiffnessSweepResult exact =
      stiffness_sweep<2>(MPI_COMM_SELF, settings, spec, stiffness_work_stem("harris_exact"));
  settings.contact_model = ContactModel::influence_coefficients;
  const StiffnessSweepResult fast =
      influence_sweep<2>(MPI_COMM_SELF, settings, spec, stiffness_work_stem("harris_fast"));
  ASSERT_EQ(fast.by_torque.size(), exact.by_torque.size());
  std::vector<double> a, b;
  for (std::size_t t = 0; t < exact.by_torque.size(); ++t)
  {
    a.push_back(summarize_transmission_error(exact.by_torque[t]).peak_to_peak);
    b.push_back(summarize_transmission_error(fast.by_torque[t]).peak_to_peak);
    std::cout << "T1 = " << settings.torques[t] << " N·m: TE p-p " << a.back() * 1e6 << " / "
              << b.back() * 1e6 << " um\n";
    EXPECT_NEAR(b.back(), a.back(), 0.1e-6) << "torque step " << t;
  }
  EXPECT_EQ(std::min_element(b.begin(), b.end()) - b.begin(),
            std::min_element(a.begin(), a.end()) - a.begin());
}

// A torque list gives at each of its torques what that torque gives alone: the list solves a
// position at every torque in turn, each warm-started from the torque before, a single torque
// from the position before, and both must reach the one solution of the same problem. On
// modified flanks the force lines (levers, τ, the strip) depend on the load; until session 43
// they were built under the list's largest torque for every torque of the list, and the
// invariants generator's own gear (case 1 of seed 20261201, 9.9 µm reliefs on both) came out
// 3.7e-5 stiffer at T within T/2, T, 2T than at T alone. Here the built-in pair with long
// reliefs (kinks: strips) and a rounded pinion tip (an arc), 16 positions. Measured (session
// 43): worst relative difference 6.7e-16 (before: 8.8e-4 at 2·T_d, 8.6e-5 at T_d). Tolerance
// 1e-12: Newton's own stop (steps below 1e-12 of the load), round-off being all that remains.
TEST(InfluenceCoefficients, TorqueListEqualsEachTorqueAlone)
{
  GearMeshStiffnessSettings settings;
  settings.contact.friction_coefficient = 0.;
  settings.contact_model = ContactModel::influence_coefficients;
  settings.scene.pinion_modifications.all_teeth = {test_support::long_relief(10e-6)};
  settings.scene.wheel_modifications.all_teeth = {test_support::long_relief(10e-6)};
  settings.scene.pair.pinion.tip_rounding_radius = 0.5e-3;
  const std::vector<double> torques = {24.7, 49.4, 98.8}; // N·m: T_d/2, T_d, 2·T_d
  settings.torques = torques;
  StiffnessSweepSpec spec;
  spec.positions = 16;
  spec.mesh = SweepMesh::once;
  const StiffnessSweepResult listed =
      influence_sweep<2>(MPI_COMM_SELF, settings, spec, stiffness_work_stem("torque_list"));
  ASSERT_EQ(listed.by_torque.size(), torques.size());
  double worst = 0.;
  for (std::size_t t = 0; t < torques.size(); ++t)
  {
    settings.torques.clear();
    settings.pinion_torque = torques[t];
    const StiffnessSweepResult alone = influence_sweep<2>(
        MPI_COMM_SELF, settings, spec, stiffness_work_stem("torque_alone_" + std::to_string(t)));
    ASSERT_EQ(alone.positions.size(), listed.by_torque[t].size());
    for (std::size_t i = 0; i < alone.positions.size(); ++i)
    {
      const GearMeshStiffnessResult &a = alone.positions[i], &b = listed.by_torque[t][i];
      const double dk = std::abs(b.mesh_stiffness / a.mesh_stiffness - 1.);
      const double dte = std::abs(b.transmission_error / a.transmission_error - 1.);
      const double dshare = largest_share_difference(a, b);
      EXPECT_LE(dk, 1e-12) << "torque " << torques[t] << " position " << i;
      EXPECT_LE(dte, 1e-12) << "torque " << torques[t] << " position " << i;
      EXPECT_LE(dshare, 1e-12) << "torque " << torques[t] << " position " << i;
      worst = std::max({worst, dk, dte, dshare});
    }
  }
  std::cout << "torque list against each torque alone: worst relative difference " << worst << "\n";
}

// Every kind of profile modification on an own pair (z 23/61, m 4 mm, x 0.2/−0.1, b 30 mm,
// T1 300 N·m): the pinion with profile crowning C_α 6 µm and a parabolic tip relief 12 µm, the
// wheel with a linear root relief 8 µm and a profile slope f_Hα −5 µm (removed at its root), both
// relief lengths auto. Measured 2026-12-05 (24 positions): worst |Δk| 0.183 %, |ΔTE| 0.050 µm,
// |Δshare| 0.0003; tolerances the 1 %, 0.1 µm, 1 %.
TEST(InfluenceCoefficients, OwnPairEveryProfileModificationMatchesExact)
{
  using geometry::ModificationKind;
  GearMeshStiffnessSettings settings;
  for (const bool wheel : {false, true})
  {
    kinematics::GearSpec& gear = wheel ? settings.scene.pair.wheel : settings.scene.pair.pinion;
    gear.teeth = wheel ? 61 : 23;
    gear.normal_module = 4e-3;
    gear.profile_shift = wheel ? -0.1 : 0.2;
    gear.face_width = 30e-3;
    gear.tip_diameter = 0.;
  }
  settings.pinion_torque = 300.;
  const auto modification = [](ModificationKind kind, double amount, geometry::ReliefShape shape)
  {
    geometry::ToothModification m;
    m.kind = kind;
    m.amount = amount;
    m.length = -1.;
    m.shape = shape;
    return m;
  };
  settings.scene.pinion_modifications.all_teeth = {
      modification(ModificationKind::profile_crowning, 6e-6, geometry::ReliefShape::linear),
      modification(ModificationKind::tip_relief, 12e-6, geometry::ReliefShape::parabolic)};
  settings.scene.wheel_modifications.all_teeth = {
      modification(ModificationKind::root_relief, 8e-6, geometry::ReliefShape::linear),
      modification(ModificationKind::profile_slope, -5e-6, geometry::ReliefShape::linear)};
  compare_with_exact(settings, 24, "own pair modified");
}
