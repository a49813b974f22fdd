#include "geometry/scene_cycloid.h"

#include "errors/errors.h"
#include "geometry/fields.h"

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>

namespace gearstiff::geometry
{
namespace
{
Eigen::Vector2d unit(double angle)
{
  return Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

// A circle loop starting at polar angle `start`, so that a mesh node lies exactly there.
BoundaryLoop circle_from(const Eigen::Vector2d& centre, double radius, double start, int id)
{
  BoundaryLoop loop;
  loop.pieces = arc_pieces(centre, radius, start, start + 2. * M_PI, id);
  loop.pieces.back().points.back() = loop.pieces.front().points.front();
  return loop;
}

// A contact between two bodies of the scene's material with the surfaces' curvature radii
// (> 0 convex), carrying `force` (N) over the disc width: its Hertz half-width. The caller
// places it (point, normal, gap, features).
SceneContact loaded_contact(const CycloidSceneSpec& spec, double first_curvature_radius,
                            double second_curvature_radius, double force)
{
  SceneContact contact;
  contact.first_curvature_radius = first_curvature_radius;
  contact.second_curvature_radius = second_curvature_radius;
  contact.normal_force = force;
  contact.hertz_half_width = hertz_half_width(
      force / spec.disc_width, first_curvature_radius, second_curvature_radius, spec.young_modulus,
      spec.poisson_ratio, spec.young_modulus, spec.poisson_ratio);
  return contact;
}

// The output pins in their holes (see the header): bodies, and one contact each where the pin
// meets its hole (on the side away from the disc centre's offset, or where the pins' turn
// output_pin_turn has moved it).
void add_output_pins(const CycloidSceneSpec& spec, const Eigen::Vector2d& disc_centre,
                     PlanarModel& model, std::vector<SceneContact>& contacts)
{
  const Eigen::Vector2d away = -disc_centre.normalized(); // from a hole to its unturned pin
  for (unsigned int j = 0; j < spec.output_pins; ++j)
  {
    const Eigen::Vector2d hole = output_hole_centre(spec, j, disc_centre);
    const Eigen::Vector2d centre = output_pin_centre(spec, j);
    // Unturned, the offset is −C: taken as such, not from the difference of the centres, whose
    // round-off moved a regression value by 7e-6 (a mesh that differs in its last digits).
    const Eigen::Vector2d offset =
        spec.output_pin_turn == 0. ? spec.ring.eccentricity * away : Eigen::Vector2d(centre - hole);
    const Eigen::Vector2d towards = offset.norm() > 1e-9 ? offset.normalized() : away;
    PlanarBody pin;
    pin.name = "output pins";
    pin.material_id = cycloid_ids::output_pin_body;
    pin.outer = circle_from(centre, spec.output_pin_radius, std::atan2(towards.y(), towards.x()),
                            cycloid_ids::output_pin_surfaces);
    pin.holes.push_back(
        circle_loop(centre, spec.output_pin_bore_radius, cycloid_ids::output_pin_bores));
    model.bodies.push_back(pin);

    SceneContact contact = loaded_contact(spec, -spec.output_pin_hole_radius, // concave
                                          spec.output_pin_radius, spec.pin_force);
    contact.point = centre + spec.output_pin_radius * towards;
    contact.normal = -towards; // out of the disc (the hole wall) into the hole
    contact.gap =
        spec.output_pin_turn == 0.
            ? spec.output_pin_hole_radius - spec.output_pin_radius - spec.ring.eccentricity
            : spec.output_pin_hole_radius - spec.output_pin_radius - offset.norm();
    contact.first_feature = static_cast<int>(j);
    contact.second_feature = static_cast<int>(j);
    contacts.push_back(contact);
  }
}

// The output pins must fit their holes with a bore inside each.
void check_output_pin_bodies(const CycloidSceneSpec& spec)
{
  if (!(spec.output_pin_radius + spec.ring.eccentricity <= spec.output_pin_hole_radius + 1e-12))
    throw InputError(field::cycloid_scene("output_pin_radius"),
                     "the pins do not fit their holes: pin radius + e = " +
                         std::to_string((spec.output_pin_radius + spec.ring.eccentricity) * 1e3) +
                         " mm exceeds the hole radius " +
                         std::to_string(spec.output_pin_hole_radius * 1e3) + " mm");
  if (!(spec.output_pin_bore_radius > 0. &&
        spec.output_pin_bore_radius < spec.output_pin_radius - 1e-3))
    throw InputError(field::cycloid_scene("output_pin_bore_radius"),
                     "must be positive and leave 1 mm of pin around it");
  if (!(spec.pin_force > 0.))
    throw InputError(field::cycloid_scene("pin_force"), "must be positive");
}

// Checks the scene's dimensions against the disc outline; returns the lobe root radius (m).
double check_cycloid_scene(const CycloidSceneSpec& spec, const CycloidDiscSpec& disc,
                           const ToothProfile& lobe)
{
  const CycloidDiscSpec& ring = spec.ring;
  if (disc.rollers != ring.rollers || std::abs(disc.eccentricity - ring.eccentricity) > 1e-12)
    throw InputError(field::cycloid_scene("disc"), "must have the ring's rollers and eccentricity");

  double lobe_root = std::numeric_limits<double>::infinity();
  for (const auto& p : lobe.points)
    lobe_root = std::min(lobe_root, p.position.norm());
  if (!(spec.bore_radius > 0.))
    throw InputError(field::cycloid_scene("bore_radius"), "must be positive");
  if (spec.output_pins > 0)
  {
    const double outer = spec.output_pin_circle_radius + spec.output_pin_hole_radius;
    const double inner = spec.output_pin_circle_radius - spec.output_pin_hole_radius;
    // At least 1 mm of material between neighbouring features: thinner webs are not a
    // drawing anyone would build, and they mesh into slivers.
    const double web = 1e-3;
    if (!(spec.output_pin_hole_radius > 0.) || outer > lobe_root - web)
      throw InputError(field::cycloid_scene("output_pin_hole_radius"),
                       "the holes must end 1 mm inside the lobe roots (" +
                           std::to_string(lobe_root * 1e3) + " mm)");
    if (inner < spec.bore_radius + web)
      throw InputError(field::cycloid_scene("output_pin_circle_radius"),
                       "the holes must stay 1 mm clear of the bore");
    // A single pin has no neighbour.
    if (spec.output_pins > 1 &&
        2. * spec.output_pin_circle_radius * std::sin(M_PI / spec.output_pins) <
            2. * spec.output_pin_hole_radius + web)
      throw InputError(field::cycloid_scene("output_pins"), "neighbouring holes overlap");
  }
  else if (spec.bore_radius > lobe_root - 1e-3)
    throw InputError(field::cycloid_scene("bore_radius"),
                     "leaves no disc material under the lobes");
  if (spec.output_pin_bodies && spec.output_pins > 0)
    check_output_pin_bodies(spec);
  if (!(spec.roller_pin_radius > 0. && spec.roller_pin_radius < 0.8 * ring.roller_radius))
    throw InputError(field::cycloid_scene("roller_pin_radius"), "must lie in (0, 0.8·q)");
  if (!(spec.disc_width > 0.))
    throw InputError(field::cycloid_scene("disc_width"), "must be positive");
  if (!(spec.roller_force > 0.))
    throw InputError(field::cycloid_scene("roller_force"), "must be positive");
  return lobe_root;
}

// Where the disc sits at rotation ψ: its centre (see the header) and the map from disc to scene
// coordinates.
struct DiscPlacement
{
  DiscPlacement(const CycloidSceneSpec& spec, unsigned int lobes)
      : centre(-spec.ring.eccentricity * unit(-double(lobes) * spec.disc_rotation)),
        to_scene(spec.disc_rotation)
  {
  }
  Eigen::Vector2d operator()(const Eigen::Vector2d& p) const { return centre + to_scene * p; }

  Eigen::Vector2d centre; // m
  Eigen::Rotation2Dd to_scene;
};

Eigen::Vector2d roller_centre(const CycloidDiscSpec& ring, unsigned int roller)
{
  return ring.roller_circle_radius * unit(2. * M_PI * roller / ring.rollers);
}

// The generating angle (rad) of the disc outline point closest to `local` (disc coordinates):
// golden-section search between the neighbours of the nearest outline point.
double closest_generating_angle(const CycloidDiscSpec& disc, unsigned int lobes,
                                unsigned int points, const Eigen::Vector2d& local)
{
  const double lobe_pitch = 2. * M_PI / lobes;
  double best = std::numeric_limits<double>::infinity(), best_alpha = 0.;
  for (unsigned int k = 0; k < lobes; ++k)
    for (unsigned int j = 0; j < points; ++j)
    {
      const double alpha = -M_PI / lobes + lobe_pitch * j / (points - 1) + k * lobe_pitch;
      const double distance = (cycloid_point(disc, alpha) - local).norm();
      if (distance < best)
        best = distance, best_alpha = alpha;
    }
  double low = best_alpha - lobe_pitch / (points - 1),
         high = best_alpha + lobe_pitch / (points - 1);
  const double golden = 0.5 * (std::sqrt(5.) - 1.);
  for (int it = 0; it < 60; ++it)
  {
    const double a = high - golden * (high - low), b = low + golden * (high - low);
    if ((cycloid_point(disc, a) - local).norm() < (cycloid_point(disc, b) - local).norm())
      high = b;
    else
      low = a;
  }
  return 0.5 * (low + high);
}

struct RollerContacts
{
  std::vector<SceneContact> contacts; // rollers within the contact clearance
  std::vector<double> contact_angles; // rad, per roller: polar angle of its closest disc point
};

// Contacts: the exact closest point of the equidistant to each roller centre, the clearance from
// prof's roller_clearances for the same placement.
RollerContacts roller_contacts(const CycloidSceneSpec& spec, const CycloidDiscSpec& disc,
                               const ToothProfile& lobe, const DiscPlacement& place)
{
  const CycloidDiscSpec& ring = spec.ring;
  const double psi = spec.disc_rotation;
  const std::vector<double> clearances = roller_clearances(ring, disc, psi);
  const unsigned int lobes = lobe.teeth;
  const double lobe_pitch = 2. * M_PI / lobes;
  RollerContacts result;
  result.contact_angles.assign(ring.rollers, 0.);
  for (unsigned int i = 0; i < ring.rollers; ++i)
  {
    const Eigen::Vector2d roller = roller_centre(ring, i);
    const Eigen::Vector2d local = place.to_scene.inverse() * (roller - place.centre);
    const double alpha = closest_generating_angle(disc, lobes, lobe.points.size(), local);
    const Eigen::Vector2d point = place(cycloid_point(disc, alpha));
    result.contact_angles[i] = std::atan2((point - roller).y(), (point - roller).x());
    if (clearances[i] > spec.contact_clearance)
      continue;
    SceneContact contact = loaded_contact(spec, cycloid_curvature_radius(disc, alpha),
                                          ring.roller_radius, spec.roller_force);
    contact.point = point;
    contact.normal = (roller - point).normalized();
    contact.gap = clearances[i];
    contact.first_feature = static_cast<int>(std::lround((alpha + psi) / lobe_pitch));
    contact.second_feature = static_cast<int>(i);
    result.contacts.push_back(contact);
  }
  if (result.contacts.empty())
    throw InputError(field::cycloid_scene("contact_clearance"),
                     "no roller lies within it at this disc rotation");
  return result;
}

PlanarBody disc_body(const CycloidSceneSpec& spec, const ToothProfile& lobe,
                     const DiscPlacement& place)
{
  PlanarBody body;
  body.name = "disc";
  body.material_id = scene_ids::first_body;
  // One closed spline through every lobe's points: pieces joined at the lobe gaps would meet
  // there with a kink of the interpolating spline (a few µm off the exact outline), right where
  // a roller sits in a gap in conformal contact — an initial overlap of that size.
  BoundaryPiece outline;
  outline.kind = CurveKind::spline;
  outline.boundary_id = scene_ids::first_contact;
  const unsigned int lobes = lobe.teeth;
  const double lobe_pitch = 2. * M_PI / lobes;
  for (unsigned int k = 0; k < lobes; ++k)
  {
    const Eigen::Rotation2Dd lobe_rotation(k * lobe_pitch);
    for (unsigned int j = k == 0 ? 0 : 1; j < lobe.points.size(); ++j)
      outline.points.push_back(place(lobe_rotation * lobe.points[j].position));
  }
  outline.points.back() = outline.points.front();
  body.outer.pieces.push_back(outline);
  body.holes.push_back(circle_loop(place.centre, spec.bore_radius, scene_ids::first_bore));
  for (unsigned int j = 0; j < spec.output_pins; ++j)
    body.holes.push_back(circle_loop(output_hole_centre(spec, j, place.centre),
                                     spec.output_pin_hole_radius, scene_ids::output_pin_holes));
  return body;
}

// The rollers, each starting its outline where the disc comes closest (a mesh node there).
void add_rollers(const CycloidSceneSpec& spec, const std::vector<double>& contact_angles,
                 PlanarModel& model)
{
  const CycloidDiscSpec& ring = spec.ring;
  for (unsigned int i = 0; i < ring.rollers; ++i)
  {
    const Eigen::Vector2d centre = roller_centre(ring, i);
    PlanarBody roller;
    roller.name = "rollers";
    roller.material_id = scene_ids::second_body;
    roller.outer =
        circle_from(centre, ring.roller_radius, contact_angles[i], scene_ids::second_contact);
    roller.holes.push_back(circle_loop(centre, spec.roller_pin_radius, scene_ids::second_bore));
    model.bodies.push_back(roller);
  }
}

std::map<int, std::string> cycloid_boundary_names(const CycloidSceneSpec& spec)
{
  std::map<int, std::string> names = {{scene_ids::first_bore, "disc bore"},
                                      {scene_ids::second_bore, "roller pins"},
                                      {scene_ids::first_contact, "disc lobes"},
                                      {scene_ids::second_contact, "roller surfaces"},
                                      {scene_ids::output_pin_holes, "output pin holes"}};
  if (spec.output_pin_bodies)
  {
    names[cycloid_ids::output_pin_bores] = "output pin bores";
    names[cycloid_ids::output_pin_surfaces] = "output pin surfaces";
  }
  return names;
}

// Away from the contacts the disc (below its lobe roots) and the rollers (below their surface)
// only carry load to the bore and the pins: the depth (m) below the nearest such surface, along
// which the cells grow.
std::function<double(const Eigen::Vector2d&)>
depth_below_surfaces(const CycloidSceneSpec& spec, const Eigen::Vector2d& disc_centre,
                     double lobe_root)
{
  std::vector<Eigen::Vector2d> roller_centres;
  for (unsigned int i = 0; i < spec.ring.rollers; ++i)
    roller_centres.push_back(roller_centre(spec.ring, i));
  std::vector<Eigen::Vector2d> pin_centres;
  for (unsigned int j = 0; spec.output_pin_bodies && j < spec.output_pins; ++j)
    pin_centres.push_back(output_pin_centre(spec, j));
  return [=, q = spec.ring.roller_radius, p = spec.output_pin_radius](const Eigen::Vector2d& x)
  {
    double result = lobe_root - (x - disc_centre).norm();
    for (const auto& c : roller_centres)
      result = std::max(result, q - (x - c).norm());
    for (const auto& c : pin_centres)
      result = std::max(result, p - (x - c).norm());
    return result;
  };
}

std::vector<SceneQuantity> cycloid_quantities(const CycloidSceneSpec& spec, unsigned int lobes,
                                              std::size_t rollers_in_contact, double lobe_root)
{
  const CycloidDiscSpec& ring = spec.ring;
  return {{"disc_rotation", spec.disc_rotation, "rad", "disc rotation ψ"},
          {"rollers", double(ring.rollers), "-", "rollers z_k (all modelled)"},
          {"lobes", double(lobes), "-", "disc lobes z_s"},
          {"rollers_in_contact", double(rollers_in_contact), "-",
           "rollers within the contact clearance"},
          {"disc_bore_radius", spec.bore_radius, "m", "disc bore radius"},
          {"output_pin_holes", double(spec.output_pins), "-", "output-pin holes"},
          {"output_pin_hole_radius", spec.output_pin_hole_radius, "m", "output-pin hole radius"},
          {"output_pin_bodies", spec.output_pin_bodies ? double(spec.output_pins) : 0., "-",
           "output pins meshed in their holes"},
          {"output_pin_play",
           spec.output_pin_hole_radius - spec.output_pin_radius - ring.eccentricity, "m",
           "radial play of each pin in its hole (hole − pin − e)"},
          {"lobe_root_radius", lobe_root, "m", "smallest radius of the disc outline"}};
}
} // namespace

Eigen::Vector2d output_pin_centre(const CycloidSceneSpec& spec, unsigned int pin)
{
  return spec.output_pin_circle_radius *
         unit(spec.disc_rotation + spec.output_pin_phase + spec.output_pin_turn +
              2. * M_PI * pin / spec.output_pins);
}

bool has_output_pin_play(const CycloidSceneSpec& spec)
{
  return spec.output_pin_hole_radius - spec.output_pin_radius - spec.ring.eccentricity > 1e-9;
}

Eigen::Vector2d output_hole_centre(const CycloidSceneSpec& spec, unsigned int pin,
                                   const Eigen::Vector2d& disc_centre)
{
  return disc_centre +
         spec.output_pin_circle_radius *
             unit(spec.disc_rotation + spec.output_pin_phase + 2. * M_PI * pin / spec.output_pins);
}

SceneInfo write_cycloid_scene(const CycloidSceneSpec& spec, const std::string& file)
{
  const auto start = std::chrono::steady_clock::now();
  const CycloidDiscSpec& ring = spec.ring;
  const CycloidDiscSpec disc = spec.disc.rollers == 0 ? ring : spec.disc;
  // The profile generator checks the disc itself (m < 1, rollers that fit).
  const ToothProfile lobe = generate_cycloid_disc(disc, spec.points_per_lobe);
  const double lobe_root = check_cycloid_scene(spec, disc, lobe);

  const unsigned int lobes = lobe.teeth;
  const DiscPlacement placement(spec, lobes);
  RollerContacts rollers = roller_contacts(spec, disc, lobe, placement);
  PlanarModel model;
  model.bodies.push_back(disc_body(spec, lobe, placement));
  if (spec.output_pin_bodies)
    add_output_pins(spec, placement.centre, model, rollers.contacts);
  add_rollers(spec, rollers.contact_angles, model);
  model.boundary_names = cycloid_boundary_names(spec);

  // At the rollers, seated in the lobe gaps in near-conformal contact, gmsh's longest edges
  // reach about 1.9 times the requested size (1.87–1.96 at 0.6 h_c for crank angles 0° and 9°
  // of the built-in drive, against 1.45 at gear teeth): aim lower at once instead of meshing
  // the whole scene twice (at 0.48, 6 of 8 crank angles over one roller pitch mesh once).
  SceneMeshSettings mesh = spec.mesh;
  mesh.initial_contact_scale = 0.48;
  SceneInfo info = mesh_scene(model, rollers.contacts, mesh, spec.disc_width, file,
                              depth_below_surfaces(spec, placement.centre, lobe_root));
  info.kind = "cycloid";
  info.first_centre = placement.centre;
  info.second_centre = Eigen::Vector2d::Zero();
  info.first_rotation = spec.disc_rotation;
  info.quantities = cycloid_quantities(spec, lobes, rollers.contacts.size(), lobe_root);
  info.time_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return info;
}
} // namespace gearstiff::geometry
