// Many cycloid load cases at once — crank-angle sweeps, torque ramps, refinement levels —
// distributed over the MPI ranks (each rank solves its share serially with CycloidLoads<2>, its
// own scene file; every rank receives all results), and the evaluations built on them: the
// torsional stiffness and lost motion of a torque ramp.
//
// A negative output torque is solved as the mirror image (about the x axis) of the drive under
// +|M_c|: crank angle −φ_h, profile rotation −δ, mirrored pin pattern; the forces and rotations
// are mirrored back. This is exact (the ring, the nominal lobes and the equidistant are mirror
// symmetric) and keeps every solve starting from the flank the torque closes: a corrected
// profile touches on one flank only, and the frictionless solve of a reversed torque from
// that reference would have to cross the play with no contact holding the disc.
#pragma once

#include "stiffness/cycloid_loads.h"

#include <functional>
#include <mpi.h>
#include <string>
#include <vector>

namespace gearstiff::stiffness
{
// One case of any sign of torque (see above). `scene_file` in `settings` is used as is.
CycloidLoadResult solve_cycloid_case(const CycloidLoadSettings& settings);

// Every case solved once, case k on rank k mod n_ranks (2D only), scene files
// "<stem>_<k>.msh" (removed after use). `progress` (may be empty) is called on the rank that
// solved a case, after each of its cases. A failing case stops all ranks with its exception type
// and message.
std::vector<CycloidLoadResult>
solve_cycloid_cases(MPI_Comm communicator, const std::vector<CycloidLoadSettings>& cases,
                    const std::string& scene_file_stem,
                    const std::function<void(const std::string&)>& progress = {});

// Crank angles of a sweep: `positions` equal steps from `start` over `span` (rad).
std::vector<double> crank_angles(double start, double span, unsigned int positions);

// Torsional stiffness and lost motion from θ(T) (robot-reducer catalogue definitions):
//  - lost motion: the rotation between the two branches' points at ±3% of the rated torque (for
//    a profile with play it contains the backlash: each sense is solved from its own flank);
//  - torsional stiffness: the secant slope between 50% and 100% of the rated torque, mean of
//    both directions.
struct TorsionalCurve
{
  std::vector<double> torques;   // N·m
  std::vector<double> rotations; // rad, output rotation θ
  double stiffness = 0.;         // N·m/rad
  double lost_motion = 0.;       // rad
  double hysteresis = 0.; // rad, largest |θ_unload − θ_load| at one torque (0: frictionless)
  double backlash = 0.;   // rad, closing rotation at +3% minus that at −3% (0: no play)
};
// The torque levels of a ramp −M → +M in `steps` equal steps (zero left out: nothing is loaded
// there) plus ±3%, ±50% and ±100% of M, ascending. Without friction each level is one
// independent solve (path independent) and the unloading branch repeats the loading one.
std::vector<double> torsional_levels(double rated_torque, unsigned int steps);
// From the results at those levels (any order).
TorsionalCurve torsional_curve(double rated_torque, const std::vector<CycloidLoadResult>& results);
} // namespace gearstiff::stiffness
