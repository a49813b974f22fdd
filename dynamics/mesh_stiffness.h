// The stiffness of one gear mesh as a function of the mesh position, from one of three sources:
// a constant, the Cai curve (docs/references.md §1) with published or calibrated parameters, or a
// k(x) table (e.g. from FE). Besides the stiffness it returns the direction of the tooth
// friction, which reverses where a pair passes the pitch point.
//
// Mesh position x [base pitches]: roll position of the pair that entered contact last (see
// cai_stiffness.h); the function is periodic in x with period 1. For a contact ratio ε_α the pairs
// in contact sit at roll positions p = x, x + 1, ... < ε_α. A pair is in approach (sliding one
// way) while p < ε_f, the approach ratio (start of active contact to pitch point, in base
// pitches), and in recess (sliding the other way) beyond it.
#pragma once

#include "dynamics/cai_stiffness.h"

#include <string>
#include <vector>

namespace gearstiff::dynamics
{
enum class StiffnessSource
{
  constant,
  cai,
  table
};

struct MeshStiffnessState
{
  double stiffness = 0.; // [N/m] mesh stiffness along the line of action
  // [-] Σ_j σ_j·w_j over the pairs in contact: σ_j = −1 in approach, +1 in recess, w_j the
  // pair's share of the mesh force (its share of the stiffness for Cai; equal shares for the
  // constant and table sources, which do not resolve single pairs). In [−1, 1].
  double friction_direction = 0.;
};

class MeshStiffness
{
public:
  MeshStiffness() = default;
  // `parameter` names the input in error messages (e.g. "Mesh 1/stiffness").
  static MeshStiffness constant(double stiffness, const std::string& parameter);
  static MeshStiffness cai(const CaiParameters& parameters, const std::string& parameter);
  // Piecewise-linear periodic table: positions [base pitches] strictly increasing in [0, 1),
  // stiffness [N/m] positive. Throws InputError naming `parameter` otherwise.
  static MeshStiffness table(const std::vector<double>& positions,
                             const std::vector<double>& stiffness, const std::string& parameter);

  MeshStiffnessState evaluate(double mesh_position, double contact_ratio,
                              double approach_ratio) const;
  // The stiffness alone [N/m], the same value as evaluate(): the integrators' hot path when
  // there is no friction (no division per pair, no direction).
  double stiffness(double mesh_position, double contact_ratio) const;
  // Mean over one mesh period [N/m] (exact for each source).
  double mean_stiffness(double contact_ratio) const;
  // Largest value over one mesh period [N/m] (sampled finely, plus the table nodes).
  double max_stiffness(double contact_ratio) const;
  // Mean friction direction over one mesh period [-] (sampled).
  double mean_friction_direction(double contact_ratio, double approach_ratio) const;

  // The same stiffness seen with the other gear driving: contact then runs from the other end of
  // the path, so a pair at roll position p is at ε_α − p of this one. A table maps
  // k'(x) = k(frac(ε_α − x)) (the pair that entered last is the one nearest the old end), the
  // Cai bracket s → 1 − s; a constant stays.
  MeshStiffness reversed(double contact_ratio) const;

  StiffnessSource source() const { return kind; }
  const CaiParameters& cai_parameters() const { return cai_curve; }
  std::string description() const;

private:
  double table_value(double mesh_position) const;

  StiffnessSource kind = StiffnessSource::constant;
  double constant_value = 0.;          // [N/m]
  CaiParameters cai_curve;             // Cai source
  std::vector<double> table_positions; // [base pitches]
  std::vector<double> table_stiffness; // [N/m]
};
} // namespace gearstiff::dynamics
