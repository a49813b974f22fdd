// The names of the speed sweeps' categorical columns (tables dynamics_speed_sweep,
// dynamics_nonlinear_sweep, dynamics_dte_waterfall, lateral_speed_sweep,
// lateral_train_speed_sweep): one list for every table, so that a status or a direction reads
// the same wherever it appears (ReportTable::set_categories).
#pragma once

#include "dynamics/simulation.h"

#include <map>
#include <string>

namespace gearstiff::app
{
// A point's dynamics::SweepStatus by a short name; the report's text states what each means
// (dynamics::sweep_status_name).
inline std::map<int, std::string> sweep_status_categories()
{
  using dynamics::SweepStatus;
  return {{static_cast<int>(SweepStatus::valid), "valid"},
          {static_cast<int>(SweepStatus::diverged), "diverged"},
          {static_cast<int>(SweepStatus::contact_loss), "contact loss"},
          {static_cast<int>(SweepStatus::not_steady), "not steady"}};
}

// The direction of a point's sweep: code 1 for a point of the descending sweep.
inline std::map<int, std::string> sweep_direction_categories()
{
  return {{0, "up"}, {1, "down"}};
}

// The report text that says what each status name means.
inline std::string sweep_status_meanings()
{
  using dynamics::SweepStatus;
  std::string text;
  for (const SweepStatus s : {SweepStatus::valid, SweepStatus::diverged, SweepStatus::contact_loss,
                              SweepStatus::not_steady})
    text += (text.empty() ? "" : "; ") + dynamics::sweep_status_name(s);
  return text;
}
} // namespace gearstiff::app
