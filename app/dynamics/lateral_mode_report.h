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
  // The class is a name in every table writer (CSV, JSON, Python), not a code explained only in
  // the text report.
  table.set_categories("class",
                       {{0, "rotational"}, {1, "translational"}, {2, "planet"}, {3, "mixed"}});
  unsigned int counts[4] = {0, 0, 0, 0};
  for (std::size_t g = 0; g < modes.groups.size(); ++g)
  {
    const dynamics::LateralModeGroup& group = modes.groups[g];
    ++counts[static_cast<int>(group.type)];
    for (const unsigned int k : group.modes)
      table.add_row({double(k + 1), modes.frequencies[k], double(static_cast<int>(group.type)),
                     double(group.modes.size()), double(g + 1)});
  }
  report.add_text("mode classes", "rotational (central members only rotate), translational "
                                  "(central members only translate), planet (central members "
                                  "still), mixed" +
                                      theory);
  report.add_value("rotational_groups", counts[0], "-", "rotational frequencies");
  report.add_value("translational_groups", counts[1], "-", "translational frequencies");
  report.add_value("planet_groups", counts[2], "-", "planet-mode frequencies");
  report.add_value("mixed_groups", counts[3], "-", "frequencies of mixed modes");
}
} // namespace gearstiff::app
