// Private to the dynamics parameter files (dynamics_parameters.cc: declaration and the whole
// parse; dynamics_mesh_parameters.cc: the entries of one mesh, "Mesh n" or "Train mesh n";
// dynamics_train_parameters.cc: the train, as "Gear n"/"Mesh n" or the Train description).
#pragma once

#include "app/dynamics/dynamics_parameters.h"
#include "dynamics/cai_stiffness.h"
#include "dynamics/nonlinear_mesh.h"
#include "dynamics/stiffness_file.h"
#include "dynamics/torsional_model.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gearstiff::app::dynamics_input
{
constexpr double micrometre = 1e-6;
constexpr double newton_per_mm = 1e3;            // N/mm → N/m
constexpr double newton_per_mm_micrometre = 1e9; // N/(mm·µm) → N/m²
// ISO 6336-1 (docs/references.md §5): c' ≈ 14 N/(mm·µm), the single stiffness of solid steel
// spur gears with the standard basic rack when the pair's own data are not used.
constexpr double iso_approximate_single_stiffness = 14. * newton_per_mm_micrometre; // N/m²

inline std::string gear_section(unsigned int i)
{
  return "Gear " + std::to_string(i + 1);
}
inline std::string mesh_section(unsigned int m)
{
  return "Mesh " + std::to_string(m + 1);
}
inline std::string train_mesh_section(unsigned int m)
{
  return "Train mesh " + std::to_string(m + 1);
}

// The comma-separated entries of `text` that are not blank.
std::vector<std::string> comma_entries(const std::string& text);

// ---- issue 29: the nonlinear mesh entries of "Mesh n" and "Train mesh n" ----
// The raw entries of the nonlinear law (the caller knows the pair to check a file against and
// the teeth for the pitch deviation's order).
struct NonlinearMeshEntries
{
  double backlash = 0.; // [m]
  std::string file;
  std::string back_file;                    // the back flanks' own FE table; empty: mirrored
  std::vector<double> thickness_allowances; // [m] A_sn1, A_sn2; empty: `backlash` as given
  double profile_deviation = 0.;            // [m] peak-to-peak
  double pitch_deviation = 0.;              // [m] peak-to-peak
  std::vector<dynamics::ExcitationHarmonic> harmonics;
};

// What the backlash from tooth-thickness allowances needs of the pair (spur, x = 0).
struct MeshGeometry
{
  double module = 0.;         // [m]
  double pressure_angle = 0.; // [rad] α_n
};
// Throws InputError naming `parameter` when the FE file is not of this mesh's pair.
using PairCheck =
    std::function<void(const dynamics::StiffnessFile& file, const std::string& parameter)>;

// The law of one mesh: backlash (given, or from the allowances: a line into `derived`), the TE
// from the file and from the deviations, the back flanks' own table; every file's pair checked
// by `check_pair`; `teeth` of the gear whose revolution the pitch deviation follows.
dynamics::NonlinearMesh build_nonlinear_mesh(const NonlinearMeshEntries& entries,
                                             const std::string& section, unsigned int teeth,
                                             const MeshGeometry& geometry,
                                             const PairCheck& check_pair,
                                             std::vector<std::string>& derived);

// A "Mesh n" pair is known by its driver's teeth and base radii: the file's pinion must be
// the driver (teeth equal, base radius within 1 %: the split path rounds r_b1 to 24.7 mm) and
// its wheel z1·r_b2/r_b1 teeth.
void check_numbered_mesh_pair(const dynamics::StiffnessFile& file, const dynamics::Mesh& mesh,
                              const std::string& parameter);

// ---- the entries every mesh has ----
// The entries a mesh needs whatever describes its gears: stiffness source, damping, friction.
// Shared by "Mesh n" (gears and meshes) and "Train mesh n" (Train description).
// `train_mesh` adds the source 'file' (a stiffness result of the FE commands): only a Train
// mesh knows its gears' teeth and modules, which the file must match.
void declare_mesh_physics(dealii::ParameterHandler& prm, double stiffness, double damping,
                          double friction, double driver_arm, double driven_arm, bool train_mesh);

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

// The entries of declare_mesh_physics in the subsection `section` (left also when it throws).
// `automatic_stiffness` [N/m]: what 'stiffness = auto' stands for (NaN: auto not offered).
MeshPhysics parse_mesh_physics_section(dealii::ParameterHandler& prm, const std::string& section,
                                       double contact_ratio,
                                       double automatic_stiffness = std::nan(""));

void apply_mesh_physics(const MeshPhysics& physics, dynamics::Mesh& mesh);

// A table with positions without contact (`gearstiff faults` with a broken tooth, docs/faults.md)
// runs only under the nonlinear mesh law: InputError naming `section`/stiffness file otherwise.
void check_contact_loss(const MeshPhysics& physics, bool nonlinear, const std::string& section);

// Mesh damping as a ratio (issue 25): c_g = 2ζ·√(k_m·m_e) for every mesh whose ζ (`ratios`,
// per model mesh) is a number; one line per such mesh with a section name (`sections`, per model
// mesh; empty: not reported) into `derived`.
void apply_damping_ratios(dynamics::GearTrain& train, const std::vector<double>& ratios,
                          const std::vector<std::string>& sections,
                          std::vector<std::string>& derived);

// ---- the train ----
// "Gear n" / "Mesh n" sections: a tree-shaped train in the two-gear mesh form.
void parse_numbered_train(dealii::ParameterHandler& prm, DynamicsParameters& p);
// The kinematics command's "Train" description plus "Train mesh n" sections.
void parse_train_description(dealii::ParameterHandler& prm, DynamicsParameters& p);
} // namespace gearstiff::app::dynamics_input
