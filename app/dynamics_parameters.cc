#include "app/dynamics_parameters.h"

#include "app/kinematics_parameters.h"
#include "app/parameter_patterns.h"
#include "app/train_parameter_entries.h"
#include "app/units.h"
#include "dynamics/split_path_case.h"
#include "dynamics/stiffness_file.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace gearstiff::app
{
namespace
{
constexpr double micrometre = 1e-6;
constexpr double newton_per_mm = 1e3;            // N/mm → N/m
constexpr double newton_per_mm_micrometre = 1e9; // N/(mm·µm) → N/m²
// Mesh damping as a ratio (issue 25): ζ = 0.05, inside the 0.03–0.17 of the gear-mesh damping
// ratios reported in the literature (docs/references.md §10); the published split-path meshes
// keep their c_g = 100 N·s/m (§1). Applied by apply_damping_ratios.
constexpr double default_damping_ratio = 0.05;

std::string gear_section(unsigned int i)
{
  return "Gear " + std::to_string(i + 1);
}
std::string mesh_section(unsigned int m)
{
  return "Mesh " + std::to_string(m + 1);
}
std::string train_mesh_section(unsigned int m)
{
  return "Train mesh " + std::to_string(m + 1);
}

// The comma-separated entries of `text` that are not blank.
std::vector<std::string> comma_entries(const std::string& text)
{
  std::vector<std::string> entries;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ','))
    if (entry.find_first_not_of(" \t") != std::string::npos)
      entries.push_back(entry);
  return entries;
}

// "x:k, x:k, ..." with x in base pitches and k in N/mm.
void parse_table(const std::string& text, const std::string& parameter,
                 std::vector<double>& positions, std::vector<double>& stiffness)
{
  for (const std::string& entry : comma_entries(text))
  {
    const auto colon = entry.find(':');
    try
    {
      if (colon == std::string::npos)
        throw std::invalid_argument("no colon");
      std::size_t used = 0;
      const double x = std::stod(entry.substr(0, colon));
      const double k = std::stod(entry.substr(colon + 1), &used);
      if (entry.substr(colon + 1 + used).find_first_not_of(" \t") != std::string::npos)
        throw std::invalid_argument("trailing text");
      positions.push_back(x);
      stiffness.push_back(k * newton_per_mm);
    }
    catch (const std::exception&)
    {
      throw InputError(parameter,
                       "entry '" + entry + "' is not 'position:stiffness' (base pitches : N/mm)");
    }
  }
}
// ---- issue 29: the nonlinear mesh entries of "Mesh n" and "Train mesh n" ----
void declare_nonlinear_mesh_entries(ParameterHandler& prm, bool train_mesh)
{
  const std::string gear = train_mesh ? "the mesh's first gear" : "the driver";
  prm.declare_entry("backlash", "100", Double(),
                    "mesh model nonlinear: free play 2b between drive and back flanks along the "
                    "line of action, the normal backlash j_bn (µm); j_bn = j_t·cos alpha_wt from "
                    "the circular backlash j_t, or -(A_sn1 + A_sn2)·cos alpha_n from the "
                    "tooth-thickness allowances (spur gears, nominal centre distance)");
  prm.declare_entry("transmission error file", "", Anything(),
                    "mesh model nonlinear: summary.json of a `gearstiff stiffness` sweep of the "
                    "same pair (checked): its loaded TE s(x) and stiffness k(x) give the "
                    "unloaded TE e = s - W/k (zero for k = W/s); empty: none");
  prm.declare_entry("profile deviation", "0", Double(0.),
                    "mesh model nonlinear: profile form deviation f_f, a sinusoid of this "
                    "peak-to-peak at the mesh frequency in the unloaded TE (µm)");
  prm.declare_entry("pitch deviation", "0", Double(0.),
                    "mesh model nonlinear: cumulative pitch deviation F_p of " + gear +
                        ", a once-per-revolution sinusoid of this peak-to-peak (µm)");
  prm.declare_entry("transmission error harmonics", "", Anything(),
                    "mesh model nonlinear: further TE sinusoids 'order: amplitude[: phase], "
                    "...' (mesh orders, µm, degrees)");
}

// The raw entries of declare_nonlinear_mesh_entries (the caller knows the pair to check a file
// against and the teeth for the pitch deviation's order).
struct NonlinearMeshEntries
{
  double backlash = 0.; // [m]
  std::string file;
  double profile_deviation = 0.; // [m] peak-to-peak
  double pitch_deviation = 0.;   // [m] peak-to-peak
  std::vector<dynamics::ExcitationHarmonic> harmonics;
};

NonlinearMeshEntries parse_nonlinear_mesh_entries(ParameterHandler& prm, const std::string& section)
{
  NonlinearMeshEntries entries;
  entries.backlash = prm.get_double("backlash") * micrometre;
  entries.file = prm.get("transmission error file");
  entries.profile_deviation = prm.get_double("profile deviation") * micrometre;
  entries.pitch_deviation = prm.get_double("pitch deviation") * micrometre;
  const std::string parameter = section + "/transmission error harmonics";
  for (const std::string& entry : comma_entries(prm.get("transmission error harmonics")))
  {
    std::istringstream in(entry);
    std::vector<double> numbers;
    std::string field;
    while (std::getline(in, field, ':'))
    {
      std::size_t used = 0;
      try
      {
        numbers.push_back(std::stod(field, &used));
      }
      catch (const std::exception&)
      {
        used = 0;
      }
      if (used == 0 || field.find_first_not_of(" \t", used) != std::string::npos)
        numbers.assign(4, 0.);
    }
    if (numbers.size() < 2 || numbers.size() > 3)
      throw InputError(parameter,
                       "entry '" + entry + "' is not 'order: amplitude[: phase]' (-, µm, degrees)");
    entries.harmonics.push_back(
        {numbers[0], numbers[1] * micrometre, numbers.size() == 3 ? numbers[2] * degree : 0.});
  }
  return entries;
}

// The law of one mesh: backlash, the TE from the file (its pair checked by `check_pair`, which
// throws naming the file parameter) and from the deviations; `teeth` of the gear whose
// revolution the pitch deviation follows.
dynamics::NonlinearMesh
build_nonlinear_mesh(const NonlinearMeshEntries& entries, const std::string& section,
                     unsigned int teeth,
                     const std::function<void(const dynamics::StiffnessFile&)>& check_pair)
{
  dynamics::NonlinearMesh mesh;
  mesh.section = section;
  mesh.backlash = entries.backlash;
  if (!entries.file.empty())
  {
    const std::string parameter = section + "/transmission error file";
    const dynamics::StiffnessFile file = dynamics::read_stiffness_file(entries.file, parameter);
    if (!file.transmission_error)
      throw InputError(parameter, "'" + entries.file +
                                      "' has no loaded transmission error (the stiffness_sweep "
                                      "table of `gearstiff stiffness` in mode sweep)");
    check_pair(file);
    mesh.transmission_error = file.transmission_error->unloaded;
  }
  const std::string harmonics = section + "/transmission error harmonics";
  mesh.transmission_error.add_harmonic({1., 0.5 * entries.profile_deviation, 0.},
                                       section + "/profile deviation");
  mesh.transmission_error.add_harmonic(
      {1. / std::max(1u, teeth), 0.5 * entries.pitch_deviation, 0.}, section + "/pitch deviation");
  for (const dynamics::ExcitationHarmonic& h : entries.harmonics)
    mesh.transmission_error.add_harmonic(h, harmonics);
  dynamics::check_nonlinear_mesh(mesh, section);
  return mesh;
}

// A "Mesh n" pair is known by its driver's teeth and base radii: the file's pinion must be
// the driver (teeth equal, base radius within 1 %: the split path rounds r_b1 to 24.7 mm) and
// its wheel z1·r_b2/r_b1 teeth.
void check_numbered_mesh_pair(const dynamics::StiffnessFile& file, const dynamics::Mesh& mesh,
                              const std::string& parameter)
{
  const double pinion_base_radius = file.pair.pinion_base_radius;
  const long wheel_teeth =
      std::lround(mesh.driver_teeth * mesh.driven_base_radius / mesh.driver_base_radius);
  const bool same = file.pair.pinion_teeth == static_cast<int>(mesh.driver_teeth) &&
                    file.pair.wheel_teeth == wheel_teeth &&
                    std::abs(pinion_base_radius / mesh.driver_base_radius - 1.) < 0.01;
  if (!same)
    throw InputError(parameter, "the table belongs to another pair: file " + file.pair.describe() +
                                    ", this mesh z " + std::to_string(mesh.driver_teeth) + "/" +
                                    std::to_string(wheel_teeth) + ", r_b1 " +
                                    format_number(mesh.driver_base_radius / mm, 6) + " mm");
}
// ---- end of issue 29 entries ----

// The entries a mesh needs whatever describes its gears: stiffness source, damping, friction.
// Shared by "Mesh n" (gears and meshes) and "Train mesh n" (Train description).
// `train_mesh` adds the source 'file' (a stiffness result of the FE commands): only a Train
// mesh knows its gears' teeth and modules, which the file must match.
void declare_mesh_physics(ParameterHandler& prm, double stiffness, double damping, double friction,
                          double driver_arm, double driven_arm, bool train_mesh)
{
  prm.declare_entry(
      "stiffness source", "cai",
      Selection(train_mesh ? "cai|constant|table|cai fit|file" : "cai|constant|table|cai fit"),
      std::string("mesh stiffness: 'cai' (Cai curve, peak = stiffness), 'constant', "
                  "'table' (k(x) table), 'cai fit' (Cai curve least-squares fitted "
                  "to the table)") +
          (train_mesh ? ", 'file' (FE k(x) table or calibrated Cai curve of "
                        "'stiffness file')"
                      : ""));
  if (train_mesh)
    prm.declare_entry("stiffness file", "", Anything(),
                      "summary.json written by `gearstiff stiffness` (mode sweep: its k(x) "
                      "table) or `gearstiff cai` (its calibrated Cai curve) with -o, for the "
                      "same pair (teeth, module, centre distance checked); path relative to the "
                      "working directory");
  prm.declare_entry("stiffness",
                    train_mesh ? std::string("auto") : format_number(stiffness / newton_per_mm, 10),
                    Anything(),
                    std::string("constant: the mesh stiffness; cai: one pair's peak k'_j; a "
                                "number in N/mm, or with its unit: '327.2 N/µm' (the unit of "
                                "every stiffness the program prints), 'N/um', 'N/mm', 'N/m'") +
                        (train_mesh ? "; auto = ISO 6336-1's c' = 14 N/(mm·µm) for solid steel "
                                      "spur gears times the smaller face width of the mesh's "
                                      "gears in Train/face widths, else ISO 6336/face width"
                                    : ""));
  prm.declare_entry("cai shape", "0.55, 1.8, -1.8", Anything(),
                    "c0, c1, c2 of the Cai bracket c2·s² + c1·s + c0, s = engagement "
                    "fraction (-); the published shape peaks at 1");
  prm.declare_entry("stiffness table", "", Anything(),
                    "mesh stiffness samples 'x:k, x:k, ...' with x the mesh position in base "
                    "pitches in [0, 1) (increasing) and k in N/mm");
  prm.declare_entry("fit cai shape", "false", Bool(),
                    "cai fit: fit the three shape coefficients too, not only the scale");
  // Damping as a ratio (issue 25): see apply_damping_ratios.
  prm.declare_entry("damping", train_mesh ? std::string("auto") : format_number(damping, 10),
                    Anything(),
                    "c_g, mesh damping along the line of action (N·s/m); auto: from 'damping "
                    "ratio'");
  prm.declare_entry("damping ratio", format_number(default_damping_ratio, 10), Double(0., 1.),
                    "ζ of the mesh for damping = auto (-): c_g = 2ζ·√(k_m·m_e), k_m the mean "
                    "mesh stiffness, m_e = 1/Σ r_b²/J of the gears in the mesh; default 0.05, "
                    "inside the 0.03–0.17 reported for gear meshes (docs/references.md §10)");
  prm.declare_entry("friction coefficient", format_number(friction, 10),
                    friction_coefficient_pattern(), "mu, tooth friction (-)");
  prm.declare_entry("driver friction arm", format_number(driver_arm / mm, 10), Double(0.),
                    "r_f of the driver (mm)");
  prm.declare_entry("driven friction arm", format_number(driven_arm / mm, 10), Double(0.),
                    "r_f of the driven gear (mm)");
  declare_nonlinear_mesh_entries(prm, train_mesh);
}

// ISO 6336-1 (docs/references.md §5): c' ≈ 14 N/(mm·µm), the single stiffness of solid steel
// spur gears with the standard basic rack when the pair's own data are not used.
constexpr double iso_approximate_single_stiffness = 14. * newton_per_mm_micrometre; // N/m²

// A stiffness as the parameter file writes it: a number in N/mm, or a number with its unit
// (N/µm, N/um, N/mm, N/m); returned in N/m.
double parse_stiffness_value(const std::string& text, const std::string& parameter)
{
  std::size_t used = 0;
  double value = std::nan("");
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  std::string unit = used == 0 ? std::string() : text.substr(used);
  unit.erase(0, unit.find_first_not_of(" \t"));
  unit.erase(unit.find_last_not_of(" \t") + 1);
  const std::pair<const char*, double> units[] = {
      {"", newton_per_mm}, {"N/mm", newton_per_mm}, {"N/µm", 1e6}, {"N/um", 1e6}, {"N/m", 1.}};
  if (used > 0 && std::isfinite(value))
    for (const auto& [name, factor] : units)
      if (unit == name)
        return value * factor;
  throw InputError(parameter, "'" + text +
                                  "' is not a stiffness: a number in N/mm, or with its unit "
                                  "(N/µm, N/mm, N/m)");
}

struct MeshPhysics
{
  dynamics::MeshStiffness stiffness;
  std::optional<dynamics::CaiFit> fit;
  double damping = 0.;                         // [N·s/m]
  double damping_ratio = std::nan("");         // [-] ζ when damping = auto, else NaN
  double friction_coefficient = 0.;            // [-]
  double driver_friction_arm = 0.;             // [m]
  double driven_friction_arm = 0.;             // [m]
  std::optional<dynamics::StiffnessFile> file; // source 'file': the FE result it came from
  NonlinearMeshEntries nonlinear;              // issue 29
};

// Reads the entries of declare_mesh_physics inside the mesh's subsection `section`.
// `automatic_stiffness` [N/m]: what 'stiffness = auto' stands for (NaN: auto not offered).
MeshPhysics parse_mesh_physics(ParameterHandler& prm, const std::string& section,
                               double contact_ratio, double automatic_stiffness)
{
  MeshPhysics physics;
  const std::string damping = prm.get("damping");
  if (damping == "auto")
  {
    physics.damping_ratio = prm.get_double("damping ratio");
    if (!(physics.damping_ratio > 0.))
      throw InputError(section + "/damping ratio",
                       "must be positive: without mesh damping the start-up transient never "
                       "decays, so there is no steady state to report");
  }
  else
  {
    std::size_t used = 0;
    try
    {
      physics.damping = std::stod(damping, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used == 0 || damping.find_first_not_of(" \t", used) != std::string::npos ||
        !std::isfinite(physics.damping))
      throw InputError(section + "/damping",
                       "'" + damping + "' is neither a damping (N·s/m) nor auto");
    // Without damping the start-up transient never decays: there is no steady state, and the
    // figures read from the window (DTE, K_v) depend on where the window starts.
    if (!(physics.damping > 0.))
      throw InputError(section + "/damping",
                       "must be positive and finite (N·s/m): without mesh damping the start-up "
                       "transient never decays (decay time infinite), so there is no steady "
                       "state to report");
  }
  physics.friction_coefficient = prm.get_double("friction coefficient");
  physics.driver_friction_arm = prm.get_double("driver friction arm") * mm;
  physics.driven_friction_arm = prm.get_double("driven friction arm") * mm;
  physics.nonlinear = parse_nonlinear_mesh_entries(prm, section);

  const std::string source = prm.get("stiffness source");
  const std::string stiffness_text = prm.get("stiffness");
  if (stiffness_text == "auto" && std::isnan(automatic_stiffness))
    throw InputError(section + "/stiffness", "auto is offered for Train meshes only");
  const double stiffness = stiffness_text == "auto"
                               ? automatic_stiffness
                               : parse_stiffness_value(stiffness_text, section + "/stiffness");
  dynamics::CaiParameters cai = dynamics::cai_published_parameters(stiffness);
  {
    std::istringstream shape(prm.get("cai shape"));
    std::string value;
    unsigned int i = 0;
    try
    {
      for (; std::getline(shape, value, ','); ++i)
        if (i < 3)
          cai.shape[i] = std::stod(value);
    }
    catch (const std::exception&)
    {
      i = 0;
    }
    if (i != 3)
      throw InputError(section + "/cai shape", "expects three numbers c0, c1, c2");
  }
  std::vector<double> positions, values;
  parse_table(prm.get("stiffness table"), section + "/stiffness table", positions, values);
  const bool fit_shape = prm.get_bool("fit cai shape");

  if (source == "constant")
    physics.stiffness = dynamics::MeshStiffness::constant(stiffness, section + "/stiffness");
  else if (source == "cai")
    physics.stiffness = dynamics::MeshStiffness::cai(cai, section + "/stiffness");
  else if (source == "table")
    physics.stiffness =
        dynamics::MeshStiffness::table(positions, values, section + "/stiffness table");
  else if (source == "file")
  {
    physics.file =
        dynamics::read_stiffness_file(prm.get("stiffness file"), section + "/stiffness file");
    physics.stiffness = physics.file->stiffness;
  }
  else
  {
    // Validate the samples as a table first so the user gets the table's own message.
    dynamics::MeshStiffness::table(positions, values, section + "/stiffness table");
    std::vector<dynamics::StiffnessSample> samples;
    for (std::size_t i = 0; i < positions.size(); ++i)
      samples.push_back({positions[i], values[i]});
    physics.fit = dynamics::fit_cai_parameters(samples, contact_ratio,
                                               dynamics::StiffnessSampleKind::mesh, fit_shape);
    physics.stiffness =
        dynamics::MeshStiffness::cai(physics.fit->parameters, section + "/stiffness");
  }
  return physics;
}

// parse_mesh_physics in the subsection `section`, which is left also when it throws.
MeshPhysics parse_mesh_physics_section(ParameterHandler& prm, const std::string& section,
                                       double contact_ratio,
                                       double automatic_stiffness = std::nan(""))
{
  prm.enter_subsection(section);
  try
  {
    MeshPhysics physics = parse_mesh_physics(prm, section, contact_ratio, automatic_stiffness);
    prm.leave_subsection();
    return physics;
  }
  catch (...)
  {
    prm.leave_subsection();
    throw;
  }
}

// The entries of "ISO 6336", one a member of IsoParameters, in the unit the file writes it in
// (`unit`: its SI value); declared with IsoParameters' default, read back into the member.
struct IsoEntry
{
  const char* name;
  double IsoParameters::*member;
  double unit;
  Double pattern;
  const char* documentation;
};

const IsoEntry iso_entries[] = {
    {"face width", &IsoParameters::face_width, mm, Double(0.), "b, common face width (mm)"},
    {"transverse pressure angle", &IsoParameters::pressure_angle, degree, Double(0., 45.),
     "alpha_t: F_t = F_bt·cos alpha_t (degrees)"},
    {"single stiffness", &IsoParameters::single_stiffness, newton_per_mm_micrometre, Double(0.),
     "c' (N/(mm·µm)); 0: c_gamma_alpha/(0.75·epsilon_alpha + 0.25)"},
    {"mesh stiffness", &IsoParameters::mesh_stiffness, newton_per_mm_micrometre, Double(0.),
     "c_gamma_alpha (N/(mm·µm)); 0: the model's mean mesh stiffness / b"},
    {"pitch deviation", &IsoParameters::pitch_deviation, micrometre, Double(0.),
     "f_pb,eff = f_pb - y_p, effective base pitch deviation (µm); the default is ISO 1328 grade "
     "6 for this size without running-in allowance"},
    {"profile deviation", &IsoParameters::profile_deviation, micrometre, Double(0.),
     "f_f,eff = f_f_alpha - y_f, effective profile form deviation (µm)"},
    {"tip relief", &IsoParameters::tip_relief, micrometre, Double(0.), "C_a (µm); 0: none"},
    {"application factor", &IsoParameters::application_factor, 1., Double(0.), "K_A (-)"}};

void apply_mesh_physics(const MeshPhysics& physics, dynamics::Mesh& mesh)
{
  mesh.stiffness = physics.stiffness;
  mesh.damping = physics.damping;
  mesh.friction_coefficient = physics.friction_coefficient;
  mesh.driver_friction_arm = physics.driver_friction_arm;
  mesh.driven_friction_arm = physics.driven_friction_arm;
}

// ---- Mesh damping as a ratio (issue 25) ---------------------------------------------------
// 1/m_e = Σ r²/J over the mesh's rotations: the tree form's r_b1²/J1 + r_b2²/J2, or the general
// form's terms (signed base radii, the carrier's included) [kg].
double mesh_equivalent_mass(const dynamics::GearTrain& train, const dynamics::Mesh& mesh)
{
  double compliance = 0.;
  if (mesh.terms.empty())
    compliance =
        mesh.driver_base_radius * mesh.driver_base_radius / train.gears[mesh.driver].inertia +
        mesh.driven_base_radius * mesh.driven_base_radius / train.gears[mesh.driven].inertia;
  else
    for (const dynamics::MeshTerm& term : mesh.terms)
      compliance += term.coefficient * term.coefficient / train.gears[term.dof].inertia;
  return 1. / compliance;
}

// c_g = 2ζ·√(k_m·m_e) for every mesh whose ζ (`ratios`, per model mesh) is a number; one line
// per such mesh with a section name (`sections`, per model mesh; empty: not reported) into
// `derived`.
void apply_damping_ratios(dynamics::GearTrain& train, const std::vector<double>& ratios,
                          const std::vector<std::string>& sections,
                          std::vector<std::string>& derived)
{
  for (std::size_t m = 0; m < train.meshes.size(); ++m)
  {
    if (std::isnan(ratios[m]))
      continue;
    dynamics::Mesh& mesh = train.meshes[m];
    const double stiffness = mesh.stiffness.mean_stiffness(mesh.contact_ratio);
    const double mass = mesh_equivalent_mass(train, mesh);
    mesh.damping = 2. * ratios[m] * std::sqrt(stiffness * mass);
    if (!sections[m].empty())
      derived.push_back(sections[m] + "/damping = " + format_number(mesh.damping, 4) +
                        " N·s/m (auto: ζ = " + format_number(ratios[m], 3) +
                        ", k_m = " + format_number(stiffness / 1e6, 4) +
                        " N/µm, m_e = " + format_number(mass, 4) + " kg)");
  }
}
// ---- end of the damping-ratio block -------------------------------------------------------
} // namespace

void declare_dynamics_parameters(ParameterHandler& prm)
{
  const dynamics::SplitPathCase data = dynamics::split_path_case();

  prm.enter_subsection("Train");
  prm.declare_entry("number of gears", "3", Integer(2, max_dynamics_gears),
                    "gears (rotational degrees of freedom) of the train; a tree of n gears has "
                    "n - 1 meshes, read from 'Mesh 1' ... (-)");
  prm.declare_entry("input speed", format_number(data.input_speed_rpm, 10), Double(0.),
                    "n1, nominal speed of gear 1 (rpm); the others follow from the base radii");
  prm.declare_entry("published reference", "true", Bool(),
                    "print the published split-path values (docs/references.md §1, Reszuta & "
                    "Drewniak 2015) beside ours when the train is that case (T1 and the base "
                    "radii of Mesh 1); false: never");
  prm.declare_entry("model", "gears and meshes", Selection("gears and meshes|train|lateral"),
                    "'gears and meshes': the sections Gear n / Mesh n (a tree, default: the "
                    "split path); 'train': the kinematics command's Train description (gears, "
                    "carriers, planets, meshes, ...) with the sections Train mesh n; 'lateral': "
                    "one planetary stage of that description as the planar lateral-torsional "
                    "model (Lin & Parker 1999: modes, classes, load sharing, bearing forces)");
  prm.declare_entry("pressure angle", "20", Double(0., 45.),
                    "train model: pressure angle of the standard teeth (x = 0, h_a* = 1) for "
                    "base radii, contact and approach ratios (degrees)");
  prm.declare_entry("suspended members", "", Anything(),
                    "train model: fixed members hung on a torsional spring and damper to the "
                    "housing, 'name: stiffness damping, ...' (N·m/rad, N·m·s/rad)");
  prm.declare_entry("face widths", "", Anything(),
                    "train model: gears whose J and mass come from a steel blank where "
                    "Train/inertias and Train/masses give none, 'name: b, ...' (mm)");
  prm.declare_entry("bore diameters", "", Anything(),
                    "train model: bore of those blanks, 'name: d, ...' (mm; none: solid); for an "
                    "internal gear the rim's outside diameter (required)");
  prm.declare_entry("density", "7850", Double(0.), "train model: density of the blanks (kg/m³)");
  prm.leave_subsection();
  declare_train_parameters(prm); // gears, modules, ..., inertias, masses, input torque

  for (unsigned int m = 0; m < max_train_meshes; ++m)
  {
    prm.enter_subsection(train_mesh_section(m));
    declare_mesh_physics(prm, data.single_pair_stiffness, data.mesh_damping, 0., 0., 0., true);
    prm.leave_subsection();
  }

  for (unsigned int i = 0; i < max_dynamics_gears; ++i)
  {
    prm.enter_subsection(gear_section(i));
    const bool pinion = i == 0;
    prm.declare_entry("inertia",
                      format_number(pinion ? data.pinion_inertia : data.wheel_inertia, 10),
                      Double(0.), "J, mass moment of inertia about the gear axis (kg·m²)");
    prm.declare_entry("torque",
                      pinion ? format_number(data.input_torque, 10) : std::string("balance"),
                      Anything(),
                      "external torque (N·m), positive in the running direction (input), "
                      "negative for a load; 'balance': the load that takes an equal share of "
                      "its driver's torque, T = -T_driver/(meshes of the driver)·r_b/r_b,driver");
    prm.leave_subsection();
  }

  for (unsigned int m = 0; m + 1 < max_dynamics_gears; ++m)
  {
    prm.enter_subsection(mesh_section(m));
    prm.declare_entry("driver gear", "1", Integer(1, max_dynamics_gears),
                      "number of the driving gear (-)");
    prm.declare_entry("driven gear", std::to_string(m + 2), Integer(1, max_dynamics_gears),
                      "number of the driven gear (-)");
    prm.declare_entry("driver teeth", std::to_string(data.pinion_teeth), Integer(1, 10000),
                      "z of the driver: the mesh frequency is z·n_driver/60 (-)");
    prm.declare_entry("driver base radius", format_number(data.pinion_base_radius / mm, 10),
                      Double(0.), "r_b of the driver (mm)");
    prm.declare_entry("driven base radius", format_number(data.wheel_base_radius / mm, 10),
                      Double(0.), "r_b of the driven gear (mm)");
    prm.declare_entry("contact ratio", format_number(data.contact_ratio, 10), Double(1., 4.),
                      "epsilon_alpha, transverse contact ratio (-); default from the "
                      "kinematics module's split-path pair");
    prm.declare_entry("approach ratio", format_number(data.approach_ratio, 10), Double(0., 4.),
                      "epsilon_f, start of active contact to the pitch point in base pitches "
                      "(-): where the friction force reverses; default from kinematics");
    prm.declare_entry("placement angle", m == 1 ? "180" : "0", Double(-360., 360.),
                      "theta, angle of the driven gear's centre around the driver axis, "
                      "against the driver's rotation, from the driven gear of the first mesh "
                      "of the same driver (degrees); sets the phase frac(z·theta/360°)");
    declare_mesh_physics(prm, data.single_pair_stiffness, data.mesh_damping,
                         data.friction_coefficient, data.pinion_friction_arm,
                         data.wheel_friction_arm, false);
    prm.leave_subsection();
  }

  prm.enter_subsection("Simulation");
  prm.declare_entry("integrator", "RK4", Selection("RK4|adaptive RK|HHT-alpha"),
                    "RK4: classical Runge-Kutta, fixed step (the published method); adaptive "
                    "RK: Dormand-Prince 5(4) with error control; HHT-alpha: implicit, for "
                    "stiff meshes");
  prm.declare_entry("time step", "5", Double(0.),
                    "step of RK4 and HHT-alpha, output interval of the adaptive method (µs)");
  prm.declare_entry("allow unstable step", "false", Bool(),
                    "run RK4 with a step above the estimated stability limit");
  prm.declare_entry("relative tolerance", "1e-7", Double(0., 0.1),
                    "adaptive RK: local error tolerance relative to the state (-)");
  prm.declare_entry("HHT alpha", "-0.05", Double(-1. / 3., 0.),
                    "HHT-alpha parameter in [-1/3, 0]; 0 is the trapezoidal rule (-)");
  prm.declare_entry("start", "static deflection", Selection("static deflection|rest"),
                    "initial state: static deflection under mean stiffness, or rest (the "
                    "torques applied suddenly)");
  prm.declare_entry("initial mesh position", "0", Double(0., 1.),
                    "position of mesh 1 at t = 0, in base pitches (0: a pair enters contact)");
  prm.declare_entry("steady state start", "-1", Double(),
                    "start of the K_v window (s); negative: automatic, when the slowest mode "
                    "has decayed to 1/1000");
  prm.declare_entry("simulated time", "0", Double(0.),
                    "end time (s); 0: the window start plus 'window periods' mesh periods");
  prm.declare_entry("window periods", "40", Integer(1, 100000),
                    "length of the automatic K_v window in periods of mesh 1 (-)");
  prm.declare_entry("output interval", "20", Double(0.),
                    "spacing of the rows of the time-series CSV (µs); K_v uses every step");
  prm.declare_entry("mesh model", "linear", Selection("linear|nonlinear"),
                    "linear: F = k·delta + c·delta'; nonlinear: F = k·h(delta - e) + c·(delta' - "
                    "e')·[in contact] with the unloaded TE e, free play (backlash), tooth "
                    "separation and back-flank contact, switches located by RK4 (issue 29, "
                    "dynamics/README.md)");
  prm.leave_subsection();

  prm.enter_subsection("Speed sweep");
  prm.declare_entry("points", "60", Integer(0, 100000),
                    "speeds in the K_v resonance chart (-); 0: no sweep");
  prm.declare_entry("minimum speed", "500", Double(0.), "first input speed (rpm)");
  prm.declare_entry("maximum speed", "45000", Double(0.), "last input speed (rpm)");
  prm.declare_entry("steps per mesh period", "40", Integer(8, 10000),
                    "the step is reduced so each mesh period holds at least this many (-)");
  prm.declare_entry("direction", "up", Selection("up|down|both"),
                    "order of the speeds: up, down, or both (up, then down from the top); with "
                    "the nonlinear mesh model each speed starts from the previous speed's final "
                    "state, so multi-valued responses show both branches");
  prm.leave_subsection();

  // The split-path pair's b, α_t = 20°, ISO 1328 grade 6 deviations (iso_entries).
  IsoParameters iso;
  iso.face_width = data.face_width;
  iso.pressure_angle = 20. * degree;
  iso.pitch_deviation = 8. * micrometre;
  iso.profile_deviation = 8. * micrometre;
  prm.enter_subsection("ISO 6336");
  for (const IsoEntry& entry : iso_entries)
    prm.declare_entry(entry.name, format_number(iso.*entry.member / entry.unit, 10), entry.pattern,
                      entry.documentation);
  prm.leave_subsection();
}

namespace
{
// issue 29: Simulation/mesh model and Speed sweep/direction (read before the meshes).
void parse_nonlinear_settings(ParameterHandler& prm, DynamicsParameters& p)
{
  prm.enter_subsection("Simulation");
  p.mesh_model = prm.get("mesh model") == "nonlinear" ? dynamics::MeshModel::nonlinear
                                                      : dynamics::MeshModel::linear;
  prm.leave_subsection();
  prm.enter_subsection("Speed sweep");
  const std::string direction = prm.get("direction");
  p.sweep_direction = direction == "down"   ? dynamics::SweepDirection::down
                      : direction == "both" ? dynamics::SweepDirection::both
                                            : dynamics::SweepDirection::up;
  prm.leave_subsection();
}

// "Gear n" / "Mesh n" sections: a tree-shaped train in the two-gear mesh form.
void parse_numbered_train(ParameterHandler& prm, DynamicsParameters& p)
{
  prm.enter_subsection("Train");
  const unsigned int n_gears = prm.get_integer("number of gears");
  p.train.input_speed = prm.get_double("input speed") * rpm;
  p.published_reference = prm.get_bool("published reference");
  prm.leave_subsection();
  if (!(p.train.input_speed > 0.) || !std::isfinite(p.train.input_speed))
    throw InputError("Train/input speed", "must be positive (rpm), got " +
                                              format_number(p.train.input_speed / rpm, 6) + " rpm");

  std::vector<std::string> torque_text(n_gears);
  for (unsigned int i = 0; i < n_gears; ++i)
  {
    prm.enter_subsection(gear_section(i));
    dynamics::Gear gear;
    gear.name = gear_section(i);
    gear.inertia = prm.get_double("inertia");
    torque_text[i] = prm.get("torque");
    prm.leave_subsection();
    p.train.gears.push_back(gear);
  }

  std::vector<double> damping_ratios; // per mesh, NaN: damping given
  std::vector<std::string> mesh_sections;
  for (unsigned int m = 0; m + 1 < n_gears; ++m)
  {
    const std::string section = mesh_section(m);
    mesh_sections.push_back(section);
    prm.enter_subsection(section);
    dynamics::Mesh mesh;
    mesh.name = section;
    const unsigned int driver = prm.get_integer("driver gear");
    const unsigned int driven = prm.get_integer("driven gear");
    mesh.driver_teeth = prm.get_integer("driver teeth");
    mesh.driver_base_radius = prm.get_double("driver base radius") * mm;
    mesh.driven_base_radius = prm.get_double("driven base radius") * mm;
    mesh.contact_ratio = prm.get_double("contact ratio");
    mesh.approach_ratio = prm.get_double("approach ratio");
    p.placement_angle.push_back(prm.get_double("placement angle") * degree);
    prm.leave_subsection();
    if (driver > n_gears || driven > n_gears || driver == driven)
      throw InputError(section + "/driven gear",
                       "a mesh joins two different gears among the first " +
                           std::to_string(n_gears));
    mesh.driver = driver - 1;
    mesh.driven = driven - 1;
    const MeshPhysics physics = parse_mesh_physics_section(prm, section, mesh.contact_ratio);
    apply_mesh_physics(physics, mesh);
    damping_ratios.push_back(physics.damping_ratio);
    if (p.mesh_model == dynamics::MeshModel::nonlinear)
      mesh.nonlinear = build_nonlinear_mesh(
          physics.nonlinear, section, mesh.driver_teeth,
          [&](const dynamics::StiffnessFile& file)
          { check_numbered_mesh_pair(file, mesh, section + "/transmission error file"); });
    const std::optional<dynamics::CaiFit>& fit = physics.fit;
    p.stiffness_description.push_back(mesh.stiffness.description() +
                                      (fit ? " (fitted to the table)" : ""));
    p.cai_fit.push_back(fit);
    p.train.meshes.push_back(mesh);
  }

  // Torques: numbers, or "balance" for a load taking an equal share of its driver's torque.
  std::vector<bool> known(n_gears, false);
  std::vector<double> torque(n_gears, 0.);
  for (unsigned int i = 0; i < n_gears; ++i)
    if (torque_text[i] != "balance")
    {
      std::size_t used = 0;
      try
      {
        torque[i] = std::stod(torque_text[i], &used);
      }
      catch (const std::exception&)
      {
        used = 0;
      }
      if (used == 0 || torque_text[i].find_first_not_of(" \t", used) != std::string::npos)
        throw InputError(gear_section(i) + "/torque",
                         "expects a number (N·m) or 'balance', got '" + torque_text[i] + "'");
      known[i] = true;
    }
  for (unsigned int i = 0; i < n_gears; ++i)
    if (!known[i])
    {
      const dynamics::Mesh* feeding = nullptr;
      for (const auto& mesh : p.train.meshes)
        if (mesh.driven == i)
          feeding = &mesh;
      if (feeding == nullptr || !known[feeding->driver] || !(torque[feeding->driver] > 0.))
        throw InputError(gear_section(i) + "/torque",
                         "'balance' needs a driving gear with a given positive torque");
      unsigned int shares = 0;
      for (const auto& mesh : p.train.meshes)
        shares += (mesh.driver == feeding->driver);
      torque[i] = -torque[feeding->driver] / shares * feeding->driven_base_radius /
                  feeding->driver_base_radius;
    }
  for (unsigned int i = 0; i < n_gears; ++i)
    p.train.gears[i].torque = torque[i];
  apply_damping_ratios(p.train, damping_ratios, mesh_sections, p.derived_sizes);
  // The published nominal force F_cn belongs to the split-path case alone: T1 and r_b1 of it.
  const dynamics::SplitPathCase data = dynamics::split_path_case();
  const dynamics::Mesh& first = p.train.meshes.front();
  p.published_reference = p.published_reference &&
                          std::abs(torque[first.driver] - data.input_torque) < 1e-9 &&
                          std::abs(first.driver_base_radius - data.pinion_base_radius) < 1e-9 &&
                          std::abs(first.driven_base_radius - data.wheel_base_radius) < 1e-9;
}

// The Train entries of the dynamics beyond the kinematics' description.
void parse_train_extras(ParameterHandler& prm, dynamics::TrainDynamicsInput& input)
{
  prm.enter_subsection("Train");
  input.pressure_angle = prm.get_double("pressure angle") * degree;
  input.density = prm.get_double("density");
  const std::string suspended = prm.get("suspended members");
  const std::string widths = prm.get("face widths");
  const std::string bores = prm.get("bore diameters");
  prm.leave_subsection();
  for (const auto& [name, v] :
       parse_named_numbers(suspended, 2, "Train/suspended members", "stiffness damping"))
    input.suspensions.push_back({name, v[0], v[1]});
  for (const auto& [name, v] : parse_named_numbers(widths, 1, "Train/face widths", "b"))
    input.blanks.push_back({name, v[0] * mm, 0.});
  for (const auto& [name, v] : parse_named_numbers(bores, 1, "Train/bore diameters", "d"))
  {
    const auto blank =
        std::find_if(input.blanks.begin(), input.blanks.end(),
                     [&, n = name](const dynamics::GearBlank& b) { return b.member == n; });
    if (blank == input.blanks.end())
      throw InputError("Train/bore diameters", "'" + name + "' has no face width");
    blank->bore_diameter = v[0] * mm;
  }
}

// The kinematics command's "Train" description plus "Train mesh n" sections.
void parse_train_description(ParameterHandler& prm, DynamicsParameters& p)
{
  const TrainParameters train = parse_train_parameters(prm);
  prm.enter_subsection("ISO 6336");
  const double iso_face_width = prm.get_double("face width") * mm;
  prm.leave_subsection();
  dynamics::TrainDynamicsInput input;
  input.spec = kinematics::parse_gear_train(train.text);
  // 'Train/input speed' belongs to the 'gears and meshes' model; the train model's speeds come
  // from Train/inputs. A value set to something else would be ignored: refuse the conflict.
  prm.enter_subsection("Train");
  const double input_speed = prm.get_double("input speed");
  prm.leave_subsection();
  const double default_speed = dynamics::split_path_case().input_speed_rpm;
  if (std::abs(input_speed - default_speed) > 1e-9 * default_speed)
  {
    const bool same = input.spec.inputs.size() == 1 &&
                      std::abs(input_speed * rpm - input.spec.inputs.front().second) <=
                          1e-9 * std::abs(input.spec.inputs.front().second);
    if (!same)
      throw InputError("Train/input speed",
                       "is not used by Train/model = train, whose speeds come from Train/inputs "
                       "(" +
                           (input.spec.inputs.empty()
                                ? std::string("none given")
                                : input.spec.inputs.front().first + " at " +
                                      format_number(input.spec.inputs.front().second / rpm, 6) +
                                      " rpm") +
                           "): give the speed there and leave 'input speed' at its default");
  }
  input.input_torque = train.input_torque;
  parse_train_extras(prm, input);
  input.initial_position = p.initial_position;
  if (input.spec.meshes.size() > max_train_meshes)
    throw InputError("Train/meshes", "at most " + std::to_string(max_train_meshes) +
                                         " meshes (sections 'Train mesh 1' ...)");
  std::vector<double> spec_damping_ratios; // per Train mesh, NaN: damping given
  for (std::size_t m = 0; m < input.spec.meshes.size(); ++m)
  {
    const std::string section = train_mesh_section(m);
    // The contact ratio of standard teeth, for a Cai fit (the model recomputes it).
    const kinematics::TrainMesh& tm = input.spec.meshes[m];
    double contact_ratio = 1.5, module = 0.;
    int teeth[2] = {0, 0};
    for (const auto& a : input.spec.members)
      for (const auto& b : input.spec.members)
        if (a.name == tm.gear_a && b.name == tm.gear_b && a.module > 0.)
        {
          contact_ratio =
              dynamics::standard_mesh(a.teeth, b.teeth, a.module, input.pressure_angle, 0)
                  .contact_ratio;
          module = a.module;
          teeth[0] = a.teeth;
          teeth[1] = b.teeth;
        }
    // stiffness = auto: c'·b with this mesh's own face width (the smaller of its gears'), so
    // that no mesh inherits the split-path pair's peak.
    double width = 0.;
    std::string width_origin = "ISO 6336/face width";
    for (const dynamics::GearBlank& blank : input.blanks)
      if ((blank.member == tm.gear_a || blank.member == tm.gear_b) &&
          (width == 0. || blank.face_width < width))
      {
        width = blank.face_width;
        width_origin = "Train/face widths";
      }
    if (width == 0.)
      width = iso_face_width;
    const double automatic_stiffness = iso_approximate_single_stiffness * width;
    const MeshPhysics physics =
        parse_mesh_physics_section(prm, section, contact_ratio, automatic_stiffness);
    prm.enter_subsection(section);
    const bool automatic = prm.get("stiffness") == "auto";
    prm.leave_subsection();
    if (automatic)
      p.derived_sizes.push_back(
          section + "/stiffness = " + format_number(automatic_stiffness / 1e6, 5) +
          " N/µm (auto: ISO 6336-1 c' = 14 N/(mm·µm) × b = " + format_number(width / mm, 5) +
          " mm from " + width_origin + ")");
    dynamics::TrainMeshDynamics mesh{physics.stiffness,
                                     physics.damping,
                                     physics.friction_coefficient,
                                     physics.driver_friction_arm,
                                     physics.driven_friction_arm,
                                     {},
                                     {},
                                     {},
                                     {}};
    if (p.mesh_model == dynamics::MeshModel::nonlinear)
      mesh.nonlinear = build_nonlinear_mesh(
          physics.nonlinear, section, static_cast<unsigned int>(std::abs(teeth[0])),
          [&](const dynamics::StiffnessFile& file)
          {
            dynamics::match_stiffness_file(file, teeth[0], teeth[1], module,
                                           section + "/transmission error file");
          });
    std::string origin = physics.fit ? " (fitted to the table)" : "";
    if (physics.file)
    {
      mesh.stiffness_driver = dynamics::match_stiffness_file(*physics.file, teeth[0], teeth[1],
                                                             module, section + "/stiffness file");
      // The FE pair's path of contact (its tips) sets the cycle the table is measured on.
      mesh.contact_ratio = physics.file->pair.contact_ratio;
      if (std::isfinite(physics.file->pair.approach_ratio))
        mesh.approach_ratio = physics.file->pair.approach_ratio;
      origin =
          " from `gearstiff " + physics.file->command + "` (" + physics.file->pair.describe() + ")";
    }
    input.meshes.push_back(mesh);
    spec_damping_ratios.push_back(physics.damping_ratio);
    p.stiffness_description.push_back(physics.stiffness.description() + origin);
    p.cai_fit.push_back(physics.fit);
  }
  p.train_model = dynamics::build_train_model(input);
  p.train = p.train_model.train;
  {
    // Per model mesh (every copy) the ζ of its Train mesh; reported once per Train mesh.
    std::vector<double> ratios;
    std::vector<std::string> sections;
    for (std::size_t m = 0; m < p.train.meshes.size(); ++m)
    {
      ratios.push_back(spec_damping_ratios[p.train_model.spec_mesh[m]]);
      sections.push_back(p.train_model.mesh_copy[m] == 0
                             ? train_mesh_section(p.train_model.spec_mesh[m])
                             : std::string());
    }
    apply_damping_ratios(p.train, ratios, sections, p.derived_sizes);
  }
  p.published_reference = false;
  // Per model mesh (every copy): the description of its Train mesh.
  std::vector<std::string> descriptions;
  std::vector<std::optional<dynamics::CaiFit>> fits;
  for (const unsigned int m : p.train_model.spec_mesh)
  {
    descriptions.push_back(p.stiffness_description[m]);
    fits.push_back(p.cai_fit[m]);
  }
  p.stiffness_description = descriptions;
  p.cai_fit = fits;
  p.placement_angle.assign(p.train.meshes.size(), std::nan(""));
}
} // namespace

DynamicsParameters parse_dynamics_parameters(ParameterHandler& prm)
{
  DynamicsParameters p;
  prm.enter_subsection("Train");
  p.train_description = prm.get("model") == "train";
  prm.leave_subsection();
  parse_nonlinear_settings(prm, p);
  if (!p.train_description)
    parse_numbered_train(prm, p);

  prm.enter_subsection("Simulation");
  const std::string integrator = prm.get("integrator");
  p.simulation.integrator.type = integrator == "RK4" ? dynamics::IntegratorType::rk4
                                 : integrator == "adaptive RK"
                                     ? dynamics::IntegratorType::adaptive_rk
                                     : dynamics::IntegratorType::hht_alpha;
  p.simulation.integrator.time_step = prm.get_double("time step") * micrometre;
  p.simulation.integrator.allow_unstable_step = prm.get_bool("allow unstable step");
  p.simulation.integrator.relative_tolerance = prm.get_double("relative tolerance");
  p.simulation.integrator.hht_alpha = prm.get_double("HHT alpha");
  p.simulation.start = prm.get("start") == "rest" ? dynamics::StartState::rest
                                                  : dynamics::StartState::static_deflection;
  p.initial_position = prm.get_double("initial mesh position");
  p.simulation.steady_state_start = prm.get_double("steady state start");
  p.simulation.end_time = prm.get_double("simulated time");
  p.simulation.window_periods = prm.get_integer("window periods");
  p.output_interval = prm.get_double("output interval") * micrometre;
  p.simulation.record_interval = p.output_interval;
  prm.leave_subsection();
  if (!(p.simulation.integrator.time_step > 0.))
    throw InputError("Simulation/time step", "must be positive");

  prm.enter_subsection("Speed sweep");
  p.sweep.points = prm.get_integer("points");
  p.sweep.minimum_speed = prm.get_double("minimum speed") * rpm;
  p.sweep.maximum_speed = prm.get_double("maximum speed") * rpm;
  p.sweep.steps_per_mesh_period = prm.get_integer("steps per mesh period");
  prm.leave_subsection();
  if (p.sweep.points > 0 &&
      !(p.sweep.minimum_speed > 0. && p.sweep.maximum_speed >= p.sweep.minimum_speed))
    throw InputError("Speed sweep/maximum speed", "needs 0 < minimum speed <= maximum speed");

  prm.enter_subsection("ISO 6336");
  for (const IsoEntry& entry : iso_entries)
    p.iso.*entry.member = prm.get_double(entry.name) * entry.unit;
  prm.leave_subsection();

  if (p.train_description)
  {
    parse_train_description(prm, p);
    return p;
  }
  // Mesh phases from the placement angles: each mesh relative to the first mesh of its driver.
  for (unsigned int m = 0; m < p.train.meshes.size(); ++m)
    p.train.meshes[m].initial_position =
        p.initial_position +
        dynamics::mesh_phase_from_placement(p.train.meshes[m].driver_teeth, p.placement_angle[m]);
  return p;
}
} // namespace gearstiff::app

namespace gearstiff::app
{
// issue 30: the lateral model's view of a Train mesh (dynamics_parameters.h).
TrainMeshMean parse_train_mesh_mean(ParameterHandler& prm, unsigned int m, double contact_ratio,
                                    int teeth_a, int teeth_b, double module)
{
  const std::string section = train_mesh_section(m);
  const MeshPhysics physics = parse_mesh_physics_section(prm, section, contact_ratio);
  const double ratio = physics.file ? physics.file->pair.contact_ratio : contact_ratio;
  TrainMeshMean mean{physics.stiffness.mean_stiffness(ratio),
                     physics.damping,
                     physics.stiffness.description() + ", mean " +
                         format_number(physics.stiffness.mean_stiffness(ratio) * 1e-6, 6) + " N/µm",
                     physics.stiffness,
                     ratio,
                     std::nullopt,
                     std::nullopt};
  if (physics.file && module > 0.)
    mean.stiffness_driver = dynamics::match_stiffness_file(*physics.file, teeth_a, teeth_b, module,
                                                           section + "/stiffness file");
  prm.enter_subsection("Simulation");
  const bool nonlinear = prm.get("mesh model") == "nonlinear";
  prm.leave_subsection();
  if (nonlinear)
    mean.nonlinear = build_nonlinear_mesh(
        physics.nonlinear, section, static_cast<unsigned int>(std::abs(teeth_a)),
        [&](const dynamics::StiffnessFile& file)
        {
          if (module > 0.)
            dynamics::match_stiffness_file(file, teeth_a, teeth_b, module,
                                           section + "/transmission error file");
        });
  return mean;
}
} // namespace gearstiff::app
