#include "app/stiffness/face_load_report.h"

#include "app/core/report.h"
#include "errors/format.h"

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

// -, the node planes below which the exact path's k on a contact ending inside the face is still
// moving with the layers. Measured 2026-12-04 (invariants case 29 of seed 20261201: z 25/85, m 2,
// b 14.4 mm, T1 16.0 N·m, C_β 13 µm on both gears, Q1, 2 positions, μ 0, 2 ranks, one run each;
// docs/ltca.md §3 "Lead modifications"): 16, 24, 32 layers load 5, 7, 11 planes, exact k
// 135.52, 135.54, 136.57 and 132.73, 133.13, 133.83 N/µm (−0.77/−0.82 % and −0.75/−0.52 %
// against 32 layers), while the influence-coefficient model moved +0.17/+0.01 % from 7 to 11.
constexpr unsigned int resolved_face_planes = 11;

void report_face_resolution(Report& report,
                            const std::vector<stiffness::GearMeshStiffnessResult>& positions,
                            unsigned int layers)
{
  if (positions.empty() || positions.front().dimension != 3)
    return;
  unsigned int fewest = 0;
  double angle = 0., from = 0., to = 0., width = 0.;
  for (const auto& r : positions)
  {
    const stiffness::FaceLoadSummary s = stiffness::summarise_face_load(r.face_load);
    if (s.z.size() < 2)
      continue;
    const double half_step = 0.5 * (s.z.back() - s.z.front()) / (s.z.size() - 1);
    std::vector<double> loaded;
    for (std::size_t i = 0; i < s.z.size(); ++i)
      if (s.line_load[i] > 0.)
        loaded.push_back(s.z[i]);
    if (loaded.empty() || loaded.front() <= s.z.front() + half_step ||
        loaded.back() >= s.z.back() - half_step)
      continue;
    const auto n = static_cast<unsigned int>(loaded.size());
    if (fewest == 0 || n < fewest)
    {
      fewest = n;
      angle = r.pinion_roll_angle;
      from = loaded.front();
      to = loaded.back();
      width = s.z.back() - s.z.front();
    }
  }
  if (fewest == 0 || fewest >= resolved_face_planes)
    return;
  const auto needed = static_cast<unsigned int>(
      std::ceil(static_cast<double>(layers) * resolved_face_planes / fewest));
  report.add_text(
      "face resolution",
      "the contact ends inside the face on only " + std::to_string(fewest) + " node planes (z " +
          format_number(from * 1e3, 4) + " … " + format_number(to * 1e3, 4) + " mm of " +
          format_number(width * 1e3, 4) + " mm at θ = " + format_number(angle * 180. / M_PI, 6) +
          "°): there k is still moving with the layers (a light load on crowned teeth: −0.8 % "
          "at 5 and 7 planes against 11, docs/ltca.md §3 \"Lead modifications\"); about " +
          std::to_string(needed) + " Mesh/layers load " + std::to_string(resolved_face_planes));
}
} // namespace gearstiff::app
