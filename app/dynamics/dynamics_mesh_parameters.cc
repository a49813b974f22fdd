// The entries of one mesh ("Mesh n" and "Train mesh n"): stiffness source, damping (or its
// ratio), friction, and the nonlinear law of issue 29 (backlash, transmission error).
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/dynamics/dynamics_field_names.h"
#include "app/dynamics/dynamics_parameters_internal.h"
#include "dynamics/split_path_case.h"
#include "errors/errors.h"

#include <sstream>

namespace gearstiff::app::dynamics_input
{
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

namespace
{
// Mesh damping as a ratio (issue 25): ζ = 0.05, inside the 0.03–0.17 of the gear-mesh damping
// ratios reported in the literature (docs/references.md §10); the published split-path meshes
// keep their c_g = 100 N·s/m (§1). Applied by apply_damping_ratios.
constexpr double default_damping_ratio = 0.05;

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
                    "line of action, the normal backlash j_bn [µm]; j_bn = j_t·cos alpha_wt from "
                    "the circular backlash j_t, or -(A_sn1 + A_sn2)·cos alpha_n from the "
                    "tooth-thickness allowances (spur gears, nominal centre distance)");
  prm.declare_entry("transmission error file", "", Anything(),
                    "mesh model nonlinear: summary.json of a `gearstiff stiffness` sweep of the "
                    "same pair (checked): its loaded TE s(x) and stiffness k(x) give the "
                    "unloaded TE e = s - W/k (zero for k = W/s); empty: none");
  prm.declare_entry(
      "tooth thickness allowances", "", Anything(),
      "mesh model nonlinear: backlash from the geometry instead of 'backlash': the "
      "tooth-thickness allowances A_sn of " +
          std::string(train_mesh ? "the mesh's first and second gear"
                                 : "the driver and the driven gear") +
          ", 'A_sn1, A_sn2' (µm, zero or negative: DIN 3967 upper allowances), "
          "giving j_bn = -(A_sn1 + A_sn2)·cos alpha_n at the nominal centre "
          "distance (ISO 21771 / DIN 3967, docs/references.md §14; alpha_n = " +
          (train_mesh ? "Train/pressure angle" : "ISO 6336/transverse pressure angle") +
          "); empty: 'backlash' as given");
  prm.declare_entry("back flank file", "", Anything(),
                    "mesh model nonlinear: summary.json of a `gearstiff stiffness` sweep of the "
                    "same pair (checked) loaded on the flanks that are the back flanks here (e.g. "
                    "with their own modifications): its k(x), mirrored onto the back flanks' "
                    "path like the default; empty: the drive flanks' stiffness mirrored "
                    "(symmetric teeth)");
  prm.declare_entry("profile deviation", "0", Double(0.),
                    "mesh model nonlinear: profile form deviation f_f, a sinusoid of this "
                    "peak-to-peak at the mesh frequency in the unloaded TE [µm]");
  prm.declare_entry("pitch deviation", "0", Double(0.),
                    "mesh model nonlinear: cumulative pitch deviation F_p of " + gear +
                        ", a once-per-revolution sinusoid of this peak-to-peak [µm]");
  prm.declare_entry("transmission error harmonics", "", Anything(),
                    "mesh model nonlinear: further TE sinusoids 'order: amplitude[: phase], "
                    "...' (mesh orders, µm, deg)");
}

NonlinearMeshEntries parse_nonlinear_mesh_entries(ParameterHandler& prm, const std::string& section)
{
  NonlinearMeshEntries entries;
  entries.backlash = prm.get_double("backlash") * micrometre;
  entries.file = prm.get("transmission error file");
  entries.back_file = prm.get("back flank file");
  const std::vector<std::string> allowances = comma_entries(prm.get("tooth thickness allowances"));
  const std::string allowance_parameter = section + "/tooth thickness allowances";
  for (const std::string& entry : allowances)
  {
    std::size_t used = 0;
    double value = std::nan("");
    try
    {
      value = std::stod(entry, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used == 0 || entry.find_first_not_of(" \t", used) != std::string::npos ||
        !std::isfinite(value))
      throw InputError(allowance_parameter, "'" + entry + "' is not a number (µm)");
    entries.thickness_allowances.push_back(value * micrometre);
  }
  if (!allowances.empty() && allowances.size() != 2)
    throw InputError(allowance_parameter, "expects two allowances 'A_sn1, A_sn2' (µm), got " +
                                              std::to_string(allowances.size()));

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
                       "entry '" + entry + "' is not 'order: amplitude[: phase]' (-, µm, deg)");
    entries.harmonics.push_back(
        {numbers[0], numbers[1] * micrometre, numbers.size() == 3 ? numbers[2] * degree : 0.});
  }
  return entries;
}
} // namespace

// The law of one mesh: backlash, the TE from the file (its pair checked by `check_pair`, which
// throws naming the file parameter) and from the deviations; `teeth` of the gear whose
// revolution the pitch deviation follows.
namespace
{
// ISO 21771 / DIN 3967 (docs/references.md §14): at the nominal centre distance the circular
// backlash of a spur pair is j_t = −(A_sn1 + A_sn2) and the normal backlash, the free play along
// the line of action, j_bn = j_t·cos α_n [m]. An allowance must thin the tooth (≤ 0) and leave
// at least half of the nominal tooth thickness m·π/2 (x = 0).
double backlash_from_allowances(const std::vector<double>& allowances, const MeshGeometry& geometry,
                                const std::string& section, std::vector<std::string>& derived)
{
  const std::string parameter = section + "/tooth thickness allowances";
  const double half_tooth = 0.25 * M_PI * geometry.module;
  for (const double allowance : allowances)
  {
    if (allowance > 0.)
      throw InputError(parameter, "must not be positive, got " +
                                      format_number(allowance / micrometre, 6) +
                                      " µm: a tooth-thickness allowance thins the tooth (DIN "
                                      "3967); a thicker tooth than nominal leaves no backlash");
    if (-allowance > half_tooth)
      throw InputError(parameter,
                       format_number(allowance / micrometre, 6) +
                           " µm removes more than half the nominal tooth thickness m·π/2 = " +
                           format_number(2. * half_tooth / micrometre, 6) +
                           " µm (m = " + format_number(geometry.module / mm, 6) + " mm)");
  }
  const double circular = -(allowances[0] + allowances[1]);
  const double normal = circular * std::cos(geometry.pressure_angle);
  derived.push_back(
      section + "/backlash = " + format_number(normal / micrometre, 6) +
      " µm (from the tooth thickness allowances " + format_number(allowances[0] / micrometre, 6) +
      ", " + format_number(allowances[1] / micrometre, 6) +
      " µm: j_t = " + format_number(circular / micrometre, 6) + " µm, j_bn = j_t·cos α_n, α_n = " +
      format_number(geometry.pressure_angle / degree, 4) + "°)");
  return normal;
}

// An FE summary for `parameter` of the pair (`check_pair` throws naming it otherwise).
dynamics::StiffnessFile read_pair_file(const std::string& path, const std::string& parameter,
                                       const PairCheck& check_pair)
{
  const dynamics::StiffnessFile file = dynamics::read_stiffness_file(path, parameter);
  check_pair(file, parameter);
  return file;
}
} // namespace

dynamics::NonlinearMesh build_nonlinear_mesh(const NonlinearMeshEntries& entries,
                                             const std::string& section, unsigned int teeth,
                                             const MeshGeometry& geometry,
                                             const PairCheck& check_pair,
                                             std::vector<std::string>& derived)
{
  dynamics::NonlinearMesh mesh;
  mesh.section = section;
  mesh.backlash =
      entries.thickness_allowances.empty()
          ? entries.backlash
          : backlash_from_allowances(entries.thickness_allowances, geometry, section, derived);
  if (!entries.file.empty())
  {
    const std::string parameter = section + "/transmission error file";
    const dynamics::StiffnessFile file = read_pair_file(entries.file, parameter, check_pair);
    if (!file.transmission_error)
      throw InputError(parameter, "'" + entries.file +
                                      "' has no loaded transmission error (the stiffness_sweep "
                                      "table of `gearstiff stiffness` in mode sweep)");
    mesh.transmission_error = file.transmission_error->unloaded;
  }
  if (!entries.back_file.empty())
  {
    // Its own back-flank table: the file's k(x) run the other way along its own path of contact.
    const dynamics::StiffnessFile file =
        read_pair_file(entries.back_file, section + "/back flank file", check_pair);
    mesh.back_stiffness = file.stiffness.reversed(file.pair.contact_ratio);
  }
  const std::string harmonics = section + "/transmission error harmonics";
  mesh.transmission_error.add_harmonic({1., 0.5 * entries.profile_deviation, 0.},
                                       section + "/profile deviation");
  mesh.transmission_error.add_harmonic(
      {1. / std::max(1u, teeth), 0.5 * entries.pitch_deviation, 0.}, section + "/pitch deviation");
  for (const dynamics::ExcitationHarmonic& h : entries.harmonics)
    mesh.transmission_error.add_harmonic(h, harmonics);
  // Checked as mesh 1 of its own, named by its section.
  with_parameter_names(gear_mesh_parameter_names(0, section),
                       [&] { dynamics::check_nonlinear_mesh(mesh, 0); });
  return mesh;
}

// A "Mesh n" pair is known by its driver's teeth and base radii: the file's pinion must be
// the driver (teeth equal, base radius within 1 %: the split path rounds r_b1 to 24.7 mm) and
// its wheel z1·r_b2/r_b1 teeth. An internal wheel's file counts its teeth negative; a Mesh n
// does not know the sign (the torsional model along the line of action is the same for both:
// the ring turns with the pinion), so the file's wheel is compared by its tooth count.
void check_numbered_mesh_pair(const dynamics::StiffnessFile& file, const dynamics::Mesh& mesh,
                              const std::string& parameter)
{
  const double pinion_base_radius = file.pair.pinion_base_radius;
  const long wheel_teeth =
      std::lround(mesh.driver_teeth * mesh.driven_base_radius / mesh.driver_base_radius);
  const bool same = file.pair.pinion_teeth == static_cast<int>(mesh.driver_teeth) &&
                    std::abs(file.pair.wheel_teeth) == wheel_teeth &&
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
                    "fraction [-]; the published shape peaks at 1");
  prm.declare_entry("stiffness table", "", Anything(),
                    "mesh stiffness samples 'x:k, x:k, ...' with x the mesh position in base "
                    "pitches in [0, 1) (increasing) and k in N/mm");
  prm.declare_entry("fit cai shape", "false", Bool(),
                    "cai fit: fit the three shape coefficients too, not only the scale");
  // Damping as a ratio (issue 25): see apply_damping_ratios.
  prm.declare_entry("damping", train_mesh ? std::string("auto") : format_number(damping, 10),
                    Anything(),
                    "c_g, mesh damping along the line of action [N·s/m]; auto: from 'damping "
                    "ratio'");
  prm.declare_entry("damping ratio", format_number(default_damping_ratio, 10), Double(0., 1.),
                    "ζ of the mesh for damping = auto [-]: c_g = 2ζ·√(k_m·m_e), k_m the mean "
                    "mesh stiffness, m_e = 1/Σ r_b²/J of the gears in the mesh; default 0.05, "
                    "inside the 0.03–0.17 reported for gear meshes (docs/references.md §10)");
  prm.declare_entry("friction coefficient", format_number(friction, 10),
                    friction_coefficient_pattern(), "mu, tooth friction [-]");
  prm.declare_entry("driver friction arm", format_number(driver_arm / mm, 10), Double(0.),
                    "r_f of the driver [mm]");
  prm.declare_entry("driven friction arm", format_number(driven_arm / mm, 10), Double(0.),
                    "r_f of the driven gear [mm]");
  declare_nonlinear_mesh_entries(prm, train_mesh);
}

namespace
{
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

// "damping" (N·s/m, or auto with its "damping ratio") into `physics`.
void parse_damping(ParameterHandler& prm, const std::string& section, MeshPhysics& physics)
{
  const std::string damping = prm.get("damping");
  if (damping == "auto")
  {
    physics.damping_ratio = prm.get_double("damping ratio");
    if (!(physics.damping_ratio > 0.))
      throw InputError(section + "/damping ratio",
                       "must be positive: without mesh damping the start-up transient never "
                       "decays, so there is no steady state to report");
    return;
  }
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

// The published Cai curve with peak `stiffness` [N/m] and the shape of "cai shape".
dynamics::CaiParameters parse_cai_shape(ParameterHandler& prm, const std::string& section,
                                        double stiffness)
{
  dynamics::CaiParameters cai = dynamics::cai_published_parameters(stiffness);
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
  return cai;
}

// Reads the entries of declare_mesh_physics inside the mesh's subsection `section`.
// `automatic_stiffness` [N/m]: what 'stiffness = auto' stands for (NaN: auto not offered).
MeshPhysics parse_mesh_physics(ParameterHandler& prm, const std::string& section,
                               double contact_ratio, double automatic_stiffness)
{
  MeshPhysics physics;
  parse_damping(prm, section, physics);
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
  const dynamics::CaiParameters cai = parse_cai_shape(prm, section, stiffness);
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
} // namespace

// parse_mesh_physics in the subsection `section`, which is left also when it throws.
MeshPhysics parse_mesh_physics_section(ParameterHandler& prm, const std::string& section,
                                       double contact_ratio, double automatic_stiffness)
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

void check_contact_loss(const MeshPhysics& physics, bool nonlinear, const std::string& section)
{
  if (nonlinear || !physics.stiffness.loses_contact())
    return;
  throw InputError(section + "/stiffness file",
                   "the table has positions without contact (a broken tooth: k = 0 from " +
                       format_number(physics.stiffness.first_lost_contact(), 6) +
                       " base pitches); the linear mesh law cannot separate the teeth, set "
                       "Simulation/mesh model = nonlinear");
}

void apply_mesh_physics(const MeshPhysics& physics, dynamics::Mesh& mesh)
{
  mesh.stiffness = physics.stiffness;
  mesh.damping = physics.damping;
  mesh.friction_coefficient = physics.friction_coefficient;
  mesh.driver_friction_arm = physics.driver_friction_arm;
  mesh.driven_friction_arm = physics.driven_friction_arm;
}

namespace
{
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
} // namespace

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
} // namespace gearstiff::app::dynamics_input

namespace gearstiff::app
{
using namespace dynamics_input;

// issue 30: the lateral model's view of a Train mesh (dynamics_parameters.h).
TrainMeshMean parse_train_mesh_mean(ParameterHandler& prm, unsigned int m, double contact_ratio,
                                    int teeth_a, int teeth_b, double module, double centre_distance,
                                    double automatic_stiffness)
{
  const std::string section = train_mesh_section(m);
  const MeshPhysics physics =
      parse_mesh_physics_section(prm, section, contact_ratio, automatic_stiffness);
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
    mean.stiffness_driver = dynamics::match_stiffness_file(
        *physics.file, teeth_a, teeth_b, module, centre_distance, section + "/stiffness file");
  prm.enter_subsection("Simulation");
  const bool nonlinear = prm.get("mesh model") == "nonlinear";
  prm.leave_subsection();
  check_contact_loss(physics, nonlinear, section);
  if (nonlinear)
  {
    // The lateral model's nonlinear meshes: the allowances' backlash is reported in the law.
    prm.enter_subsection("Train");
    const double pressure_angle = prm.get_double("pressure angle") * degree;
    prm.leave_subsection();
    std::vector<std::string> derived;
    mean.nonlinear = build_nonlinear_mesh(
        physics.nonlinear, section, static_cast<unsigned int>(std::abs(teeth_a)),
        {module, pressure_angle},
        [&](const dynamics::StiffnessFile& file, const std::string& parameter)
        {
          if (module > 0.)
            dynamics::match_stiffness_file(file, teeth_a, teeth_b, module, centre_distance,
                                           parameter);
        },
        derived);
  }
  return mean;
}
} // namespace gearstiff::app
