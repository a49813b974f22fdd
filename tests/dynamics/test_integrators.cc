// The integrators against the analytic response of a constant-stiffness pair, their observed
// convergence orders, energy conservation, and the RK4 stability limit.
#include "dynamics/integrators.h"
#include "dynamics/split_path_case.h"
#include "errors/errors.h"
#include "tests/dynamics/single_pair_train.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;
using namespace gearstiff::test_support;

namespace
{
// The split-path pinion and one wheel (single_pair_train.h) with constant stiffness k: a
// single pair whose relative coordinate δ = r1·φ1 − r2·φ2 obeys
//   m_e·δ̈ + c·δ̇ + k·δ = T1/r1,   1/m_e = r1²/J1 + r2²/J2,
// because the wheel's load T1·r2/r1 balances the input (derivation in torsional_model.h).
constexpr double k = 400e6;

// Step response from rest of the damped oscillator above [m].
double analytic_deflection(double t, double damping)
{
  const double me = 1. / (r1 * r1 / J1 + r2 * r2 / J2);
  const double wn = std::sqrt(k / me);
  const double zeta = damping / (2. * std::sqrt(k * me));
  const double wd = wn * std::sqrt(1. - zeta * zeta);
  const double static_deflection = T1 / r1 / k;
  return static_deflection *
         (1. - std::exp(-zeta * wn * t) *
                   (std::cos(wd * t) + zeta / std::sqrt(1. - zeta * zeta) * std::sin(wd * t)));
}

// Largest deviation from the analytic δ(t) over the run, relative to the static deflection.
double max_error(const IntegratorSettings& settings, double damping)
{
  const TorsionalModel model(single_pair_train(k, damping));
  const Trajectory trajectory = integrate(model, {0., 0.}, {0., 0.}, settings);
  double error = 0.;
  for (std::size_t i = 0; i < trajectory.size(); ++i)
  {
    const double* phi = trajectory.angle_at(i);
    const double deflection = r1 * phi[0] - r2 * phi[1];
    error =
        std::max(error, std::abs(deflection - analytic_deflection(trajectory.time[i], damping)));
  }
  return error / (T1 / r1 / k);
}

IntegratorSettings settings_for(IntegratorType type, double step, double end_time)
{
  IntegratorSettings settings;
  settings.type = type;
  settings.time_step = step;
  settings.end_time = end_time;
  settings.hht_alpha = 0.;
  return settings;
}

// Errors at three steps, each half the one before: each observed order log2(e(h)/e(h/2)) lies
// within `tolerance` of `order`.
void expect_observed_order(IntegratorType type, const double (&steps)[3], double order,
                           double tolerance)
{
  double errors[3];
  for (int i = 0; i < 3; ++i)
    errors[i] = max_error(settings_for(type, steps[i], 2e-3), 100.);
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(std::log2(errors[i] / errors[i + 1]), order, tolerance)
        << "errors " << errors[i] << " / " << errors[i + 1];
}
} // namespace

TEST(Integrators, Rk4MatchesAnalyticStepResponseAtThePublishedStep)
{
  // The published step 5 µs (docs/references.md §1) resolves the 6.9 kHz pair mode with h·ω = 0.22;
  // RK4's phase error after 2 ms (ωt = 87 rad) is then about (hω)⁴/120·ωt ≈ 1.6e-3 of the
  // amplitude (= the static deflection for a step response), so 2e-3 bounds it.
  const double error = max_error(settings_for(IntegratorType::rk4, 5e-6, 2e-3), 100.);
  EXPECT_LT(error, 2e-3);
}

TEST(Integrators, Rk4ConvergesAtFourthOrder)
{
  // Halving the step must divide the error by 2⁴ = 16: observed orders within ±0.2 of 4 (the
  // asymptotic range starts well above these steps, h·ω ≤ 0.17).
  expect_observed_order(IntegratorType::rk4, {4e-6, 2e-6, 1e-6}, 4., 0.2);
}

TEST(Integrators, HhtAlphaIsSecondOrderAndAccurate)
{
  // HHT-α with α = 0 is the trapezoidal rule: second order (observed within ±0.15 of 2).
  expect_observed_order(IntegratorType::hht_alpha, {2e-6, 1e-6, 0.5e-6}, 2., 0.15);
  // α = −0.05 adds numerical damping of high modes but stays accurate at 1 µs: (hω)² ≈ 2e-3
  // phase error per radian, 14 periods → a few per cent at most.
  IntegratorSettings damped = settings_for(IntegratorType::hht_alpha, 1e-6, 2e-3);
  damped.hht_alpha = -0.05;
  EXPECT_LT(max_error(damped, 100.), 0.05);
}

TEST(Integrators, AdaptiveRungeKuttaMeetsItsTolerance)
{
  // Dormand–Prince 5(4) with a local tolerance of 1e-9 of the state: the global error over
  // 14 periods stays below 1e-6 of the static deflection, at far fewer steps than 1 µs RK4.
  IntegratorSettings settings = settings_for(IntegratorType::adaptive_rk, 10e-6, 2e-3);
  settings.relative_tolerance = 1e-9;
  EXPECT_LT(max_error(settings, 100.), 1e-6);
  const TorsionalModel model(single_pair_train(k, 100.));
  const Trajectory trajectory = integrate(model, {0., 0.}, {0., 0.}, settings);
  EXPECT_GT(trajectory.cost.steps, 0u);
  EXPECT_LT(trajectory.cost.steps, 2000u);
  EXPECT_GE(trajectory.cost.function_evaluations, 6 * trajectory.cost.steps);
}

TEST(Integrators, EnergyIsConservedWithoutDamping)
{
  // No damping, no friction, constant stiffness: E = ½φ̇ᵀMφ̇ + ½kδ² − Tᵀφ is an invariant.
  // The trapezoidal rule (HHT α = 0) conserves it exactly for a linear system (round-off only,
  // 1e-9 of the strain-energy scale over 10⁴ steps); RK4 loses (hω)⁶/72 per step, at 1 µs
  // (hω = 0.043) about 1e-10 per step, so < 1e-5 over 5·10⁴ steps.
  const TorsionalModel model(single_pair_train(k, 0.));
  const double energy_scale = 0.5 * k * std::pow(T1 / r1 / k, 2);
  for (const auto& [type, step, tolerance] : {std::tuple{IntegratorType::hht_alpha, 5e-6, 1e-9},
                                              std::tuple{IntegratorType::rk4, 1e-6, 1e-5}})
  {
    const Trajectory trajectory =
        integrate(model, {0., 0.}, {0., 0.}, settings_for(type, step, 0.05));
    const double e0 = model.total_energy(0., trajectory.angle_at(0), trajectory.velocity_at(0));
    double drift = 0.;
    for (std::size_t i = 0; i < trajectory.size(); ++i)
      drift =
          std::max(drift, std::abs(model.total_energy(trajectory.time[i], trajectory.angle_at(i),
                                                      trajectory.velocity_at(i)) -
                                   e0));
    EXPECT_LT(drift / energy_scale, tolerance) << integrator_name(type);
  }
}

TEST(Integrators, Rk4AboveTheStabilityLimitIsRefusedOrDetected)
{
  // The split-path train with constant stiffness, where the frozen-coefficient estimate is
  // exact: 2 % above the limit RK4's amplification is |R| ≈ 1.07 per step, so the vibration
  // energy passes the 10⁶ divergence threshold within a few hundred steps.
  const SplitPathCase data = split_path_case();
  const TorsionalModel model(split_path_train(data, MeshStiffness::constant(450e6, "k")));
  const double limit = model.rk4_step_limit();
  IntegratorSettings settings = settings_for(IntegratorType::rk4, 1.02 * limit, 0.05);

  try
  {
    integrate(model, {0., 0., 0.}, {0., 0., 0.}, settings);
    FAIL() << "a step above the limit was accepted without the override";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "simulation.time_step");
  }

  settings.allow_unstable_step = true;
  try
  {
    integrate(model, {0., 0., 0.}, {0., 0., 0.}, settings);
    FAIL() << "divergence not detected";
  }
  catch (const SolverFailure& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("diverged"), std::string::npos) << message;
    EXPECT_NE(message.find("stability limit"), std::string::npos) << message;
  }

  // The implicit method at the same step stays bounded: the mesh force never exceeds twice the
  // nominal one (a suddenly applied load overshoots to at most 2× without damping).
  settings.type = IntegratorType::hht_alpha;
  settings.hht_alpha = -0.05;
  const Trajectory implicit = integrate(model, {0., 0., 0.}, {0., 0., 0.}, settings);
  for (std::size_t i = 0; i < implicit.size(); ++i)
    for (unsigned int m = 0; m < 2; ++m)
      EXPECT_LT(std::abs(model
                             .mesh_response(m, implicit.time[i], implicit.angle_at(i),
                                            implicit.velocity_at(i))
                             .force),
                2. * model.nominal_force(m));

  // Just below the limit RK4 runs through.
  settings.type = IntegratorType::rk4;
  settings.time_step = 0.98 * limit;
  EXPECT_NO_THROW(integrate(model, {0., 0., 0.}, {0., 0., 0.}, settings));
}
