#include "geometry/scene_cylinders.h"

#include "errors/errors.h"
#include "geometry/fields.h"
#include "kinematics/hertz.h"

#include <chrono>
#include <cmath>

namespace gearstiff::geometry
{
namespace
{
// The body of one cylinder: `side` +1 for the upper cylinder (centre above the origin),
// −1 for the lower one. The half-disc keeps the half that contains the contact point.
PlanarBody cylinder_body(const std::string& name, int material_id, double radius,
                         double bore_radius, int side, int contact_id, int bore_id, int cut_id)
{
  PlanarBody body;
  body.name = name;
  body.material_id = material_id;
  const Eigen::Vector2d centre(0., side * radius);
  // Polar angle of the contact point (the origin) seen from the centre.
  const double contact_angle = side > 0 ? -0.5 * M_PI : 0.5 * M_PI;
  if (bore_radius > 0.)
  {
    // Start the circle at the contact point so a junction (a mesh node) lies exactly there.
    body.outer.pieces =
        arc_pieces(centre, radius, contact_angle, contact_angle + 2. * M_PI, contact_id);
    body.outer.pieces.back().points.back() = body.outer.pieces.front().points.front();
    body.holes.push_back(circle_loop(centre, bore_radius, bore_id));
  }
  else
  {
    body.outer.pieces = arc_pieces(centre, radius, contact_angle - 0.5 * M_PI,
                                   contact_angle + 0.5 * M_PI, contact_id);
    BoundaryPiece flat;
    flat.kind = CurveKind::straight;
    flat.boundary_id = cut_id;
    flat.points = {body.outer.pieces.back().points.back(),
                   body.outer.pieces.front().points.front()};
    body.outer.pieces.push_back(flat);
  }
  return body;
}
} // namespace

SceneInfo write_cylinders_scene(const CylindersSceneSpec& spec, const std::string& file)
{
  const auto start = std::chrono::steady_clock::now();
  for (const auto& [value, bore, name] : {std::tuple{spec.radius_1, spec.bore_radius_1, "_1"},
                                          std::tuple{spec.radius_2, spec.bore_radius_2, "_2"}})
  {
    if (!(value > 0.))
      throw InputError(field::cylinders(std::string("radius") + name), "must be positive");
    if (!(bore >= 0. && bore < 0.8 * value))
      throw InputError(field::cylinders(std::string("bore_radius") + name),
                       "must be 0 (half-disc) or below 0.8 × the radius, so the contact "
                       "zone stays clear of the bore");
  }
  if (!(spec.length > 0.))
    throw InputError(field::cylinders("length"), "must be positive");
  kinematics::check_young_modulus(spec.young_modulus, field::cylinders("young_modulus"));
  kinematics::check_poisson_ratio(spec.poisson_ratio, field::cylinders("poisson_ratio"));

  SceneContact contact;
  contact.point = Eigen::Vector2d::Zero();
  contact.normal = Eigen::Vector2d(0., 1.);
  contact.first_curvature_radius = spec.radius_1;
  contact.second_curvature_radius = spec.radius_2;
  contact.normal_force = spec.force_per_length * spec.length;
  contact.hertz_half_width =
      hertz_half_width(spec.force_per_length, spec.radius_1, spec.radius_2, spec.young_modulus,
                       spec.poisson_ratio, spec.young_modulus, spec.poisson_ratio);
  if (!(contact.hertz_half_width < 0.2 * std::min(spec.radius_1, spec.radius_2)))
    throw InputError(field::cylinders("force_per_length"),
                     "gives a Hertz half-width beyond a fifth of the smaller radius, outside "
                     "the small-contact theory this scene verifies");

  PlanarModel model;
  model.bodies.push_back(cylinder_body("cylinder 1", scene_ids::first_body, spec.radius_1,
                                       spec.bore_radius_1, -1, scene_ids::first_contact,
                                       scene_ids::first_bore, scene_ids::first_cuts));
  model.bodies.push_back(cylinder_body("cylinder 2", scene_ids::second_body, spec.radius_2,
                                       spec.bore_radius_2, +1, scene_ids::second_contact,
                                       scene_ids::second_bore, scene_ids::second_cuts));
  model.boundary_names = {{scene_ids::first_contact, "cylinder 1 surface"},
                          {scene_ids::second_contact, "cylinder 2 surface"}};
  for (const auto& [bore, bore_id, cut_id, name] :
       {std::tuple{spec.bore_radius_1, scene_ids::first_bore, scene_ids::first_cuts, "1"},
        std::tuple{spec.bore_radius_2, scene_ids::second_bore, scene_ids::second_cuts, "2"}})
    if (bore > 0.)
      model.boundary_names[bore_id] = std::string("cylinder ") + name + " bore";
    else
      model.boundary_names[cut_id] = std::string("cylinder ") + name + " flat face";

  SceneInfo info = mesh_scene(model, {contact}, spec.mesh, spec.length, file);
  info.kind = "cylinders";
  info.first_centre = Eigen::Vector2d(0., -spec.radius_1);
  info.second_centre = Eigen::Vector2d(0., spec.radius_2);
  info.quantities = {
      {"radius_1", spec.radius_1, "m", "radius of cylinder 1"},
      {"radius_2", spec.radius_2, "m", "radius of cylinder 2"},
      {"hertz_half_width", contact.hertz_half_width, "m", "Hertz half-width a (plane strain)"},
      {"hertz_peak_pressure", 2. * spec.force_per_length / (M_PI * contact.hertz_half_width), "Pa",
       "Hertz peak pressure p0 = 2F'/(πa)"}};
  info.time_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return info;
}
} // namespace gearstiff::geometry
