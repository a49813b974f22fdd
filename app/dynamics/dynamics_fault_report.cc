#include "app/dynamics/dynamics_fault_report.h"

#include "dynamics/fault_signature.h"

#include <string>

namespace gearstiff::app
{
void report_fault_signature(const dynamics::TorsionalModel& model,
                            const dynamics::SimulationResult& result, Report& report)
{
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
  {
    const unsigned int period = model.train().meshes[m].stiffness.period();
    if (period < 2)
      continue;
    const dynamics::FaultSignature s = dynamics::fault_signature(result, m, period);
    const std::string& name = result.meshes[m].name;
    report.add_text("fault signature",
                    name + " runs a whole-revolution table of " + std::to_string(period) +
                        " base pitches: the excitation repeats once per revolution of the faulty "
                        "gear (f_r = f_m/" +
                        std::to_string(period) +
                        "), the window spans whole revolutions, and the spectrum has sidebands "
                        "at h·f_m ± s·f_r (table dynamics_sidebands; docs/faults.md)");
    report.add_value("revolution_frequency", s.revolution_frequency, "Hz",
                     name + " rotation frequency of the faulty gear f_r = f_m/P");
    report.add_value("window_revolutions", s.revolutions, "-",
                     "revolutions of the faulty gear in the window");
    report.add_value("sideband_ratio_max", s.largest_sideband_ratio, "-",
                     "largest force sideband h·f_m ± s·f_r (s ≠ 0, h ≤ 3, |s| ≤ 3) over the "
                     "force line at f_m");
    report.add_value("impulse_ratio", s.impulse_ratio, "-",
                     "largest mesh-force peak of a mesh period over the median peak: the "
                     "once-per-revolution impulse");
    report.add_value("revolution_repeat", s.revolution_repeat, "-",
                     "max |δ(t) − δ(t − 1/f_r)| over the last revolution / peak-to-peak δ");
    auto& table =
        report.add_table("dynamics_sidebands",
                         {"harmonic", "order", "frequency", "force_amplitude", "dte_amplitude"},
                         {"-", "-", "Hz", "N", "um"});
    for (const dynamics::SidebandLine& line : s.lines)
      table.add_row({double(line.harmonic), double(line.order), line.frequency, line.force,
                     line.deflection * 1e6});
    return;
  }
}
} // namespace gearstiff::app
