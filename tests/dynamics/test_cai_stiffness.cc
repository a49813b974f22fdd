// The Cai stiffness curve and its calibration (docs/references.md §1, Cai 1995 as used by Reszuta &
// Drewniak 2015).
#include "dynamics/cai_stiffness.h"
#include "dynamics/mesh_stiffness.h"
#include "errors/errors.h"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace gearstiff;
using namespace gearstiff::dynamics;

namespace
{
// docs/references.md §1: k'_j = T1/(r_b1²·Δφ) = 49.4e3 N·mm / (24.667² mm² · 2.481e-4 rad),
// printed as 327 222 N/mm; the unrounded inputs give 327.24e6 N/m.
constexpr double single_pair_ansys = 327.2e6; // [N/m]
constexpr double contact_ratio = 1.5;         // docs/references.md §1: ε_α = 1.500

// The smallest and largest mesh stiffness (N/m) of the Cai curve with ε_α = 1.5, sampled at
// `samples` points of one period, in the double-contact zone (x < ε_α − 1 = 0.5) and the
// single-contact zone.
struct ZoneRanges
{
  double low_single = 1e30, high_single = 0., low_double = 1e30, high_double = 0.;
};

ZoneRanges zone_ranges(const CaiParameters& cai, int samples)
{
  ZoneRanges r;
  for (int i = 0; i < samples; ++i)
  {
    const double x = double(i) / samples;
    const double k = cai_mesh_stiffness(cai, x, contact_ratio);
    double& low = x < 0.5 ? r.low_double : r.low_single;
    double& high = x < 0.5 ? r.high_double : r.high_single;
    low = std::min(low, k);
    high = std::max(high, k);
  }
  return r;
}
} // namespace

TEST(CaiStiffness, PublishedShapePeaksAtOneAtMidEngagement)
{
  // The bracket −1.8 s² + 1.8 s + 0.55 has its vertex at s = 1/2 with value exactly 1 and is
  // 0.55 at engagement start and end (docs/references.md §1). Exact arithmetic: 1e-15 round-off.
  const CaiParameters cai = cai_published_parameters(1.);
  EXPECT_NEAR(cai_pair_stiffness(cai, 0.5), 1.0, 1e-15);
  EXPECT_NEAR(cai_pair_stiffness(cai, 0.0), 0.55, 1e-15);
  EXPECT_NEAR(cai_pair_stiffness(cai, 1.0), 0.55, 1e-15);
  EXPECT_EQ(cai_pair_stiffness(cai, 1.01), 0.);
}

TEST(CaiStiffness, MeshStiffnessRangesAndMean)
{
  // With ε_α = 1.5 the mesh alternates between two pairs (x ∈ [0, 0.5)) and one pair
  // (x ∈ [0.5, 1)). Single contact: s ∈ [1/3, 2/3] → bracket ∈ [0.95, 1]; double contact: the
  // sum of two brackets ∈ [1.5, 1.6] (closed forms, see the header). Mean = ε_α·(0.55 + 0.9 − 0.6)
  // = 1.275 peaks.
  const CaiParameters cai = cai_published_parameters(single_pair_ansys);
  const auto [low_single, high_single, low_double, high_double] = zone_ranges(cai, 1000);
  // The samples include the zone ends (x = 0, 0.5) and the vertices (x = 0.25, 0.75), where
  // the extremes lie, so only round-off remains.
  EXPECT_NEAR(low_single / single_pair_ansys, 0.95, 1e-12);
  EXPECT_NEAR(high_single / single_pair_ansys, 1.00, 1e-12);
  EXPECT_NEAR(low_double / single_pair_ansys, 1.50, 1e-12);
  EXPECT_NEAR(high_double / single_pair_ansys, 1.60, 1e-12);
  const MeshStiffness mesh = MeshStiffness::cai(cai, "test");
  EXPECT_NEAR(mesh.mean_stiffness(contact_ratio) / single_pair_ansys, 1.275, 1e-14);
}

TEST(CaiStiffness, PaperForceCheckValuesLieInTheirContactZones)
{
  // docs/references.md §1: with the bracket scaled so one pair's peak equals k'_j, the paper's
  // force check used 520.58e6 N/m (double contact) and 321.10e6 N/m (single contact); it does not
  // print the instants. The scaled curve must reach each value inside the zone the paper names, and
  // not in the other: the double-contact zone (x < ε_α − 1 = 0.5) spans [1.5, 1.6]·k'_j =
  // [490.8, 523.5] N/µm, the single-contact zone [0.95, 1]·k'_j = [310.8, 327.2] N/µm (the
  // closed forms of the test above), so both values are consistent with the stated scaling and
  // would not be if the paper had scaled the mesh (not the pair) stiffness to k'_j. Sampled at
  // 1e-4 of a period: the curve's slope is at most 2·1.8·k'_j per unit s, so a sampled range
  // misses its extremes by < 1e-3·k'_j, well inside the 2.6 and 5.9 N/µm margins to the range
  // ends.
  const auto [low_single, high_single, low_double, high_double] =
      zone_ranges(cai_published_parameters(single_pair_ansys), 10000);
  EXPECT_GT(520.58e6, low_double);
  EXPECT_LT(520.58e6, high_double);
  EXPECT_GT(321.10e6, low_single);
  EXPECT_LT(321.10e6, high_single);
  EXPECT_GT(520.58e6, high_single); // not reachable in single contact
  EXPECT_LT(321.10e6, low_double);  // nor this one in double contact
}

TEST(CaiFit, RecoversScaleFromMeshSamples)
{
  // Synthetic FE data generated from a known curve: the linear least-squares fit is exact up
  // to round-off (1e-12 relative).
  const CaiParameters truth = cai_published_parameters(350e6);
  std::vector<StiffnessSample> samples;
  for (int i = 0; i < 20; ++i)
  {
    const double x = i / 20.;
    samples.push_back({x, cai_mesh_stiffness(truth, x, contact_ratio)});
  }
  const CaiFit fit = fit_cai_parameters(samples, contact_ratio, StiffnessSampleKind::mesh, false);
  EXPECT_NEAR(fit.parameters.scale / 350e6, 1., 1e-12);
  EXPECT_LT(fit.rms_residual, 1e-6 * 350e6);
}

TEST(CaiFit, RecoversShapeAndScaleFromPairSamples)
{
  // A different, still positive shape (peak 1 at s = 0.4): fitted from noise-free single-pair
  // samples it must come back exactly (1e-10), normalised to peak 1.
  CaiParameters truth;
  truth.scale = 300e6;
  truth.shape = {0.6, 2.0, -2.5}; // peak at s = 0.4: 0.6 + 0.8 − 0.4 = 1.0
  std::vector<StiffnessSample> samples;
  for (int i = 0; i <= 30; ++i)
  {
    const double p = contact_ratio * i / 30. * 0.999;
    samples.push_back({p, cai_pair_stiffness(truth, p / contact_ratio)});
  }
  const CaiFit fit =
      fit_cai_parameters(samples, contact_ratio, StiffnessSampleKind::single_pair, true);
  EXPECT_NEAR(fit.parameters.scale / truth.scale, 1., 1e-10);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(fit.parameters.shape[i], truth.shape[i], 1e-10);
}

TEST(CaiFit, NoisyMeshSamplesGiveScaleWithinStatisticalError)
{
  // 200 mesh samples with 2 % Gaussian noise: the scale's standard error is about
  // 2 % · 1.3 / sqrt(200) / 1.28 ≈ 0.15 %; 1 % is a > 6σ bound (seeded, deterministic).
  const CaiParameters truth = cai_published_parameters(single_pair_ansys);
  std::mt19937 generator(42);
  std::normal_distribution<double> noise(0., 0.02);
  std::vector<StiffnessSample> samples;
  for (int i = 0; i < 200; ++i)
  {
    const double x = i / 200.;
    samples.push_back({x, cai_mesh_stiffness(truth, x, contact_ratio) * (1. + noise(generator))});
  }
  const CaiFit scale_only =
      fit_cai_parameters(samples, contact_ratio, StiffnessSampleKind::mesh, false);
  EXPECT_NEAR(scale_only.parameters.scale / truth.scale, 1., 0.01);
  const CaiFit full = fit_cai_parameters(samples, contact_ratio, StiffnessSampleKind::mesh, true);
  EXPECT_NEAR(full.parameters.scale / truth.scale, 1., 0.03);
  EXPECT_TRUE(full.shape_fitted);
}

TEST(CaiFit, RejectsBadSamples)
{
  EXPECT_THROW(fit_cai_parameters({}, contact_ratio, StiffnessSampleKind::mesh, false), InputError);
  EXPECT_THROW(fit_cai_parameters({{1.2, 4e8}}, contact_ratio, StiffnessSampleKind::mesh, false),
               InputError);
  EXPECT_THROW(fit_cai_parameters({{0.2, -4e8}}, contact_ratio, StiffnessSampleKind::mesh, false),
               InputError);
  // Three samples at one position cannot determine three shape coefficients.
  EXPECT_THROW(fit_cai_parameters({{0.2, 4e8}, {0.2, 4e8}, {0.2, 4e8}}, contact_ratio,
                                  StiffnessSampleKind::mesh, true),
               SolverFailure);
}

TEST(MeshStiffnessTable, InterpolatesPeriodicallyAndRejectsBadTables)
{
  const MeshStiffness table = MeshStiffness::table({0., 0.5}, {500e6, 300e6}, "t");
  // Linear between nodes and across the period end (x = 0.75 is halfway from 300e6 back to
  // 500e6); exact arithmetic on representable values.
  EXPECT_DOUBLE_EQ(table.evaluate(0.25, 1.5, 0.6).stiffness, 400e6);
  EXPECT_DOUBLE_EQ(table.evaluate(0.75, 1.5, 0.6).stiffness, 400e6);
  EXPECT_DOUBLE_EQ(table.evaluate(1.25, 1.5, 0.6).stiffness, 400e6);
  EXPECT_DOUBLE_EQ(table.mean_stiffness(1.5), 400e6);
  EXPECT_THROW(MeshStiffness::table({}, {}, "t"), InputError);
  EXPECT_THROW(MeshStiffness::table({0., 0.5, 0.4}, {1e8, 1e8, 1e8}, "t"), InputError);
  EXPECT_THROW(MeshStiffness::table({0., 0.5}, {1e8, -1e8}, "t"), InputError);
  EXPECT_THROW(MeshStiffness::constant(-1e8, "t"), InputError);
}

TEST(MeshStiffnessFriction, DirectionReversesAtThePitchPoint)
{
  // One pair in contact (x in the single-contact zone [0.5, 1) for ε_α = 1.5): the friction
  // direction is −1 before the pitch point (approach, p < ε_f) and +1 after it.
  const MeshStiffness mesh = MeshStiffness::constant(4e8, "t");
  const double approach = 0.58;
  EXPECT_EQ(mesh.evaluate(0.55, 1.5, approach).friction_direction, -1.);
  EXPECT_EQ(mesh.evaluate(0.65, 1.5, approach).friction_direction, 1.);
  // Two pairs: at x = 0.2 the pairs sit at 0.2 (approach) and 1.2 (recess): they cancel.
  EXPECT_EQ(mesh.evaluate(0.2, 1.5, approach).friction_direction, 0.);
}
