// The stiffness of one gear mesh as a function of the mesh position, from one of three sources:
// a constant, the Cai curve (docs/references.md §1) with published or calibrated parameters, or a
// k(x) table (e.g. from FE). Besides the stiffness it returns the direction of the tooth
// friction, which reverses where a pair passes the pitch point.
//
// Mesh position x [base pitches]: roll position of the pair that entered contact last (see
// cai_stiffness.h); the function is periodic in x with period 1, or, for a table over a whole
// revolution of a gear with a faulty tooth (issue 31, docs/faults.md), with a period of P base
// pitches (P = that gear's tooth count): the table is indexed by x modulo P, the pairs in
// contact (and the friction direction) by x modulo 1. For a contact ratio ε_α the pairs
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
  // Piecewise-linear periodic table: positions [base pitches] strictly increasing in
  // [0, period), stiffness [N/m] positive. Throws InputError naming `parameter` otherwise.
  // `period` [base pitches] > 1: a whole-revolution table. Rows flagged in `lost_contact`
  // (empty: none) are positions where no pair touches (a broken tooth's single-contact zone):
  // they must carry k = 0, and the table holds 0 from half-way to the neighbouring rows with
  // contact (no interpolated stiffness between a loaded row and one without contact).
  static MeshStiffness table(const std::vector<double>& positions,
                             const std::vector<double>& stiffness, const std::string& parameter,
                             unsigned int period = 1, const std::vector<bool>& lost_contact = {});

  MeshStiffnessState evaluate(double mesh_position, double contact_ratio,
                              double approach_ratio) const;
  // The stiffness alone [N/m], the same value as evaluate(): the integrators' hot path when
  // there is no friction (no division per pair, no direction).
  double stiffness(double mesh_position, double contact_ratio) const;
  // Mean over one mesh period [N/m] (exact for each source; a table over P pitches: over P).
  double mean_stiffness(double contact_ratio) const;
  // Largest value over one mesh period [N/m] (sampled finely, plus all the table nodes).
  double max_stiffness(double contact_ratio) const;
  // Mean friction direction over one mesh period [-] (sampled).
  double mean_friction_direction(double contact_ratio, double approach_ratio) const;

  // The same stiffness seen with the other gear driving: contact then runs from the other end of
  // the path, so a pair at roll position p is at ε_α − p of this one. A table maps
  // k'(x) = k((ε_α − x) mod P) (the pair that entered last is the one nearest the old end; over
  // a revolution table the sequence of pitches runs backwards, as the gears do), the
  // Cai bracket s → 1 − s; a constant stays.
  MeshStiffness reversed(double contact_ratio) const;

  StiffnessSource source() const { return kind; }
  // [base pitches] the period of k(x): 1, or P of a whole-revolution table.
  unsigned int period() const { return table_period; }
  // Whether some positions have no contact (k = 0 there: only the nonlinear mesh law, which
  // separates, can run such a table).
  bool loses_contact() const { return lost_contact_rows > 0; }
  // [base pitches] the first table position without contact (NaN: none).
  double first_lost_contact() const;
  const CaiParameters& cai_parameters() const { return cai_curve; }
  std::string description() const;

private:
  double table_value(double table_position) const;
  double table_position(double mesh_position) const; // [base pitches] in [0, period)

  StiffnessSource kind = StiffnessSource::constant;
  double constant_value = 0.;          // [N/m]
  CaiParameters cai_curve;             // Cai source
  std::vector<double> table_positions; // [base pitches]
  std::vector<double> table_stiffness; // [N/m] (0 at rows without contact)
  unsigned int table_period = 1;       // [base pitches]
  unsigned int lost_contact_rows = 0;  // [-] rows with k = 0
};
} // namespace gearstiff::dynamics
