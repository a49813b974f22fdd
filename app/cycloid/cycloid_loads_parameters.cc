#include "app/cycloid/cycloid_loads_parameters.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/cycloid/cycloid_scene_parameters.h"
#include "app/scenes/fe_contact_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "errors/errors.h"

#include <cmath>

namespace gearstiff::app
{
void declare_cycloid_loads_parameters(ParameterHandler& prm)
{
  const geometry::CycloidSceneSpec scene = stiffness::default_cycloid_load_scene();
  declare_cycloid_scene_parameters(prm, scene);
  declare_scene_mesh_parameters(prm, scene.mesh);
  declare_fe_contact_parameters(prm);
  prm.enter_subsection("Finite elements");
  // The disc is thin (15 mm against a 190 mm diameter): plane stress of the disc width.
  prm.set("Planar model", "plane stress");
  prm.set("Element degree", std::to_string(stiffness::default_cycloid_elasticity().degree));
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  // stiffness::default_cycloid_contact(): 5 µm (m → mm).
  prm.set("Overlap tolerance",
          format_number(stiffness::default_cycloid_contact().overlap_tolerance / mm, 6));
  prm.leave_subsection();

  prm.enter_subsection("Cycloid loads");
  prm.declare_entry("output torque", "440", Double(),
                    "M_c on the output member per disc [N·m], > 0; docs/references.md §4: 880 N·m "
                    "shared by two discs");
  prm.declare_entry("crank angle", "0", Double(-360., 360.),
                    "phi_h, direction of the eccentric: disc centre at e(cos phi_h, sin phi_h) "
                    "[deg]");
  prm.declare_entry("profiles", "both", Selection("nominal|corrected|both"),
                    "disc profiles solved: nominal equidistant, corrected (r_k, q_k, delta), both");
  prm.declare_entry("contact arc ratio", "0.27", Double(),
                    "epsilon of the corrected profile, in (0, 0.5) [-]");
  prm.declare_entry("clearance limit", "0.01", Double(0.), "Delta r of the correction [mm]");
  prm.declare_entry("sweep positions", "0", Integer(0, 10000),
                    "crank angles of the sweep, spread over the MPI ranks [-]; 0: no sweep");
  prm.declare_entry("sweep span", "18", Double(0., 360.),
                    "crank-angle span of the sweep [deg]; 360/z_k repeats the roller pattern");
  prm.declare_entry("torque steps", "0", Integer(0, 1000),
                    "steps of the torque ramp -M_c -> +M_c for the torsional stiffness and "
                    "lost motion [-]; 0: only the +-3%, 50%, 100% levels they need");
  prm.declare_entry("torsional curve", "true", Bool(),
                    "solve the torque levels of the torsional stiffness and lost motion");
  prm.declare_entry("Young's modulus", "210", Double(0.), "E of disc and pins [GPa]");
  prm.declare_entry("roller Young's modulus", "210", Double(0.), "E of the rollers [GPa]");
  prm.declare_entry("Poisson's ratio", "0.3", Double(0., 0.5), "nu of every body [-]");
  prm.declare_entry("write vtu", "false", Bool(), "VTU of the solved position(s) with -o");
  prm.leave_subsection();
}

CycloidLoadsParameters parse_cycloid_loads_parameters(ParameterHandler& prm)
{
  CycloidLoadsParameters p;
  stiffness::CycloidLoadSettings& s = p.settings;
  s.scene = stiffness::default_cycloid_load_scene();
  parse_cycloid_scene_parameters(prm, s.scene);
  s.scene.mesh = parse_scene_mesh_parameters(prm, s.scene.mesh);
  parse_fe_contact_parameters(prm, s.elasticity, s.linear_solver, s.contact);

  prm.enter_subsection("Cycloid loads");
  s.output_torque = prm.get_double("output torque");
  s.crank_angle = prm.get_double("crank angle") * degree;
  const std::string profiles = prm.get("profiles");
  p.nominal = profiles != "corrected";
  p.corrected = profiles != "nominal";
  p.contact_arc_ratio = prm.get_double("contact arc ratio");
  p.clearance_limit = prm.get_double("clearance limit") * mm;
  p.sweep_positions = prm.get_integer("sweep positions");
  p.sweep_span = prm.get_double("sweep span") * degree;
  p.torque_steps = prm.get_integer("torque steps");
  p.torsional = prm.get_bool("torsional curve");
  s.material.youngs_modulus = prm.get_double("Young's modulus") * 1e9;
  s.roller_material.youngs_modulus = prm.get_double("roller Young's modulus") * 1e9;
  s.material.poisson_ratio = s.roller_material.poisson_ratio = prm.get_double("Poisson's ratio");
  p.write_vtu = prm.get_bool("write vtu");
  prm.leave_subsection();

  if (!(s.output_torque > 0.))
    throw InputError(stiffness::field::cycloid_loads("output_torque"),
                     "must be positive (M_c per disc, N·m; the torque ramp covers both signs)");
  if (p.corrected && !(p.contact_arc_ratio > 0. && p.contact_arc_ratio < 0.5))
    throw InputError(stiffness::field::cycloid_loads("contact_arc_ratio"),
                     "epsilon must lie in (0, 0.5): the contact arc is a fraction of half a lobe");
  if (s.scene.output_pins == 0)
    throw InputError("Cycloid scene/output pins", "the output torque needs at least one pin");
  stiffness::check_cycloid_materials(s); // at parse time: no progress line before the error
  return p;
}
} // namespace gearstiff::app
