#include "geometry/scene_common.h"

#include "errors/errors.h"
#include "geometry/fields.h"
#include "kinematics/hertz.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gearstiff::geometry
{
double hertz_half_width(const double force_per_length, const double radius_1, const double radius_2,
                        const double young_modulus_1, const double poisson_ratio_1,
                        const double young_modulus_2, const double poisson_ratio_2)
{
  const double inverse_radius = 1. / radius_1 + 1. / radius_2; // 1/∞ = 0 for a flat
  if (!(inverse_radius > 0.))
    throw InputError("contact geometry", "the surfaces do not form a convex contact "
                                         "(relative curvature not positive)");
  if (!(force_per_length > 0.))
    throw InputError("load", "the contact force must be positive for the Hertz estimate");
  return kinematics::hertz_line_contact(
             force_per_length, radius_1, radius_2,
             kinematics::effective_modulus(young_modulus_1, poisson_ratio_1, young_modulus_2,
                                           poisson_ratio_2))
      .half_width;
}

SizeGrading
contact_size_grading(const SceneMeshSettings& settings, std::vector<SceneContact>& contacts,
                     const std::function<double(const Eigen::Vector2d&)>& depth_below_surface)
{
  SizeGrading grading;
  for (auto& contact : contacts)
  {
    const bool have_width = contact.hertz_half_width > 0.;
    if (settings.contact_size > 0.)
      contact.contact_size = settings.contact_size;
    else if (have_width)
      contact.contact_size = 0.1 * contact.hertz_half_width; // ten cells across the half-width
    else
      throw InputError(field::mesh("contact_size"),
                       "must be given when the scene has no Hertz estimate");
    if (settings.fine_radius > 0.)
      contact.fine_radius = settings.fine_radius;
    else
      contact.fine_radius =
          have_width ? 1.5 * contact.hertz_half_width : 10. * contact.contact_size;
    grading.foci.push_back({contact.point, contact.contact_size, contact.fine_radius});
    if (!(settings.body_size > 0.) || !std::isfinite(settings.body_size))
      throw InputError(field::mesh("body_size"), "must be a positive number (mm)");
    if (!std::isfinite(contact.contact_size) || !std::isfinite(contact.fine_radius))
      throw InputError(field::mesh("contact_size"), "must be a finite number (mm)");
    // The parameter the user set is the one named: a given contact size larger than the body
    // size, or the automatic one (a tenth of the Hertz half-width) at a large load.
    if (!(settings.body_size >= contact.contact_size))
    {
      const std::string sizes = "contact size " + std::to_string(contact.contact_size * 1e3) +
                                " mm, body size " + std::to_string(settings.body_size * 1e3) +
                                " mm";
      if (settings.contact_size > 0.)
        throw InputError(field::mesh("contact_size"),
                         "must not exceed the body size (" + sizes + ")");
      throw InputError(field::mesh("body_size"),
                       "must not be smaller than the automatic contact size, a "
                       "tenth of the Hertz half-width at this load (" +
                           sizes + "): give a larger body size or a contact size");
    }
  }
  if (!(settings.growth_rate > 0.))
    throw InputError(field::mesh("growth_rate"), "must be positive");
  grading.growth_rate = settings.growth_rate;
  grading.body_size = settings.body_size;
  grading.largest_size = grading.body_size;
  grading.initial_contact_scale = settings.initial_contact_scale;
  if (depth_below_surface)
  {
    grading.largest_size = settings.rim_size > 0. ? settings.rim_size : 4. * settings.body_size;
    if (!(grading.largest_size >= grading.body_size))
      throw InputError(field::mesh("rim_size"), "must not be smaller than the body size");
    grading.coarse_size = [depth_below_surface, body = grading.body_size,
                           rate = grading.growth_rate](const Eigen::Vector2d& point)
    { return body + rate * std::max(0., depth_below_surface(point)); };
  }
  return grading;
}

std::vector<BoundaryPiece> arc_pieces(const Eigen::Vector2d& centre, const double radius,
                                      const double from, const double to, const int boundary_id)
{
  const unsigned int n_pieces =
      std::max(1u, static_cast<unsigned int>(std::ceil(std::abs(to - from) / (0.5 * M_PI) - 1e-9)));
  const auto point_at = [&](const double angle) -> Eigen::Vector2d
  { return centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)); };
  std::vector<BoundaryPiece> pieces(n_pieces);
  for (unsigned int k = 0; k < n_pieces; ++k)
  {
    pieces[k].kind = CurveKind::arc;
    pieces[k].arc_centre = centre;
    pieces[k].boundary_id = boundary_id;
    pieces[k].points = {point_at(from + (to - from) * k / n_pieces),
                        point_at(from + (to - from) * (k + 1) / n_pieces)};
  }
  return pieces;
}

BoundaryLoop circle_loop(const Eigen::Vector2d& centre, const double radius, const int boundary_id)
{
  BoundaryLoop loop;
  loop.pieces = arc_pieces(centre, radius, 0., 2. * M_PI, boundary_id);
  // Close exactly: cos(2π) is not bit-identical to cos(0).
  loop.pieces.back().points.back() = loop.pieces.front().points.front();
  return loop;
}

namespace
{
// m, the mean thickness of the thinnest body: area / perimeter (half a ring's rim width, half a
// disc's radius), the perimeter along the pieces' points (arcs by their chords).
double thinnest_body(const PlanarModel& model)
{
  double thinnest = std::numeric_limits<double>::infinity();
  const auto length = [](const BoundaryLoop& loop)
  {
    double sum = 0.;
    for (const auto& piece : loop.pieces)
      for (std::size_t i = 1; i < piece.points.size(); ++i)
        sum += (piece.points[i] - piece.points[i - 1]).norm();
    return sum;
  };
  for (const auto& body : model.bodies)
  {
    double area = std::abs(body.outer.signed_area()), perimeter = length(body.outer);
    for (const auto& hole : body.holes)
    {
      area -= std::abs(hole.signed_area());
      perimeter += length(hole);
    }
    if (area > 0. && perimeter > 0.)
      thinnest = std::min(thinnest, area / perimeter);
  }
  return thinnest;
}

SceneMeshSettings clamped_to_bodies(SceneMeshSettings settings, const PlanarModel& model)
{
  // Sizes beyond the bodies' own thickness leave gmsh a handful of triangles it cannot recombine
  // (100 mm sizes: "4 leftover Triangle 3 cells", exit 3): no size exceeds the thinnest body's
  // area/perimeter (a few cells across it); the sizes used are reported with the scene.
  const double largest = thinnest_body(model);
  if (!std::isfinite(largest))
    return settings;
  settings.body_size = std::min(settings.body_size, largest);
  if (settings.rim_size > 0.)
    settings.rim_size = std::min(settings.rim_size, 4. * largest);
  if (settings.contact_size > 0.)
    settings.contact_size = std::min(settings.contact_size, largest);
  return settings;
}
} // namespace

SceneInfo mesh_scene(const PlanarModel& model, std::vector<SceneContact> contacts,
                     const SceneMeshSettings& settings, const double face_width,
                     const std::string& file,
                     const std::function<double(const Eigen::Vector2d&)>& depth_below_surface,
                     const std::vector<SizeFocus>& extra_foci)
{
  const auto start = std::chrono::steady_clock::now();
  SceneInfo info;
  MeshOptions options;
  options.dimension = settings.dimension;
  options.layers = settings.layers;
  options.least_layers = settings.least_layers;
  options.element_degree = settings.element_degree;
  options.memory_limit = settings.memory_limit;
  options.face_width = face_width;
  options.side_face_boundary_id = scene_ids::side_faces;
  options.file = file;
  PlanarModel named = model;
  if (settings.dimension == 3)
    named.boundary_names[scene_ids::side_faces] = "side faces";

  SceneMeshSettings sized = settings;
  const auto graded = [&](const SceneMeshSettings& s)
  { return contact_size_grading(clamped_to_bodies(s, model), contacts, depth_below_surface); };
  const auto with_foci = [&](SizeGrading grading)
  {
    grading.foci.insert(grading.foci.end(), extra_foci.begin(), extra_foci.end());
    return grading;
  };
  // An automatic body size coarsens until the estimate fits (mesh_planar_model refuses it
  // otherwise, naming the parameter as before).
  for (unsigned int step = 0;
       settings.body_size_fits_cell_limit && settings.dimension == 3 &&
       step < SceneMeshSettings::body_size_steps &&
       (sized.rim_size <= 0. ||
        sized.body_size * SceneMeshSettings::body_size_step <= sized.rim_size) &&
       over_work_limit(estimate_mesh(named, with_foci(graded(sized)), options), options);
       ++step)
    sized.body_size *= SceneMeshSettings::body_size_step;
  const SizeGrading grading = graded(sized);
  info.mesh = mesh_planar_model(named, with_foci(grading), options);

  info.file = file;
  info.dimension = settings.dimension;
  info.face_width = face_width;
  for (const auto& body : model.bodies)
    info.material_names.emplace(body.material_id, body.name);
  info.boundary_names = named.boundary_names;
  info.contacts = contacts;
  info.contact_size = grading.smallest_size();
  for (const auto& focus : grading.foci)
    info.fine_radius = std::max(info.fine_radius, focus.radius);
  info.body_size = grading.body_size;
  info.rim_size = grading.largest_size;
  info.growth_rate = grading.growth_rate;
  info.time_total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return info;
}
} // namespace gearstiff::geometry
