// Whole-revolution stiffness tables in the dynamics (issue 31, docs/faults.md): a table over
// P = z1 base pitches (one revolution of the faulty pinion), indexed over [0, P); its sidebands at
// h·f_m ± s·f_r, f_r = f_m/P; the response repeating once per revolution; rows without contact
// (a broken tooth) separating in the nonlinear law and refused by the linear one; the reader of
// the `gearstiff faults` table.
//
// The pair: the split-path pinion and one wheel (tests/dynamics/single_pair_train.h, z1 = 21,
// 1450 rpm, docs/references.md §1) with the published Cai pair curve (ε_α = 1.5, single-pair peak
// 327.2 N/µm, §1) sampled at N = 16 positions per pitch, (i + ½)/N as `gearstiff faults` writes;
// mesh damping ratio ζ = 0.05 (§10). The faulty tooth enters contact at X = 0 and meshes over
// X ∈ [0, ε_α): there its pair's stiffness is scaled (a crack) or removed (a broken tooth).
#include "dynamics/fault_signature.h"
#include "dynamics/stiffness_file.h"
#include "errors/errors.h"
#include "single_pair_train.h"
#include "tests/dynamics/work_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;
using namespace gearstiff::test_support;

namespace
{
constexpr unsigned int z1 = 21;        // the pinion of single_pair_train
constexpr unsigned int per_pitch = 16; // N
constexpr double contact_ratio = 1.5;  // ε_α of single_pair_train
const CaiParameters cai = cai_published_parameters(327.2e6);

// The mesh stiffness at X [base pitches after the faulty tooth entered]: Σ over the pairs in
// contact of the Cai pair stiffness; the faulty tooth's own pair (roll position X while
// X < ε_α) times `faulty_share` (1 healthy, 0 broken). NaN where no pair is left (broken tooth).
double revolution_stiffness(double x, double faulty_share)
{
  double k = 0.;
  bool contact = false;
  for (double p = std::fmod(x, 1.); p < contact_ratio; p += 1.)
  {
    const double share = std::abs(p - x) < 1e-12 ? faulty_share : 1.;
    k += share * cai_pair_stiffness(cai, p / contact_ratio);
    contact = contact || share > 0.;
  }
  return contact ? k : std::nan("");
}

// The revolution table: P·N rows; rows without contact carry 0 and the flag.
MeshStiffness revolution_table(double faulty_share, unsigned int period = z1)
{
  std::vector<double> x, k;
  std::vector<bool> lost;
  for (unsigned int i = 0; i < period * per_pitch; ++i)
  {
    x.push_back((i + 0.5) / per_pitch);
    const double value = revolution_stiffness(x.back(), faulty_share);
    lost.push_back(std::isnan(value));
    k.push_back(lost.back() ? 0. : value);
  }
  return MeshStiffness::table(x, k, "Mesh 1/stiffness", period, lost);
}

GearTrain train_with(const MeshStiffness& stiffness)
{
  // ζ = 0.05 of m_e = 1/(r1²/J1 + r2²/J2) and the mean stiffness (docs/references.md §10).
  const double mass = 1. / (r1 * r1 / J1 + r2 * r2 / J2);
  GearTrain train =
      single_pair_train(417e6, 2. * 0.05 * std::sqrt(stiffness.mean_stiffness(1.5) * mass));
  train.meshes[0].stiffness = stiffness;
  return train;
}

// Five revolutions of the pinion in the window (105 mesh periods), every step stored.
SimulationResult five_revolutions(const GearTrain& train)
{
  SimulationSettings settings;
  settings.window_periods = 5 * z1;
  return simulate(TorsionalModel(train), settings);
}

// max |δ(t) − δ(t − shift)| over the window's last revolution, over the peak-to-peak of δ.
double repeat_after(const SimulationResult& r, double shift)
{
  const std::vector<double>& t = r.trajectory.time;
  const std::vector<double>& d = r.meshes[0].deflection;
  const double revolution = z1 / r.meshes[0].mesh_frequency;
  double worst = 0., low = INFINITY, high = -INFINITY;
  for (std::size_t i = 1; i < t.size(); ++i)
  {
    if (t[i] < r.window_start)
      continue;
    low = std::min(low, d[i]);
    high = std::max(high, d[i]);
    if (t[i] < r.window_end - revolution)
      continue;
    const std::size_t j = std::upper_bound(t.begin(), t.end(), t[i] - shift) - t.begin();
    const double w = (t[i] - shift - t[j - 1]) / (t[j] - t[j - 1]);
    worst = std::max(worst, std::abs(d[i] - ((1. - w) * d[j - 1] + w * d[j])));
  }
  return worst / (high - low);
}
} // namespace

// A table of P identical pitches is the one-pitch table: the same values to round-off (x mod P
// and x mod 1 differ by whole pitches), the same mean and the same reversal.
TEST(FaultDynamics, RepeatedPitchTableEqualsOnePitchTable)
{
  const MeshStiffness repeated = revolution_table(1.);
  const MeshStiffness one = revolution_table(1., 1);
  EXPECT_EQ(repeated.period(), z1);
  EXPECT_EQ(one.period(), 1u);
  EXPECT_NEAR(repeated.mean_stiffness(1.5), one.mean_stiffness(1.5),
              1e-12 * one.mean_stiffness(1.5));
  const MeshStiffness back = repeated.reversed(1.5), one_back = one.reversed(1.5);
  for (double x = -3.; x < 50.; x += 0.0371)
  {
    const double k = one.stiffness(x, 1.5);
    EXPECT_NEAR(repeated.stiffness(x, 1.5), k, 1e-9 * k) << x;
    EXPECT_NEAR(back.stiffness(x, 1.5), one_back.stiffness(x, 1.5), 1e-9 * k) << x;
  }
}

// The faulty tooth's pair at 80 % (a root crack: the FE of docs/faults.md gives up to −5 % of
// the mesh stiffness for 1 mm; 20 % of the pair makes the lines stand clear of the floor below).
// The force spectrum's lines around f_m are found by scanning (local maxima above 1e-3 of the
// f_m line): their spacing is the pinion's rotation frequency f_r = n1/60 = 1450/60 Hz exactly
// (kinematics: z1·f_r = f_m = 507.5 Hz), to the round-off of the bin frequencies.
TEST(FaultDynamics, SidebandSpacingIsTheShaftFrequency)
{
  const SimulationResult r = five_revolutions(train_with(revolution_table(0.8)));
  const MeshResult& mesh = r.meshes[0];
  const double f_r = 1450. / 60.;
  EXPECT_NEAR(mesh.mesh_frequency, 21. * f_r, 1e-9);
  // The window spans whole revolutions (excitation_period): five.
  EXPECT_NEAR((r.window_end - r.window_start) * f_r, 5., 1e-9);
  const FaultSignature s = fault_signature(r, 0, z1);
  EXPECT_NEAR(s.revolution_frequency, f_r, 1e-12 * f_r);
  const double resolution = mesh.spectrum_frequency[1];
  const std::size_t centre = std::llround(mesh.mesh_frequency / resolution);
  const double reference = mesh.spectrum_amplitude[centre];
  std::vector<double> peaks;
  for (std::size_t k = centre - 17; k <= centre + 17; ++k)
  {
    const double a = mesh.spectrum_amplitude[k];
    if (a > 1e-3 * reference && a > mesh.spectrum_amplitude[k - 1] &&
        a > mesh.spectrum_amplitude[k + 1])
      peaks.push_back(mesh.spectrum_frequency[k]);
  }
  ASSERT_EQ(peaks.size(), 7u); // s = −3 … 3
  for (std::size_t i = 1; i < peaks.size(); ++i)
    EXPECT_NEAR(peaks[i] - peaks[i - 1], f_r, 1e-9 * f_r) << peaks[i];
  // The first sidebands (measured 2026-11-26: f_m line 3.199 N, f_m − f_r 0.0441 N, f_m + f_r
  // 0.0461 N; largest sideband 0.052 of the f_m line, impulse ratio 1.054): well above the
  // healthy floor of HealthyTableGivesNoSidebands (1e-4).
  const auto line_at = [&](int order)
  {
    for (const SidebandLine& l : s.lines)
      if (l.harmonic == 1 && l.order == order)
        return l;
    return SidebandLine{};
  };
  std::printf("f_m line %.4g N, f_m-f_r %.4g N, f_m+f_r %.4g N, largest ratio %.4g, impulse %.4g\n",
              line_at(0).force, line_at(-1).force, line_at(1).force, s.largest_sideband_ratio,
              s.impulse_ratio);
  EXPECT_GT(s.largest_sideband_ratio, 0.01);
  EXPECT_GT(line_at(-1).force, 0.01 * line_at(0).force);
  EXPECT_GT(line_at(1).force, 0.01 * line_at(0).force);
  EXPECT_GT(s.impulse_ratio, 1.01);
}

// The same table with a healthy faulty tooth (all pitches alike): no sideband h·f_m ± s·f_r
// rises above the floor of 1e-4 of the f_m line. What is there is the rest of the start-up
// transient: the window opens when the slowest mode has decayed to 1/1000 of it (simulation.h);
// measured 2026-11-26: 2.5e-5 of the f_m line, impulse ratio 1 + 1.6e-5 (floor: four times
// that). The 20 % crack of SidebandSpacingIsTheShaftFrequency gives 0.052, 2000 times more.
TEST(FaultDynamics, HealthyTableGivesNoSidebands)
{
  const SimulationResult healthy = five_revolutions(train_with(revolution_table(1.)));
  const FaultSignature s = fault_signature(healthy, 0, z1);
  std::printf("healthy largest sideband ratio %.3g, impulse %.6g\n", s.largest_sideband_ratio,
              s.impulse_ratio);
  EXPECT_LT(s.largest_sideband_ratio, 1e-4);
  EXPECT_NEAR(s.impulse_ratio, 1., 1e-4);
}

// The faulty response repeats after one revolution of the pinion over the window's last
// revolution (measured 2026-11-26: 2.5e-13 of the DTE's peak-to-peak, round-off: the step divides
// the mesh period, simulation.cc), not after one base pitch (0.41 of it); the healthy one
// repeats after every pitch (below 1e-6).
TEST(FaultDynamics, PeriodicResponseRepeatsOncePerRevolution)
{
  const SimulationResult faulty = five_revolutions(train_with(revolution_table(0.8)));
  const double mesh_period = 1. / faulty.meshes[0].mesh_frequency;
  const FaultSignature s = fault_signature(faulty, 0, z1);
  const double per_pitch_repeat = repeat_after(faulty, mesh_period);
  std::printf("revolution repeat %.3g, pitch repeat %.3g\n", s.revolution_repeat, per_pitch_repeat);
  EXPECT_LT(s.revolution_repeat, 1e-6);
  EXPECT_NEAR(repeat_after(faulty, z1 * mesh_period), s.revolution_repeat, 1e-9);
  EXPECT_GT(per_pitch_repeat, 0.01);
  const SimulationResult healthy = five_revolutions(train_with(revolution_table(1.)));
  EXPECT_LT(repeat_after(healthy, mesh_period), 1e-6);
}

// A broken tooth: no pair touches over its single zone X ∈ [0.5, 1) (k = 0 there, half-way to
// the neighbouring rows), the other pair carries alone in its double zones. The linear law
// refuses the table; the nonlinear one separates: zero force wherever k = 0, the teeth apart at
// least over that zone (0.5/21 of the time), and an impulse at re-engagement. Measured
// 2026-11-26: separated 9.4 % of the window, impulse ratio 404, K_v max 445 — the pinion turns
// freely under T1 while no pair touches and strikes when the next pair's table value returns
// (premature contact of the next pair outside the path is not in the table, docs/faults.md).
TEST(FaultDynamics, BrokenToothSeparatesInTheNonlinearLaw)
{
  const MeshStiffness broken = revolution_table(0.);
  EXPECT_TRUE(broken.loses_contact());
  EXPECT_NEAR(broken.first_lost_contact(), 0.5 + 0.5 / per_pitch, 1e-12);
  EXPECT_EQ(broken.stiffness(0.5 + 0.25 / per_pitch, 1.5), 0.); // half-way rule
  EXPECT_GT(broken.stiffness(0.5 - 0.25 / per_pitch, 1.5), 0.);
  GearTrain train = train_with(broken);
  try
  {
    const TorsionalModel linear(train);
    FAIL() << "no InputError";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "mesh1.stiffness"); // app maps it to "Mesh 1/stiffness"
    EXPECT_NE(std::string(e.what()).find("mesh model = nonlinear"), std::string::npos);
  }
  NonlinearMesh law;
  law.backlash = 100e-6;
  train.meshes[0].nonlinear = law;
  const SimulationResult r = five_revolutions(train);
  const MeshResult& mesh = r.meshes[0];
  for (std::size_t i = 0; i < mesh.force.size(); ++i)
  {
    if (mesh.stiffness[i] == 0.)
    {
      ASSERT_EQ(mesh.force[i], 0.) << r.trajectory.time[i];
    }
  }
  const FaultSignature s = fault_signature(r, 0, z1);
  std::printf("broken: separation fraction %.4g, impulse ratio %.4g, kv max %.4g, sideband ratio "
              "%.4g\n",
              mesh.separation_fraction, s.impulse_ratio, mesh.kv_max, s.largest_sideband_ratio);
  EXPECT_GE(mesh.separation_fraction, 0.5 / z1 - 2. / (per_pitch * z1));
  EXPECT_GT(s.impulse_ratio, 1.5);
}

// Bad tables: a flagged row with a stiffness, positions outside the period, no contact anywhere.
TEST(FaultDynamics, BadRevolutionTablesNameTheParameter)
{
  const auto refused = [](const std::vector<double>& x, const std::vector<double>& k,
                          unsigned int period, const std::vector<bool>& lost)
  {
    try
    {
      MeshStiffness::table(x, k, "Mesh 1/stiffness table", period, lost);
    }
    catch (const InputError& e)
    {
      return e.parameter() == "Mesh 1/stiffness table";
    }
    return false;
  };
  EXPECT_TRUE(refused({0., 1., 2.}, {4e8, 3e8, 4e8}, 3, {false, true, false}));
  EXPECT_TRUE(refused({0., 1., 3.}, {4e8, 3e8, 4e8}, 3, {}));
  EXPECT_TRUE(refused({0., 1., 2.}, {0., 0., 0.}, 3, {true, true, true}));
  EXPECT_FALSE(refused({0., 1., 2.}, {4e8, 0., 4e8}, 3, {false, true, false}));
}

namespace
{
// A `gearstiff faults` summary of the pair 21/57 (m 2 mm, a_w 78 mm) with the revolution table
// over `period` pitches (column value `stated`), 4 rows per pitch, k = 400 N/µm but 300 at the
// faulty tooth's first rows; row 3 without contact when `broken` (k written `broken_k`).
std::string write_faults_summary(unsigned int period, double stated, bool broken,
                                 double broken_k = 0.)
{
  const std::string path =
      dynamics_work_file("faults-" + std::to_string(period) + "-" + std::to_string(stated) +
                         (broken ? "-b" : "") + ".json");
  std::ofstream out(path);
  out << "{\n  \"command\": \"faults\",\n  \"text\": {},\n  \"values\": {\n";
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, double>>{{"pinion_teeth", 21},
                                                   {"wheel_teeth", 57},
                                                   {"transverse_module", 2},
                                                   {"centre_distance", 78},
                                                   {"contact_ratio", 1.5}})
    out << "    \"" << key << "\": {\"value\": " << value
        << ", \"unit\": \"-\", \"description\": \"\"},\n";
  out << "    \"revolution_period\": {\"value\": " << period
      << ", \"unit\": \"-\", \"description\": \"\"}\n  },\n  \"tables\": {\n"
      << "    \"revolution_stiffness\": {\"columns\": [\"mesh_position\", \"stiffness\", "
         "\"pinion_angle\", \"lost_contact\", \"period\"], \"units\": [\"-\", \"N/um\", \"deg\", "
         "\"-\", \"-\"], \"rows\": [";
  for (unsigned int i = 0; i < 4 * period; ++i)
  {
    const bool lost = broken && i == 3;
    out << (i ? ", " : "") << "[" << (i + 0.5) / 4 << ", "
        << (lost ? broken_k : (i < 6 ? 300. : 400.)) << ", 0, " << (lost ? 1 : 0) << ", " << stated
        << "]";
  }
  out << "]}\n  },\n  \"files\": []\n}\n";
  return path;
}

std::string refusal(const std::string& path)
{
  try
  {
    read_stiffness_file(path, "Train mesh 1/stiffness file");
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "Train mesh 1/stiffness file");
    return e.what();
  }
  return "";
}
} // namespace

// The reader takes the period from the table and the rows without contact from lost_contact.
TEST(FaultDynamics, ReadsRevolutionTable)
{
  const StiffnessFile file =
      read_stiffness_file(write_faults_summary(21, 21, true), "Train mesh 1/stiffness file");
  EXPECT_EQ(file.stiffness.period(), 21u);
  EXPECT_TRUE(file.stiffness.loses_contact());
  EXPECT_NEAR(file.stiffness.first_lost_contact(), 0.875, 1e-12);
  EXPECT_NEAR(file.stiffness.stiffness(0.125, 1.5), 300e6, 1e-3);
  EXPECT_NEAR(file.stiffness.stiffness(21. + 0.125, 1.5), 300e6, 1e-3); // periodic in 21
  EXPECT_NEAR(file.stiffness.stiffness(1.125 + 4., 1.5), 400e6, 1e-3);
  EXPECT_FALSE(file.transmission_error);
}

// A period that is neither gear's tooth count, or not the same on every row, and a row flagged
// without contact that carries a stiffness: one message naming the file's parameter.
TEST(FaultDynamics, RefusesRevolutionTableOfWrongPeriod)
{
  EXPECT_NE(refusal(write_faults_summary(20, 20, false)).find("neither gear's tooth count"),
            std::string::npos);
  EXPECT_NE(refusal(write_faults_summary(21, 20, false)).find("neither gear's tooth count"),
            std::string::npos);
  EXPECT_NE(refusal(write_faults_summary(21, 21, true, 250.)).find("flagged as lost contact"),
            std::string::npos);
  // 57 (the wheel's teeth) is a period too: a faulty wheel tooth's revolution.
  EXPECT_EQ(read_stiffness_file(write_faults_summary(57, 57, false), "p").stiffness.period(), 57u);
}
