// Shared fixtures of the lateral–torsional model tests (test_lateral_model.cc,
// test_lateral_train.cc).
#pragma once

#include "dynamics/lateral_model.h"

#include <cmath>

namespace gearstiff::dynamics::test
{
// Lin & Parker 1999, the example system (docs/references.md §12: their parameter table, also Lin's
// thesis 2000 Table C.1): masses m_s 0.4, m_r 2.35, m_c 5.43, m_p 0.66 kg; I/r² 0.39, 3.00, 6.29,
// 0.61 kg; base diameters sun 77.4, ring 275.0, planet 100.3 mm, carrier diameter 176.8 mm; mesh
// stiffness k_sp = k_rp = 5e8 N/m; bearing stiffness k_s = k_r = k_c = 1e8 N/m, pin k_p = 1e8 N/m;
// torsional k_ru = 1e9 N/m (the ring), k_su = k_cu = 0; pressure angle 24.6° for both meshes.
// With u = r·θ the radii drop out of the frequencies (only I/r² and k_u enter).
inline LateralStage lin_parker_example(unsigned int planets)
{
  auto central =
      [](double mass, double inertia_over_r2, double diameter, double bearing, double torsional_u)
  {
    LateralCentralMember m;
    m.mass = mass;
    m.radius = 0.5e-3 * diameter;
    m.moment_of_inertia = inertia_over_r2 * m.radius * m.radius;
    m.bearing_stiffness = bearing;
    m.torsional_stiffness = torsional_u * m.radius * m.radius; // k_u [N/m] → N·m/rad
    return m;
  };
  LateralStage stage;
  stage.sun = central(0.4, 0.39, 77.4, 1e8, 0.);
  stage.ring = central(2.35, 3.00, 275.0, 1e8, 1e9);
  stage.carrier = central(5.43, 6.29, 176.8, 1e8, 0.);
  stage.planet_mass = 0.66;
  stage.planet_base_radius = 0.5e-3 * 100.3;
  stage.planet_moment_of_inertia = 0.61 * stage.planet_base_radius * stage.planet_base_radius;
  stage.pin_stiffness = 1e8;
  stage.sun_mesh_stiffness = stage.ring_mesh_stiffness = 5e8;
  stage.sun_pressure_angle = stage.ring_pressure_angle = 24.6 * M_PI / 180.;
  stage.planet_angles = equally_spaced_angles(planets);
  // The example's carrier radius is too small for 5+ planets of this size by the pitch-circle
  // check; the tip circle is not given, so the base circle stands in (frequencies unaffected).
  stage.planet_tip_radius = stage.planet_base_radius * 0.5;
  return stage;
}

} // namespace gearstiff::dynamics::test
