// The Cai stiffness curve of one tooth pair and its calibration to FE results.
//
// Source: Cai Y., "Simulation on the rotational vibration of helical gears in consideration of
// the tooth separation phenomenon", ASME J. Mech. Des. 117 (1995) 460, as used by Reszuta &
// Drewniak 2015 (docs: docs/references.md §1):
//
//   K(t) = 1/(0.85·ε_α) · ( −1.8/(t_z·ε_α)²·t² + 1.8/(t_z·ε_α)·t + 0.55 ),  0 ≤ t ≤ ε_α·t_z.
//
// Written in the pair's engagement fraction s = t/(ε_α·t_z) ∈ [0, 1] the bracket is the shape
// c2·s² + c1·s + c0 with (c0, c1, c2) = (0.55, 1.8, −1.8), whose peak at s = 1/2 is exactly 1.
// The stiffness of one pair is therefore k_pair(s) = scale · (c2·s² + c1·s + c0), and the
// paper's scaling (one pair's peak equals the FE single-pair stiffness k'_j) is scale = k'_j.
// The constant 1/(0.85·ε_α) of Cai's normalised form is absorbed into the scale.
//
// Positions: a pair's roll position p is measured along the path of contact from the start of
// active contact, in transverse base pitches, 0 ≤ p < ε_α, so s = p/ε_α. The mesh position
// x ∈ [0, 1) is the roll position of the pair that entered contact last; the pairs in contact
// sit at p = x, x + 1, ... (< ε_α), and the mesh stiffness is the sum over them.
#pragma once

#include <array>
#include <vector>

namespace gearstiff::dynamics
{
struct CaiParameters
{
  double scale = 0.; // [N/m] single-pair stiffness at the shape's peak (shape normalised to 1)
  std::array<double, 3> shape = {{0.55, 1.8, -1.8}}; // [-] c0, c1, c2 of c2·s² + c1·s + c0
};

// The published Cai shape scaled so one pair's peak equals `single_pair_peak` [N/m].
CaiParameters cai_published_parameters(double single_pair_peak);

// Stiffness [N/m] of one pair at engagement fraction s ∈ [0, 1]; zero outside (not in contact).
double cai_pair_stiffness(const CaiParameters& parameters, double engagement_fraction);

// Mesh stiffness [N/m]: the sum of the pairs in contact at mesh position x [base pitches]
// (taken modulo 1) for the transverse contact ratio ε_α.
double cai_mesh_stiffness(const CaiParameters& parameters, double mesh_position,
                          double contact_ratio);

// One stiffness-versus-position sample, e.g. from an FE run at one roll position.
struct StiffnessSample
{
  double position = 0.;  // [base pitches] roll position (see the kind of samples below)
  double stiffness = 0.; // [N/m]
};

enum class StiffnessSampleKind
{
  // Mesh stiffness (all pairs in contact) at mesh position x ∈ [0, 1).
  mesh,
  // Stiffness of one pair alone at roll position p ∈ [0, ε_α).
  single_pair
};

struct CaiFit
{
  CaiParameters parameters;
  double rms_residual = 0.; // [N/m] root-mean-square of sample minus fitted curve
  double max_residual = 0.; // [N/m] largest absolute residual
  unsigned int n_samples = 0;
  bool shape_fitted = false; // false: only the scale was fitted, the Cai shape kept
};

// Least-squares fit of the Cai curve to stiffness samples. With fit_shape = false only the
// scale is fitted (the published shape is kept); with fit_shape = true the three shape
// coefficients are fitted as well and then normalised so the shape peaks at 1 on [0, 1]
// (scale stays "the single-pair peak"). The model is linear in scale·(c0, c1, c2), so the fit
// is a linear least-squares problem solved by a column-pivoting QR (Eigen), exact in one step.
// Throws InputError("stiffness samples", ...) for too few samples, positions out of range or
// non-positive stiffness, and SolverFailure if the fitted shape is not positive over the
// engagement (a curve that cannot be a stiffness).
CaiFit fit_cai_parameters(const std::vector<StiffnessSample>& samples, double contact_ratio,
                          StiffnessSampleKind kind, bool fit_shape);
} // namespace gearstiff::dynamics
