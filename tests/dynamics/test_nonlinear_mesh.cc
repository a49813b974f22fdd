// The nonlinear mesh law (dynamics/nonlinear_mesh.h, issue 29; Kahraman & Singh 1990 and
// Kahraman & Blankenship 1997, docs/references.md §7): quasi-static limit against an FE table,
// linear limit with preload, energy through impacts of a free backlash oscillator, the softening
// jumps of a piecewise-linear single-DOF pair against a harmonic balance derived below, up and
// down sweeps, the FE split, the train model, and bad input.
#include "dynamics/nonlinear_mesh.h"
#include "dynamics/simulation.h"
#include "dynamics/split_path_case.h"
#include "dynamics/stiffness_file.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "single_pair_train.h"
#include "tests/test_paths.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;
using namespace gearstiff::test_support;

namespace
{
const std::string fe_fixture =
    (source_dir() / "tests/dynamics/cli/stiffness_sun_planet.json").string();

// The split-path pinion and wheel (single_pair_train.h) with constant stiffness k [N/m], mesh
// damping ratio ζ of the relative mode (c = 2ζ·sqrt(k·m), m = 1/(r1²/J1 + r2²/J2)), the given
// nonlinear law, and input torque T1 (load balancing it).
GearTrain nonlinear_pair(double stiffness, double zeta, const NonlinearMesh& law,
                         double torque = T1)
{
  const double mass = 1. / (r1 * r1 / J1 + r2 * r2 / J2);
  GearTrain train = single_pair_train(stiffness, 2. * zeta * std::sqrt(stiffness * mass));
  train.gears[0].torque = torque;
  train.gears[1].torque = -torque * r2 / r1;
  train.meshes[0].nonlinear = law;
  return train;
}

double relative_mass()
{
  return 1. / (r1 * r1 / J1 + r2 * r2 / J2);
}

// Up (or down) sweep of the nonlinear pair over frequency ratios r = Ω/ω_n; returns DF (K_v
// max) per ratio in the order of `ratios`.
std::vector<double> sweep_ratios(const GearTrain& train, const std::vector<double>& ratios,
                                 SweepDirection direction, std::vector<double>& ordered_ratios)
{
  const double omega_n = std::sqrt(train.meshes[0].stiffness.mean_stiffness(1.5) / relative_mass());
  std::vector<double> speeds;
  for (const double r : ratios)
    speeds.push_back(r * omega_n / train.meshes[0].driver_teeth); // Ω = z·n (rad/s)
  SimulationSettings settings;
  settings.integrator.time_step = 1e-4; // reduced to 40 steps per mesh period by the sweep
  const SweepResult sweep = speed_sweep(train, settings, speeds, 40, direction, true);
  std::vector<double> df;
  ordered_ratios.clear();
  for (const SweepPoint& p : sweep.points)
  {
    df.push_back(p.kv_max);
    ordered_ratios.push_back(p.input_speed * train.meshes[0].driver_teeth / omega_n);
  }
  return df;
}

// Where the largest jump of DF between neighbouring points of a sweep lies (midpoint ratio),
// and its size.
std::pair<double, double> largest_jump(const std::vector<double>& ratios,
                                       const std::vector<double>& df)
{
  std::pair<double, double> jump{0., 0.};
  for (std::size_t i = 1; i < df.size(); ++i)
    if (std::abs(df[i] - df[i - 1]) > jump.second)
      jump = {0.5 * (ratios[i] + ratios[i - 1]), std::abs(df[i] - df[i - 1])};
  return jump;
}
} // namespace

TEST(NonlinearMesh, BacklashFunctionAndRegimes)
{
  // nonlinear_mesh.h: h(z) = z (z > 0), 0 (−2b ≤ z ≤ 0), z + 2b (z < −2b), with 2b = 10 µm.
  const double play = 10e-6;
  EXPECT_EQ(backlash_function(3e-6, play), 3e-6);
  EXPECT_EQ(backlash_function(-4e-6, play), 0.);
  EXPECT_DOUBLE_EQ(backlash_function(-12e-6, play), -2e-6);
  EXPECT_EQ(contact_regime(1e-9, play), ContactRegime::drive);
  EXPECT_EQ(contact_regime(0., play), ContactRegime::separated);
  EXPECT_EQ(contact_regime(-10.5e-6, play), ContactRegime::back);
}

TEST(NonlinearMesh, SplitOfTheFeTableReproducesTheLoadedTe)
{
  // The fixture is the 12-position 2D sweep of the 18/30 pair at T1 = 50 N·m (recipe in
  // tests/dynamics/cli/stiffness_sun_planet.prm): k = W/s at every row with W = T1/r_b1 =
  // 50/0.0169144671741 = 2956.07 N, so the split e = s − W/k is zero (round-off) and the mean of
  // s is the table's: trapezoids of the 12 uniformly spaced rows = their arithmetic mean,
  // 108.2323/12 = 9.01936 µm (the fixture's transmission_error column, summed by hand).
  const StiffnessFile file = read_stiffness_file(fe_fixture, "f");
  ASSERT_TRUE(file.transmission_error.has_value());
  EXPECT_NEAR(file.transmission_error->load, 50. / 0.0169144671741, 0.01);
  EXPECT_TRUE(file.transmission_error->unloaded.is_zero());
  EXPECT_LT(file.transmission_error->largest_unloaded_error, 1e-15);
  EXPECT_NEAR(file.transmission_error->mean_loaded_error, 9.01936e-6, 1e-11);

  // A table with k ≠ W/s gives e = s − W/k: s = 10 µm everywhere, k = 400 and 500 N/µm,
  // W = mean(k·s) = 4500 N — more than 1e-3 apart, so refused as two load cases; with
  // k·s equal but s offset by 1 µm on one row neither.
  EXPECT_THROW(split_loaded_transmission_error({0., 0.5}, {400e6, 500e6}, {10e-6, 10e-6}, {}, "p"),
               InputError);
  const LoadedTransmissionErrorSplit split =
      split_loaded_transmission_error({0., 0.5}, {400e6, 400e6}, {10e-6, 10e-6}, {}, "p");
  EXPECT_NEAR(split.load, 4000., 1e-9);
  EXPECT_TRUE(split.unloaded.is_zero());

  // With the table's unloaded TE (a modified pair: `gearstiff stiffness` writes k = W/(s − e)),
  // e is the table's and W = k·(s − e): s = 12 and 10 µm, e = 2 and 0 µm, k = 400 N/µm → W =
  // 4000 N on both rows (exact), e(0) = 2 µm; the same rows without e are two load cases.
  const LoadedTransmissionErrorSplit modified =
      split_loaded_transmission_error({0., 0.5}, {400e6, 400e6}, {12e-6, 10e-6}, {2e-6, 0.}, "p");
  EXPECT_NEAR(modified.load, 4000., 1e-9);
  EXPECT_NEAR(modified.unloaded.value(0.), 2e-6, 1e-15);
  EXPECT_NEAR(modified.unloaded.value(0.5), 0., 1e-15);
  EXPECT_NEAR(modified.largest_unloaded_error, 2e-6, 1e-15);
  EXPECT_THROW(split_loaded_transmission_error({0., 0.5}, {400e6, 400e6}, {12e-6, 10e-6}, {}, "p"),
               InputError);
}

TEST(NonlinearMesh, QuasiStaticLimitReproducesTheFeLoadedTe)
{
  // Far below resonance (pinion 100 rpm: mesh 30 Hz against the pair's 4.2 kHz) the nonlinear
  // model with the FE table must follow the quasi-static solution δ = e + W/k(x) = s(x): its
  // mean DTE equals the FE table's mean loaded TE and DF = max F/W → 1. The pinion torque is the
  // FE load case's, T1 = 50 N·m on r_b1 = 16.9144671741 mm (fixture values).
  const StiffnessFile file = read_stiffness_file(fe_fixture, "f");
  const double rb1 = 16.9144671741e-3, rb2 = rb1 * 30. / 18.;
  NonlinearMesh law;
  law.backlash = 100e-6;
  law.transmission_error = file.transmission_error->unloaded;
  GearTrain train;
  train.gears = {{"pinion", J1, 50.}, {"wheel", J2, -50. * rb2 / rb1}};
  Mesh mesh;
  mesh.driver_base_radius = rb1;
  mesh.driven_base_radius = rb2;
  mesh.driver_teeth = 18;
  mesh.contact_ratio = file.pair.contact_ratio;
  mesh.approach_ratio = 0.5;
  mesh.stiffness = file.stiffness;
  mesh.damping = 2. * 0.05 * std::sqrt(file.stiffness.mean_stiffness(1.6) * 0.5); // ζ ≈ 0.05
  mesh.nonlinear = law;
  train.meshes = {mesh};
  train.input_speed = 100. * M_PI / 30.;
  const TorsionalModel model(train);
  SimulationSettings settings;
  settings.integrator.time_step = 10e-6;
  settings.window_periods = 4;
  settings.keep_time_series = false;
  const SimulationResult result = simulate(model, settings);
  const MeshResult& r = result.meshes[0];
  // Quasi-static: δ = W/k(x) with k piecewise linear between the 12 FE rows. Its mean over the
  // cycle (integrated here) lies 0.381 % below the rows' trapezoid mean of s, the interpolation
  // of k instead of 1/k across the two 385 ↔ 265 N/µm steps (the issue allows 0.5 %). The
  // dynamic mean must equal that quasi-static mean closely: 1e-4 bounds the dynamic correction
  // (order (f_mesh/f_n)² = 5e-5) and the window's remainder of the start-up transient.
  double compliance = 0.;
  const int samples = 100000;
  for (int i = 0; i < samples; ++i)
    compliance += 1. / file.stiffness.stiffness((i + 0.5) / samples, file.pair.contact_ratio);
  const double quasi_static_mean = file.transmission_error->load * compliance / samples;
  EXPECT_NEAR(quasi_static_mean / file.transmission_error->mean_loaded_error, 1. - 0.00381, 1e-5);
  EXPECT_NEAR(r.mean_deflection / quasi_static_mean, 1., 1e-4);
  EXPECT_NEAR(r.mean_deflection / file.transmission_error->mean_loaded_error, 1., 0.005);
  // DF → 1: the overshoot where k ramps 385 → 265 N/µm within 0.08 pitch (2.7 ms, ~11 periods
  // of the 4.2 kHz mode) is small; 1 % bounds it (regression: measured 2026-11-26, 0.67 %).
  EXPECT_NEAR(r.kv_max, 1., 0.01);
  EXPECT_EQ(r.separations, 0u);
  EXPECT_EQ(r.separation_fraction, 0.);
  std::printf("quasi-static: mean DTE / FE mean TE - 1 = %.3e, DF - 1 = %.3e\n",
              r.mean_deflection / file.transmission_error->mean_loaded_error - 1., r.kv_max - 1.);
}

TEST(NonlinearMesh, LinearLimitWithPreloadReproducesLinear)
{
  // The split path (docs/references.md §1: Cai curve, friction μ = 0.01) at 1450 rpm carries
  // 1000 N per mesh on ~2.5 µm of deflection. With the published c = 100 N·s/m the start-up
  // transient drives δ below zero (the linear force stays positive through c·δ̇), so the mesh
  // damping is raised to 2000 N·s/m (ζ ≈ 0.1): then δ > 0 all the time (asserted), the drive
  // flanks never separate, and the nonlinear law with e = 0 is the linear law exactly
  // (F = k·(δ − 0) + c·(δ̇ − 0), nonlinear_mesh.h): the runs agree to the last bits.
  SplitPathCase data = split_path_case();
  data.mesh_damping = 2000.;
  const GearTrain linear_train = split_path_train(
      data, MeshStiffness::cai(cai_published_parameters(data.single_pair_stiffness), "k"));
  GearTrain nonlinear_train = linear_train;
  NonlinearMesh law;
  law.backlash = 50e-6;
  for (Mesh& mesh : nonlinear_train.meshes)
    mesh.nonlinear = law;
  SimulationSettings settings;
  const SimulationResult linear = simulate(TorsionalModel(linear_train), settings);
  const SimulationResult nonlinear = simulate(TorsionalModel(nonlinear_train), settings);
  ASSERT_EQ(linear.trajectory.size(), nonlinear.trajectory.size());
  for (std::size_t m = 0; m < 2; ++m)
  {
    ASSERT_GT(
        *std::min_element(linear.meshes[m].deflection.begin(), linear.meshes[m].deflection.end()),
        0.);
    EXPECT_NEAR(nonlinear.meshes[m].kv_max, linear.meshes[m].kv_max, 1e-12);
    EXPECT_NEAR(nonlinear.meshes[m].mean_force, linear.meshes[m].mean_force, 1e-9);
    EXPECT_EQ(nonlinear.meshes[m].separations, 0u);
    for (std::size_t i = 0; i < linear.meshes[m].force.size(); i += 97)
      EXPECT_NEAR(nonlinear.meshes[m].force[i], linear.meshes[m].force[i], 1e-9) << i;
  }
  EXPECT_EQ(nonlinear.trajectory.cost.located_switches, 0u);
}

TEST(NonlinearMesh, FreeBacklashOscillatorConservesEnergyThroughImpacts)
{
  // No torque, no damping, constant k, e = 0, free play 2b = 20 µm. The relative coordinate
  // z = δ obeys m·z̈ = −k·h(z) (m = 1/(r1²/J1 + r2²/J2)): starting at z = 0 moving into the gap
  // at v0 it flies 2b/v0, stays on the back flank half a period π/ω (ω² = k/m, a linear spring
  // returns with −v0), flies back and stays π/ω on the drive flank: period
  // T = 2·(2b/v0 + π/ω), back impacts at t = 2b/v0 + n·T (derivation: free flight + half
  // cycles). Energy ½·m·v0² (plus the rigid rotation's, constant) is conserved.
  const double k = 2e8, play = 20e-6, v0 = 0.05;
  NonlinearMesh law;
  law.backlash = play;
  GearTrain train = nonlinear_pair(k, 0., law, 0.);
  const TorsionalModel model(train);
  const double m = relative_mass(), omega = std::sqrt(k / m);
  const double period = 2. * (play / v0 + M_PI / omega);
  const std::vector<double> angle{0., 0.}, velocity{-v0 / r1, 0.}; // ż = r1·φ̇1 = −v0

  const auto run = [&](double step, std::vector<double>& impacts)
  {
    IntegratorSettings settings;
    settings.time_step = step;
    settings.end_time = 10. * period;
    settings.record_stride = 1000000;
    impacts.clear();
    settings.contact_observer = [&](double t, unsigned int, ContactRegime, ContactRegime to)
    {
      if (to == ContactRegime::back)
        impacts.push_back(t);
    };
    const Trajectory trajectory = integrate(model, angle, velocity, settings);
    (void)trajectory;
    // The final state is not stored with this stride; integrate again to the same end with
    // an observer that keeps the last state.
    std::vector<double> last_angle, last_velocity;
    settings.observer = [&](double, const double* phi, const double* omega_)
    {
      last_angle.assign(phi, phi + 2);
      last_velocity.assign(omega_, omega_ + 2);
    };
    settings.contact_observer = nullptr;
    integrate(model, angle, velocity, settings);
    const double e0 = model.total_energy(0., angle.data(), velocity.data());
    return std::abs(model.total_energy(settings.end_time, last_angle.data(), last_velocity.data()) -
                    e0) /
           e0;
  };
  std::vector<double> coarse_impacts, fine_impacts;
  const double h = 2. * M_PI / omega / 40.; // 40 steps per contact period
  const double coarse = run(h, coarse_impacts);
  const double fine = run(h / 2., fine_impacts);
  ASSERT_EQ(fine_impacts.size(), 10u);
  for (std::size_t n = 0; n < fine_impacts.size(); ++n)
    // The switch is located on the step's cubic Hermite interpolant (O(h⁴) in time); what
    // accumulates is RK4's phase error in the contact half-cycles, relative (ωh)⁴/120 = 3e-7 at
    // 80 steps per contact period: 1e-6·T per cycle bounds it (measured 5.5e-7·T per cycle).
    EXPECT_NEAR(fine_impacts[n], play / v0 + n * period, (n + 1) * 1e-6 * period) << n;
  // Energy: conserved to RK4's accuracy (measured 2.6e-6 over 10 cycles at 80 steps per contact
  // period), and converging at order ≥ 3 (RK4 is 4 on the smooth pieces; each located switch
  // adds an O(h⁴)-in-time error of the cut; measured ratio 29, order 4.9).
  EXPECT_LT(fine, 1e-5);
  EXPECT_GT(coarse / fine, 8.);
  std::printf("energy error %.3e (h) %.3e (h/2), ratio %.1f\n", coarse, fine, coarse / fine);
}

// Harmonic balance of the piecewise-linear pair with one-sided separation (the no-back-contact
// regime of Kahraman & Singh 1990, docs/references.md §7), derived here:
//   m·z̈ + c·ż·[z > 0] + k·h(z) = W + m·a·Ω²·sin Ωt,
// from m·δ̈ = W − F with z = δ − e, e = a·sin Ωt (the TE harmonic), h(z) = max(z, 0) while
// z > −2b. Try z = z_m + A·cos θ, θ = Ωt + φ; contact while cos θ > −z_m/A = cos α, α ∈ (0, π].
// The mean of h over a cycle: (1/π)·(z_m·α + A·sin α); its cos θ coefficient
// (1/π)·∫_{−α}^{α}(z_m + A cos θ)·cos θ dθ = (A/π)·(α − sin α cos α) with z_m = −A cos α; the
// damping c·ż·[contact] has the same factor g(α) = (α − sin α cos α)/π on −A·Ω·sin θ and mean 0.
// Balance of the mean: k·A·(sin α − α cos α)/π = W  →  A = π·δ_s/(sin α − α cos α), δ_s = W/k.
// Balance of the fundamental (r = Ω/ω_n, ω_n² = k/m, ζ = c/(2·sqrt(k·m)), q = a/A):
//   (g − r²)² + (2ζ·g·r)² = (q·r²)²,  a quadratic in u = r²:
//   (1 − q²)·u² + (4ζ²g² − 2g)·u + g² = 0.
// Full contact (α = π, g = 1, A = δ_s) joins the linear branch A = a·r²/sqrt((1 − r²)² + (2ζr)²).
// With light damping the branch of α < π leans to low r (softening): sweeping up, the linear
// branch holds until A = δ_s, where the teeth start to separate and the response jumps up (r_up,
// exact: the linear response is a pure sine); sweeping down, the separated branch holds down to
// its smallest r over α ∈ [α*, π] (α* where the quadratic's discriminant vanishes, the tip of the
// peak), where it jumps down (r_down, within the one-harmonic approximation).
double harmonic_balance_down_jump(double zeta, double a_over_static)
{
  double smallest = 1e9;
  for (int i = 100000; i > 0; --i)
  {
    const double alpha = M_PI * i / 100000.;
    const double g = (alpha - std::sin(alpha) * std::cos(alpha)) / M_PI;
    const double amplitude = M_PI / (std::sin(alpha) - alpha * std::cos(alpha));
    const double q = a_over_static / amplitude;
    const double c2 = 1. - q * q, c1 = 4. * zeta * zeta * g * g - 2. * g, c0 = g * g;
    const double discriminant = c1 * c1 - 4. * c2 * c0;
    if (discriminant < 0.)
      break; // past the tip α*
    smallest = std::min(smallest, std::sqrt((-c1 - std::sqrt(discriminant)) / (2. * c2)));
  }
  return smallest;
}

double linear_separation_onset(double zeta, double a_over_static)
{
  // a·r² = sqrt((1 − r²)² + (2ζr)²) on r < 1, by bisection.
  double low = 0.3, high = 1.;
  for (int i = 0; i < 100; ++i)
  {
    const double r = 0.5 * (low + high);
    const double f =
        a_over_static * r * r - std::sqrt((1. - r * r) * (1. - r * r) + 4. * zeta * zeta * r * r);
    (f > 0. ? high : low) = r;
  }
  return high;
}

TEST(NonlinearMesh, SofteningJumpsMatchHarmonicBalance)
{
  // ζ = 0.02, TE harmonic a = 0.05·δ_s at mesh order 1, free play 10·δ_s (never reached: the
  // HB's largest swing below zero is 0.4·δ_s). From the derivation above: r_up = 0.98571,
  // r_down = 0.95629 (tip at α = 2.37, A = 1.31·δ_s).
  const double k = 2e8, zeta = 0.02, a_ratio = 0.05;
  const double static_deflection = (T1 / r1) / k;
  NonlinearMesh law;
  law.backlash = 10. * static_deflection;
  law.transmission_error.add_harmonic({1., a_ratio * static_deflection, 0.}, "h");
  const GearTrain train = nonlinear_pair(k, zeta, law);
  const double r_up = linear_separation_onset(zeta, a_ratio);
  const double r_down = harmonic_balance_down_jump(zeta, a_ratio);
  EXPECT_NEAR(r_up, 0.98571, 1e-5);
  EXPECT_NEAR(r_down, 0.95629, 1e-4);

  std::vector<double> ratios;
  for (double r = 0.93; r <= 1.0201; r += 0.0025)
    ratios.push_back(r);
  std::vector<double> up_ratios, down_ratios;
  const std::vector<double> up = sweep_ratios(train, ratios, SweepDirection::up, up_ratios);
  const std::vector<double> down = sweep_ratios(train, ratios, SweepDirection::down, down_ratios);
  const auto [up_jump, up_size] = largest_jump(up_ratios, up);
  const auto [down_jump, down_size] = largest_jump(down_ratios, down);
  std::printf("jumps: up at r = %.4f (HB %.4f, size %.3f), down at r = %.4f (HB %.4f, size "
              "%.3f)\n",
              up_jump, r_up, up_size, down_jump, r_down, down_size);
  // The sweep resolves r to 0.0025: the jump lies within half a spacing of the HB value plus
  // the one-harmonic error for the moderately clipped tip (α = 2.37): measured 2026-11-26 up at
  // 0.9862 (HB 0.9857), down at 0.9637 (HB 0.9563, 0.8 % above). The up jump starts where the
  // teeth first separate, which the HB's onset gives exactly (no clipped-tip error): 0.0015, three
  // times the measured 0.0005 and just above half a spacing (0.00125), the sweep's resolution.
  EXPECT_NEAR(up_jump, r_up, 0.0015);
  EXPECT_NEAR(down_jump, r_down, 0.01);
  // Measured 2026-11-26: up jump 0.20 (onto the separated branch's rising part), down 0.65.
  EXPECT_GT(up_size, 0.1);
  EXPECT_GT(down_size, 0.3);
}

TEST(NonlinearMesh, UpAndDownSweepsDifferWhenLightlyDampedOnly)
{
  // ζ = 0.02 (a = 0.05·δ_s, as above): between the jumps the two sweeps are on different
  // branches, DF differing by more than 0.2. ζ = 0.2 with a = 0.5·δ_s separates too (HB peak
  // 1.34·δ_s) but its separated branch never leans past the onset (derivation above: smallest r
  // of the branch = r_up = 0.9015), so the response is single-valued and both sweeps agree to
  // the steady-state tolerance (the window starts after a 1/1000 decay: 1e-3 relative).
  const double k = 2e8, static_deflection = (T1 / r1) / k;
  std::vector<double> ratios;
  for (double r = 0.85; r <= 1.1001; r += 0.01)
    ratios.push_back(r);
  for (const auto& [zeta, a_ratio] : {std::pair{0.02, 0.05}, std::pair{0.2, 0.5}})
  {
    NonlinearMesh law;
    law.backlash = 10. * static_deflection;
    law.transmission_error.add_harmonic({1., a_ratio * static_deflection, 0.}, "h");
    const GearTrain train = nonlinear_pair(k, zeta, law);
    std::vector<double> up_ratios, down_ratios;
    const std::vector<double> up = sweep_ratios(train, ratios, SweepDirection::up, up_ratios);
    std::vector<double> down = sweep_ratios(train, ratios, SweepDirection::down, down_ratios);
    std::reverse(down.begin(), down.end());
    double largest = 0., peak = 0.;
    for (std::size_t i = 0; i < up.size(); ++i)
    {
      largest = std::max(largest, std::abs(up[i] - down[i]));
      peak = std::max(peak, up[i]);
    }
    std::printf("zeta %.2f: largest |DF up - DF down| = %.4f (peak DF %.3f)\n", zeta, largest,
                peak);
    if (zeta < 0.1)
      EXPECT_GT(largest, 0.2);
    else
    {
      EXPECT_GT(peak, 1.3); // it does separate: DF above the linear 1 + a/δ_s·r²/(2ζ)…
      EXPECT_LT(largest, 2e-3 * peak);
    }
  }
}

TEST(NonlinearMesh, TrainMeshesCarryTheirOwnLaw)
{
  // The built-in planetary set (sun 20 input, 3 planets 10 on carrier c, ring −40 fixed) with
  // the nonlinear law on the sun–planet mesh only: every copy of it is nonlinear and its static
  // forces are kinematics' (the law is linear in drive contact, e = 0).
  kinematics::GearTrainText text = kinematics::builtin_train("planetary");
  text.planets = "p: c*3";
  text.inertias = "s: 2e-4, p: 5e-5, c: 4e-3, r: 1e-2";
  text.masses = "p: 0.4";
  TrainDynamicsInput input;
  input.spec = kinematics::parse_gear_train(text);
  input.input_torque = 20.;
  TrainMeshDynamics mesh{MeshStiffness::constant(3e8, "k"), 50., 0., 0., 0., {}, {}, {}, {}};
  input.meshes = {mesh, mesh};
  NonlinearMesh law;
  law.backlash = 40e-6;
  input.meshes[0].nonlinear = law;
  const TrainModel model = build_train_model(input);
  unsigned int nonlinear = 0;
  for (const Mesh& m : model.train.meshes)
    nonlinear += m.nonlinear.has_value();
  EXPECT_EQ(nonlinear, 3u);
  const TorsionalModel torsional(model.train);
  EXPECT_TRUE(torsional.has_nonlinear_meshes());
  SimulationSettings settings;
  settings.window_periods = 10;
  settings.keep_time_series = false;
  const SimulationResult result = simulate(torsional, settings);
  for (const MeshResult& r : result.meshes)
    EXPECT_NEAR(r.mean_force / r.nominal_force, 1., 1e-3) << r.name;
}

TEST(NonlinearMesh, BadInput)
{
  NonlinearMesh law;
  law.backlash = -1e-6;
  try
  {
    check_nonlinear_mesh(law, 0);
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "mesh1.backlash");
  }
  // A TE varying by 2·6 µm with 10 µm of free play would jam the pair.
  law.backlash = 10e-6;
  law.transmission_error.add_harmonic({1., 6e-6, 0.}, "h");
  try
  {
    check_nonlinear_mesh(law, 0);
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "mesh1.transmission_error");
  }
  // Order 10 at 40 steps per mesh period is 4 steps per period of the harmonic (< 8).
  NonlinearMesh fast;
  fast.backlash = 100e-6;
  fast.section = "Mesh 1";
  fast.transmission_error.add_harmonic({10., 1e-6, 0.}, "h");
  const GearTrain train = nonlinear_pair(2e8, 0.05, fast);
  const TorsionalModel model(train);
  SimulationSettings settings;
  settings.integrator.time_step = 1. / (model.mesh_position_rate(0) * 40.);
  try
  {
    simulate(model, settings);
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "mesh1.transmission_error_harmonics");
  }
  // HHT-α (linearised) cannot represent the switches.
  settings.integrator.type = IntegratorType::hht_alpha;
  settings.integrator.time_step = 1e-6;
  NonlinearMesh plain;
  plain.backlash = 10e-6;
  const TorsionalModel plain_model(nonlinear_pair(2e8, 0.05, plain));
  EXPECT_THROW(simulate(plain_model, settings), InputError);
}
