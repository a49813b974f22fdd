// The solve steps shared by the stiffness, faults, cai and run commands: one position or a sweep
// of the parsed StiffnessParameters on the context's ranks.
#pragma once

#include "app/core/command.h"
#include "app/stiffness/stiffness_parameters.h"

namespace gearstiff::app
{
// One position (modes single, double, roll angle), solved on all ranks of the context.
// `label` names the VTU files when p.write_vtu is set.
stiffness::GearMeshStiffnessResult solve_stiffness_position(const StiffnessParameters& p,
                                                            CommandContext& context,
                                                            const std::string& label);
// The sweep of p.sweep, positions distributed over the ranks, progress on context.pcout.
stiffness::StiffnessSweepResult solve_stiffness_sweep(const StiffnessParameters& p,
                                                      CommandContext& context,
                                                      const std::string& label);
} // namespace gearstiff::app
