// The 3D influence-coefficient sweep of an unmodified external spur pair (docs/ltca.md §3): the
// extruded scene meshed with flank cells sized for bending, bores clamped, K factored once; the
// face cut into the FE body's hexahedron layers, and on every flank that meshes a grid of
// (line-of-action point ℓ) × (layer). A grid point's load is a unit force spread uniformly over
// its layer along the flank's contact line, read at the matching depth under the layer's middle;
// above that depth each layer carries the plane-strain Hertz layer of its own line load (a
// uniform line load's layer is plane strain; the FE body couples the layers below the depth).
// Each position is the small complementarity problem of stiffness/ltca_contact.h with one
// unknown per (pair, layer).
#include "errors/errors.h"
#include "errors/format.h"
#include "stiffness/face_load.h"
#include "stiffness/influence_body.h"
#include "stiffness/influence_sweep.h"
#include "stiffness/ltca_contact.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace gearstiff::stiffness::influence
{
using namespace dealii;

namespace
{
// h_f of the 3D body in normal modules: twice the 2D body's (0.2 mm for the default pair), so
// that the extruded body stays near the exact 3D scene's size (docs/ltca.md §3, measured there).
constexpr double flank_cell_modules_3d = 0.08;
// h = 3·h_f, as in 2D (a point or line load's FE response is right three cells away).
constexpr double matching_depth_cells_3d = 3.;
// The load points lie this many cells inside the surface: the meshed flank is a chord polygon of
// the involute, whose sagitta h_f²/(8ρ) reaches 1 µm for h_f = 0.2 mm at ρ = 5 mm; 4 µm under a
// read 0.6 mm deep changes nothing the read sees.
constexpr double inset_cells_3d = 0.02;

// The coefficients of both gears on the grid (ℓ_g of every pair's grid) × (layer s), item
// (g, s) at index g·layers + s, interpolated along ℓ as in 2D: the same flank along its
// diagonal samples, different flanks bilinearly.
class FaceCompliance
{
public:
  FaceCompliance(const BodyModel<3>& model, const PairFrame& frame, std::vector<FlankGrid> grids,
                 double step, double depth, double inset, unsigned int layers, double face_width)
      : grids(std::move(grids)), step(step), layers(layers)
  {
    const double dz = face_width / layers;
    // Two Gauss points per layer integrate the Q1/Q2 shape functions along z exactly: the load
    // is uniform over the layer, as the layer's line load of the contact problem.
    const double gauss = 0.5 * dz / std::sqrt(3.);
    for (const bool wheel : {false, true})
    {
      std::vector<BodyPoint<3>> loads, reads;
      for (const FlankGrid& grid : this->grids)
        for (unsigned int g = 0; g < grid.count; ++g)
        {
          const FlankPoint p = flank_point(frame, grid.pair, grid.first + g * step, wheel);
          const Point<2> load = p.surface + inset * p.inward, read = p.surface + depth * p.inward;
          const Tensor<1, 3> along({p.inward[0], p.inward[1], 0.});
          for (unsigned int s = 0; s < layers; ++s)
          {
            const double z = (s + 0.5) * dz;
            loads.push_back(
                {{Point<3>(load[0], load[1], z - gauss), Point<3>(load[0], load[1], z + gauss)},
                 {0.5, 0.5},
                 along,
                 p.body});
            reads.push_back({{Point<3>(read[0], read[1], z)}, {1.}, along, p.body});
          }
        }
      (wheel ? wheel_c : pinion_c) = body_compliance(model, loads, reads);
    }
  }

  // m/N, both gears: layer s of pair j at ℓ_j loaded, layer t of pair k at ℓ_k read.
  double operator()(int j, double at_j, unsigned int s, int k, double at_k, unsigned int t) const
  {
    const auto [first_j, u_j] = locate_on_grid(grids, step, j, at_j);
    const auto [first_k, u_k] = locate_on_grid(grids, step, k, at_k);
    const auto item = [this](std::size_t g, unsigned int layer) { return g * layers + layer; };
    double c = 0.;
    for (const auto* m : {&pinion_c, &wheel_c})
    {
      const auto at = [&](std::size_t a, std::size_t b) { return (*m)[item(a, s)][item(b, t)]; };
      if (j == k)
        c += (1. - u_j) * at(first_j, first_j) + u_j * at(first_j + 1, first_j + 1);
      else
        c += (1. - u_j) * ((1. - u_k) * at(first_j, first_k) + u_k * at(first_j, first_k + 1)) +
             u_j * ((1. - u_k) * at(first_j + 1, first_k) + u_k * at(first_j + 1, first_k + 1));
    }
    return c;
  }
  std::size_t n_points() const { return pinion_c.size() / layers; }

private:
  std::vector<FlankGrid> grids;
  double step;
  unsigned int layers;
  std::vector<std::vector<double>> pinion_c, wheel_c;
};

struct FaceModel
{
  const PairFrame& frame;
  const FaceCompliance& compliance;
  LayerBody body;
  unsigned int layers = 0;
  double face_width = 0.; // m, b
};

// One position at one torque from the solved layer forces (item k·layers + s of pair k), as
// GearMeshStiffness reports a 3D solve; root stresses are not evaluated (NaN).
GearMeshStiffnessResult face_result(const FaceModel& model, double position,
                                    const std::vector<int>& pairs,
                                    const MeshContactSolution& solution, double torque)
{
  const double r_b1 = model.frame.pinion_base_radius(), r_b2 = model.frame.wheel_base_radius();
  const double dz = model.face_width / model.layers;
  // Unmodified flanks (the model refuses modifications): the unloaded TE is 0.
  GearMeshStiffnessResult r =
      result_at(model.frame, 3, position, pairs.size(), torque, solution, 0.);
  const double total = torque / r_b1; // Σ F: every force on the line of action (frictionless)
  r.torque_ratio = r_b2 / r_b1;
  r.wheel_torque = total * r_b2;
  r.pinion_hub_torque = -torque;
  r.tangential_force = total;
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    // The pair's force over its layers, its highest peak pressure and widest contact band.
    double force = 0., peak = 0., widest = 0.;
    for (unsigned int s = 0; s < model.layers; ++s)
    {
      const std::size_t item = k * model.layers + s;
      force += solution.force[item];
      peak = std::max(peak, solution.contact[item].peak_pressure);
      widest = std::max(widest, solution.contact[item].half_width);
      r.face_load.push_back({pairs[k], (s + 0.5) * dz, solution.force[item] / dz});
    }
    add_pair_load(r, model.frame, position, pairs[k], force, total, peak, widest);
  }
  r.face_load_factor = summarise_face_load(r.face_load).factor;
  return r;
}

std::vector<GearMeshStiffnessResult> solve_face_position(const FaceModel& model, double position,
                                                         const std::vector<double>& torques,
                                                         std::map<int, double>& warm,
                                                         unsigned int& newton_steps)
{
  const kinematics::GearPairGeometry& pair = model.frame.pair;
  const std::vector<int> pairs = geometry::gear_pairs_in_contact(pair, position);
  const auto key = [&model](int j, unsigned int s)
  { return j * static_cast<int>(model.layers) + static_cast<int>(s); };
  MeshContactProblem problem;
  problem.face_width = model.face_width / model.layers; // each unknown is one layer's force
  problem.pinion = problem.wheel = model.body;
  std::vector<double> at;
  for (const int j : pairs)
    at.push_back(position + j * pair.transverse_base_pitch);
  for (std::size_t a = 0; a < pairs.size(); ++a)
    for (unsigned int s = 0; s < model.layers; ++s)
    {
      // ρ1 = ℓ, ρ2 = T1T2 − ℓ of the external pair (docs/ltca.md §3).
      problem.relative_radius.push_back(1. / (1. / at[a] + 1. / (model.frame.t2 - at[a])));
      problem.separation.push_back(0.);
      problem.strip.emplace_back();
      problem.compliance.emplace_back();
      for (std::size_t b = 0; b < pairs.size(); ++b)
        for (unsigned int t = 0; t < model.layers; ++t)
          problem.compliance.back().push_back(
              model.compliance(pairs[a], at[a], s, pairs[b], at[b], t));
    }
  std::vector<int> keys;
  for (const int j : pairs)
    for (unsigned int s = 0; s < model.layers; ++s)
      keys.push_back(key(j, s));
  return solve_torques(problem, model.frame, keys, torques, warm, newton_steps,
                       [&](const MeshContactSolution& solution, double torque)
                       { return face_result(model, position, pairs, solution, torque); });
}
} // namespace

InfluenceRun run_influence_3d(const GearMeshStiffnessSettings& settings,
                              const kinematics::GearPairGeometry& pair,
                              const std::vector<double>& positions,
                              const std::vector<double>& torques, const std::string& file,
                              const std::function<void(const std::string&)>& progress)
{
  InfluenceRun run;
  InfluenceModelInfo& info = run.info;
  info.grid_points = settings.influence_grid_points;
  info.flank_cell_size = flank_cell_modules_3d * pair.spec.pinion.normal_module;
  info.matching_depth = matching_depth_cells_3d * info.flank_cell_size;
  info.grid_step = pair.path_of_contact / (info.grid_points - 1);
  if (info.grid_step > info.matching_depth)
    throw InputError(stiffness_parameter::influence_grid_points,
                     "too coarse: the grid step " + format_number(info.grid_step * 1e3, 4) +
                         " mm along the line of action exceeds the matching depth " +
                         format_number(info.matching_depth * 1e3, 4) + " mm; use more points");
  PairFrame frame(pair);
  const unsigned int layers = settings.scene.mesh.layers;
  const double face_width = pair.common_face_width;

  auto start = std::chrono::steady_clock::now();
  const geometry::GearPairScene scene =
      geometry::write_gear_pair_scene(body_scene(settings, positions, frame.pinion_base_radius(),
                                                 info.flank_cell_size, info.matching_depth, 3),
                                      file);
  info.scene_time = seconds_since(start);
  frame.scene_position = scene.reference_position;

  start = std::chrono::steady_clock::now();
  const BodyModel<3> model = factor_body_model<3>(settings, file);
  info.n_dofs = model.system->get_dof_handler().n_dofs();
  info.factorization_time = seconds_since(start);
  if (progress)
    progress("influence coefficients (3D): FE body " + std::to_string(info.n_dofs) + " DoFs, h_f " +
             format_number(info.flank_cell_size * 1e3, 3) + " mm, " + std::to_string(layers) +
             " layers, factored in " + format_number(info.factorization_time, 3) + " s");

  start = std::chrono::steady_clock::now();
  const std::vector<FlankGrid> grids = flank_grids(pair, positions, info.grid_step);
  info.flanks = 2 * grids.size();
  const FaceCompliance compliance(model, frame, grids, info.grid_step, info.matching_depth,
                                  inset_cells_3d * info.flank_cell_size, layers, face_width);
  info.coefficient_time = seconds_since(start);
  if (progress)
    progress("influence coefficients (3D): " + std::to_string(compliance.n_points()) +
             " grid points x " + std::to_string(layers) + " layers, " +
             format_number(info.coefficient_time, 3) + " s");

  start = std::chrono::steady_clock::now();
  const FaceModel face{frame, compliance,
                       LayerBody{settings.material.youngs_modulus, settings.material.poisson_ratio,
                                 info.matching_depth},
                       layers, face_width};
  run.by_torque = solve_positions(
      positions, torques.size(),
      [&](double position, std::map<int, double>& warm)
      { return solve_face_position(face, position, torques, warm, info.newton_steps); });
  info.contact_time = seconds_since(start);
  return run;
}
} // namespace gearstiff::stiffness::influence
