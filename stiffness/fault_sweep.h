// Mesh stiffness with one faulty tooth (issue 31): the FE sweep over the positions where the
// faulty tooth is in mesh (its pair from the start A to the end E of the path of contact), the
// healthy sweep over one base pitch at the same offsets, the potential-energy method
// (stiffness/potential_energy.h) beside both, and the whole-revolution table of the faulty gear
// (the healthy pitch repeated, the faulty positions where the faulty tooth meshes).
//
// Positions: ℓ_i = A + (i + ½)·p_bt/N, i = 0, 1, … while ℓ_i < E, with the faulty tooth the
// reference tooth of the scene (its pair j = 0 at ℓ_i); the healthy positions are the first N.
// Row i of the revolution table is X_i = (i + ½)/N base pitches after the faulty tooth entered
// contact at A, i < z·N (z the faulty gear's teeth: the table's period is one of its revolutions);
// the pinion angle of that row is θ_i = (A − ℓ_C)/r_b1 − f·2π/z1 + X_i·p_bt/r_b1 for pinion tooth f
// (tooth 0 at the pitch point C at θ = 0), the wheel's f meeting pinion tooth −f.
//
// Meshing (spec.mesh): per position, each position a scene of its own solved on the first rank;
// `once` (stiffness/mesh_stiffness_sweep.h), each of the two sweeps meshed and factorized once per
// rank and rolled, the positions shared by the ranks. `once` needs every flank whole at every
// position: a root crack (the cracked tooth turns with its gear) but not a broken, chipped or
// spalled tooth (the scene refuses it, InputError naming Stiffness/sweep mesh).
//
// Loss of contact: where the faulty tooth (broken, or chipped where it would touch) would carry
// alone, no pair touches: the row says so (lost_contact) and carries no stiffness (0 in the
// table, never a number from a solve); where it shares, the other pairs carry alone.
#pragma once

#include "stiffness/mesh_stiffness.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "stiffness/potential_energy.h"

#include <functional>
#include <mpi.h>
#include <string>
#include <vector>

namespace gearstiff::stiffness
{
struct FaultSweepSpec
{
  unsigned int positions_per_pitch = 16; // -, N
  bool wheel = false;                    // the faulty tooth is the wheel's (else the pinion's)
  int faulty_tooth = 0;                  // -, f, in the faulty gear's own frame
  SweepMesh mesh = SweepMesh::per_position;
};

struct FaultSweepRow
{
  double position = 0.;          // m, the faulty tooth's contact point ℓ_i from T1
  double mesh_position = 0.;     // -, (ℓ_i − A)/p_bt
  bool lost_contact = false;     // no pair touches (then faulty_stiffness and energy_faulty are 0)
  double healthy_stiffness = 0.; // N/m, FE at the same offset of the healthy pitch
  double faulty_stiffness = 0.;  // N/m, FE with the faulty tooth
  double healthy_transmission_error = 0.; // m
  double faulty_transmission_error = 0.;  // m
  double energy_healthy = 0.;             // N/m, potential-energy method, healthy
  double energy_faulty = 0.;              // N/m, potential-energy method, faulty (0: lost contact)
  unsigned int faulty_pairs = 0;          // -, pairs that carry with the fault
  // Pa·m^½, K_I and K_II at the tip of a root crack whose faces meet (2D; 0 otherwise or where
  // contact is lost): stiffness/crack_tip.h
  double mode_one = 0.;
  double mode_two = 0.;
  // -, the faulty tooth's share of the load (its pair), and the same tooth's share in the
  // healthy pitch at the same offset (0 where contact is lost)
  double faulty_share = 0.;
  double healthy_share = 0.;
};

struct FaultSweepResult
{
  std::vector<FaultSweepRow> rows; // where the faulty tooth meshes
  // The revolution table: X_i [base pitches], k [N/m] (0 where contact is lost), θ_i [rad].
  std::vector<double> revolution_position;
  std::vector<double> revolution_stiffness;
  std::vector<double> revolution_pinion_angle;
  std::vector<bool> revolution_lost_contact;
  unsigned int period_pitches = 0; // -, z of the faulty gear
  bool crack_tip_factors = false;  // the rows carry K_I/K_II (a root crack whose faces meet)
  // The energy method's SolverFailure, if it failed (then every energy value is 0 and unused).
  std::string energy_failure;
  double wall_time = 0.; // s
};

// `settings.scene` holds the fault on tooth `spec.faulty_tooth` of the gear `spec.wheel` (by_tooth;
// the other gear healthy, InputError otherwise). Positions solved one after another on the first
// rank of the communicator (each a scene of its own; `once`: shared by the ranks), results on
// every rank.
template <int dim>
FaultSweepResult fault_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                             const FaultSweepSpec& spec, const std::string& scene_file_stem,
                             const std::function<void(const std::string&)>& progress = {});
} // namespace gearstiff::stiffness
