#include "app/cycloid/cycloid_scene_parameters.h"

#include "app/core/units.h"
#include "app/scenes/geometry_parameters.h"

namespace gearstiff::app
{
namespace
{
using dealii::ParameterHandler;
using geometry::CycloidSceneSpec;

// A length of the scene: its entry (mm in the file) and its member (m).
struct Length
{
  const char* name;
  double CycloidSceneSpec::*member;
  const char* documentation;
};

const Length lengths[] = {
    {"bore radius", &CycloidSceneSpec::bore_radius,
     "radius of the disc's eccentric-bearing bore [mm] (not published)"},
    {"output pin circle radius", &CycloidSceneSpec::output_pin_circle_radius,
     "radius of the circle through the pin and hole centres [mm] (not published)"},
    {"output pin hole radius", &CycloidSceneSpec::output_pin_hole_radius,
     "radius of the holes in the disc [mm] (not published)"},
    {"output pin radius", &CycloidSceneSpec::output_pin_radius,
     "radius of the output pins (with their sleeves); pin + e <= hole, the difference is the "
     "play [mm] (not published)"},
    {"output pin bore radius", &CycloidSceneSpec::output_pin_bore_radius,
     "bore of each pin, held by the rigid output member [mm]"},
    {"roller pin radius", &CycloidSceneSpec::roller_pin_radius,
     "fixed pin inside each roller [mm]"},
    {"disc width", &CycloidSceneSpec::disc_width,
     "disc thickness: the plane-stress thickness and the 3D extrusion [mm] (not published)"},
    {"contact clearance", &CycloidSceneSpec::contact_clearance,
     "rollers within this clearance of the disc are contacts, meshed finely [mm]"},
};
} // namespace

void declare_cycloid_scene_parameters(ParameterHandler& prm, const CycloidSceneSpec& defaults)
{
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  declare_cycloid_disc_parameters(prm);
  prm.enter_subsection("Cycloid scene");
  for (const Length& l : lengths)
    prm.declare_entry(l.name, format_number(defaults.*l.member / mm, 8), Double(0.),
                      l.documentation);
  prm.declare_entry("output pins", std::to_string(defaults.output_pins), Integer(0, 100),
                    "output pins, one in each hole of the disc [-] (not published)");
  prm.declare_entry("outline points per lobe", std::to_string(defaults.points_per_lobe),
                    Integer(5, 100000), "points per lobe of the disc outline spline [-]");
  prm.leave_subsection();
}

void parse_cycloid_scene_parameters(ParameterHandler& prm, CycloidSceneSpec& spec)
{
  spec.ring = parse_cycloid_disc_parameters(prm);
  prm.enter_subsection("Cycloid scene");
  for (const Length& l : lengths)
    spec.*l.member = prm.get_double(l.name) * mm;
  spec.output_pins = prm.get_integer("output pins");
  spec.points_per_lobe = prm.get_integer("outline points per lobe");
  prm.leave_subsection();
}
} // namespace gearstiff::app
