#include "app/stiffness/face_load_report.h"

#include "app/core/report.h"

#include <algorithm>
#include <cmath>

namespace gearstiff::app
{
void report_face_load(CommandContext& context,
                      const std::vector<stiffness::GearMeshStiffnessResult>& positions)
{
  if (positions.empty() || positions.front().dimension != 3)
    return;
  Report& report = context.report;
  {
    ReportTable& lines = report.add_table("face_load", {"pinion_roll_angle", "z", "line_load"},
                                          {"deg", "mm", "N/mm"});
    for (const auto& r : positions)
    {
      const stiffness::FaceLoadSummary s = stiffness::summarise_face_load(r.face_load);
      for (std::size_t i = 0; i < s.z.size(); ++i)
        lines.add_row({r.pinion_roll_angle * 180. / M_PI, s.z[i] * 1e3, s.line_load[i] * 1e-3});
    }
  }
  ReportTable& factors = report.add_table(
      "face_load_factor",
      {"pinion_roll_angle", "face_load_factor", "peak_line_load", "mean_line_load", "peak_z"},
      {"deg", "-", "N/mm", "N/mm", "mm"});
  stiffness::FaceLoadSummary worst;
  for (const auto& r : positions)
  {
    const stiffness::FaceLoadSummary s = stiffness::summarise_face_load(r.face_load);
    factors.add_row({r.pinion_roll_angle * 180. / M_PI, s.factor, s.peak * 1e-3, s.mean * 1e-3,
                     s.peak_z * 1e3});
    if (s.factor > worst.factor)
      worst = s;
  }
  report.add_value("face_load_factor", worst.factor, "-",
                   "K_Hβ = peak/mean line load across the face width (largest over the positions)");
  report.add_value("peak_line_load", worst.peak * 1e-3, "N/mm",
                   "peak line load (at that position)");
  report.add_value("peak_line_load_z", worst.peak_z * 1e3, "mm",
                   "where across the face width the peak acts (z from the z = 0 face)");
  if (!context.writes_files() || !context.is_root())
    return;
  const TemporaryCsv csv(report, "face_load");
  context.plot("plot_contact_pattern.py", {csv.path()}, "contact_pattern.png",
               "contact pattern: line load across the face width at every position");
}
} // namespace gearstiff::app
