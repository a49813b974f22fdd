// `gearstiff dynamics` with a whole-revolution stiffness table (issue 31, docs/faults.md): the
// fault signature of the first mesh that runs one (dynamics/fault_signature.h) in the report.
#pragma once

#include "app/core/report.h"
#include "dynamics/simulation.h"

namespace gearstiff::app
{
// Nothing when no mesh of `model` runs a table of several base pitches.
void report_fault_signature(const dynamics::TorsionalModel& model,
                            const dynamics::SimulationResult& result, Report& report);
} // namespace gearstiff::app
