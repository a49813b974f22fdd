// The nonlinear mesh law (issue 29): transmission-error excitation, free play (backlash), tooth
// separation and back-flank contact, after Kahraman & Singh (1990) and Kahraman & Blankenship
// (1997), docs/references.md §7.
//
// Along the line of action, with δ the dynamic transmission error (DTE, the deflection of
// torsional_model.h) and e(x) the unloaded transmission error at mesh position x [base
// pitches], the flank approach is z = δ − e and the mesh force
//
//   F = k(x)·z + c·ż                 z > 0         drive flank in contact
//   F = 0                           −2b ≤ z ≤ 0    separated (free play 2b)
//   F = k_back(x)·(z + 2b) + c·ż     z < −2b       back flank in contact
//
// i.e. F = k·h(z) + c·ż·[in contact] with h the backlash function of Kahraman & Singh shifted
// by b, so that a pair in drive contact obeys exactly the linear law (F = k·(δ − e) + c·(δ̇ − ė)).
// The unloaded TE e(x) is what the flanks' geometry and deviations add to the rigid kinematics;
// from an FE sweep at load W, with loaded static TE s(x) and mesh stiffness k(x), the split
// e(x) = s(x) − W/k(x) makes the quasi-static solution δ = e + W/k reproduce s(x) exactly
// (dynamics/README.md "Nonlinear mesh").
#pragma once

#include "dynamics/mesh_stiffness.h"

#include <optional>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
enum class MeshModel
{
  linear,   // F = k·δ + c·δ̇ (negative forces allowed: outside the model)
  nonlinear // the law above
};
std::string mesh_model_name(MeshModel model);

// One sinusoid of the unloaded TE: amplitude·sin(2π·order·x + phase).
struct ExcitationHarmonic
{
  double order = 1.;     // [mesh orders] 1 = mesh frequency; 1/z = once per revolution of a gear
  double amplitude = 0.; // [m] along the line of action
  double phase = 0.;     // [rad]
};

// Unloaded transmission error e(x) [m] along the line of action: a periodic piecewise-linear
// table over one base pitch (the FE split) plus sinusoids. x is the mesh position [base
// pitches], not reduced (orders below 1 have periods of several pitches).
class TransmissionError
{
public:
  TransmissionError() = default; // zero
  // Positions [base pitches] strictly increasing in [0, 1), values [m]; InputError naming
  // `parameter` otherwise.
  static TransmissionError table(const std::vector<double>& positions,
                                 const std::vector<double>& values, const std::string& parameter);
  // InputError naming `parameter` for a non-positive order or a negative amplitude.
  void add_harmonic(const ExcitationHarmonic& harmonic, const std::string& parameter);

  double value(double mesh_position) const;
  // de/dx [m per base pitch]
  double slope(double mesh_position) const;
  double mean() const;         // [m] over the longest period (harmonics average to zero)
  double peak_to_peak() const; // [m] sampled over the longest period
  // [mesh orders] largest harmonic order (0 without harmonics; a table resolves itself: its
  // kinks are followed by the step control of the integrator)
  double highest_order() const;
  bool is_zero() const { return table_positions.empty() && harmonics.empty(); }
  const std::vector<ExcitationHarmonic>& excitation_harmonics() const { return harmonics; }
  // The same TE with the other gear driving (mesh_stiffness.h reversed): x → ε_α − x.
  TransmissionError reversed(double contact_ratio) const;
  std::string description() const;

private:
  std::vector<double> table_positions; // [base pitches]
  std::vector<double> table_values;    // [m]
  std::vector<ExcitationHarmonic> harmonics;
};

// What a mesh needs beyond the linear model.
struct NonlinearMesh
{
  // [m] 2b, free play between the drive and the back flanks along the line of action (the
  // normal backlash j_bn = j_t·cos α_t for spur gears, j_t the circular backlash).
  double backlash = 0.;
  TransmissionError transmission_error;
  // Back-flank stiffness k_back(x); nothing: the drive flank's mirrored, k(ε_α − x) (symmetric
  // teeth: the back flanks run the path of contact the other way).
  std::optional<MeshStiffness> back_stiffness;
  // The parameter section that describes this mesh ("Mesh 1", "Train mesh 2"): the library
  // names the mesh's fields (field::gear_mesh), app maps the harmonics' field to this section.
  std::string section;
};

// Contact state of a nonlinear mesh from the flank approach z = δ − e [m].
enum class ContactRegime
{
  drive = 0,
  separated = 1,
  back = 2
};
inline ContactRegime contact_regime(double approach, double backlash)
{
  return approach > 0. ? ContactRegime::drive
                       : (approach < -backlash ? ContactRegime::back : ContactRegime::separated);
}
// h(z): the elastic part of the flank approach [m].
inline double backlash_function(double approach, double backlash)
{
  return approach > 0. ? approach : (approach < -backlash ? approach + backlash : 0.);
}

// InputError naming the field "backlash" of mesh `m` of its train (field::gear_mesh:
// "mesh1.backlash", dynamics/fields.h) for a negative or non-finite free play, and
// "transmission_error" when e(x) varies by more than the free play: the back flanks would then
// be pressed together at some position without load (the pair jams, it cannot mesh).
void check_nonlinear_mesh(const NonlinearMesh& mesh, unsigned int m);

// The split of an FE loaded STE table into stiffness and unloaded TE: k(x) is the table's
// stiffness and W the load of the FE case. With the table's unloaded TE e(x) (`gearstiff
// stiffness` writes it: the modifications' geometric TE, and k = W/(s − e)), W = k·(s − e) at
// every row (checked to 1e-3) and e is the table's; without it W = k·s is checked and
// e(x) = s(x) − W/k(x) (a table with a tangent stiffness gives a non-zero e). An e below
// 1e-9·s everywhere is round-off and set exactly zero.
struct LoadedTransmissionErrorSplit
{
  double load = 0.;                   // [N] W along the line of action
  TransmissionError unloaded;         // e(x)
  double mean_loaded_error = 0.;      // [m] mean of s over the table (trapezoids, periodic)
  double largest_unloaded_error = 0.; // [m] max |s − W/k| before rounding to zero
};
LoadedTransmissionErrorSplit split_loaded_transmission_error(
    const std::vector<double>& positions, const std::vector<double>& stiffness,
    const std::vector<double>& loaded_error, const std::vector<double>& unloaded_error,
    const std::string& parameter);
} // namespace gearstiff::dynamics
