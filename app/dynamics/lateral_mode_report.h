// The mode table and class counts of a lateral–torsional model, one stage
// (dynamics/lateral_model.h) or a train of stages (dynamics/lateral_train.h): the same columns and
// values for both, so that scripts and tests read them alike.
#pragma once

#include "app/core/report.h"
#include "dynamics/lateral_model.h"

#include <string>

namespace gearstiff::app
{
// Modes: any type with `frequencies` [Hz] and `groups` (dynamics::LateralModeGroup).
template <typename Modes>
void report_mode_classes(const Modes& modes, const std::string& table_name,
                         const std::string& theory, Report& report)
{
  auto& table =
      report.add_table(table_name, {"mode", "frequency", "class", "multiplicity", "group"},
                       {"-", "Hz", "-", "-", "-"});
  unsigned int counts[4] = {0, 0, 0, 0};
  for (std::size_t g = 0; g < modes.groups.size(); ++g)
  {
    const dynamics::LateralModeGroup& group = modes.groups[g];
    ++counts[static_cast<int>(group.type)];
    for (const unsigned int k : group.modes)
      table.add_row({double(k + 1), modes.frequencies[k], double(static_cast<int>(group.type)),
                     double(group.modes.size()), double(g + 1)});
  }
  report.add_text("mode classes", "0 = rotational (central members only rotate), 1 = "
                                  "translational (central members only translate), 2 = planet "
                                  "(central members still), 3 = mixed" +
                                      theory);
  report.add_value("rotational_groups", counts[0], "-", "rotational frequencies");
  report.add_value("translational_groups", counts[1], "-", "translational frequencies");
  report.add_value("planet_groups", counts[2], "-", "planet-mode frequencies");
  report.add_value("mixed_groups", counts[3], "-", "frequencies of mixed modes");
}
} // namespace gearstiff::app
