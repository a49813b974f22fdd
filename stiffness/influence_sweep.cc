// The influence-coefficient sweep (docs/ltca.md), 2D and 3D: FE body below a matching depth,
// analytic Hertz layer above it, one small contact problem per position and torque. The
// dimensions differ only in the FE body (2D: the transverse section; 3D: the extruded scene
// with the face cut into its hexahedron layers, docs/ltca.md §3), the flank grid's loads (a
// point; a layer's line) and the cell size: everything else is the 2D model with one layer.
// The geometry along the face and the line of action is stiffness/influence_geometry.h, what the
// model refuses stiffness/influence_checks.h.
#include "stiffness/influence_sweep.h"

#include "errors/format.h"
#include "fem/parallel.h"
#include "stiffness/face_load.h"
#include "stiffness/influence_body.h"
#include "stiffness/influence_checks.h"
#include "stiffness/influence_geometry.h"
#include "stiffness/influence_position.h"
#include "stiffness/ltca_contact.h"

#include <algorithm>
#include <array>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>

namespace gearstiff::stiffness
{
using namespace dealii;
using namespace influence;

namespace
{
// The run's results: every position (solved on rank 0) and the model's report, on every rank.
struct InfluenceRun
{
  std::vector<std::vector<GearMeshStiffnessResult>> by_torque; // [torque][position]
  InfluenceModelInfo info;
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& by_torque;
    archive& info;
  }
};

// The scene step of the run: rank 0 meshes, every rank reads rank 0's file (each rank's scratch
// folder is its own).
struct SceneStep
{
  double time = 0.;               // s, wall
  double reference_position = 0.; // m, ℓ_s
  std::string file;               // rank 0's
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& time& reference_position& file;
  }
};

// One gear's coefficients, computed on the rank that took the gear.
struct GearCoefficients
{
  unsigned int wheel = 0;
  std::vector<std::vector<double>> coefficients;  // m/N, [load][read]
  FilletStressPoints fillet;                      // the gear's fillets
  std::vector<std::vector<double>> fillet_values; // m/N, [load][fillet row]
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& wheel& coefficients& fillet& fillet_values;
  }
};

// h_f, the FE body's cell size at the flanks, in normal modules. 2D: 0.1 mm for the default
// pair, 3.3x the exact scene's contact size; the body is sized for tooth bending (docs/ltca.md
// §1). 3D: twice that (0.2 mm), so that the extruded body stays near the exact 3D scene's size
// (docs/ltca.md §3, measured there).
constexpr double flank_cell_modules(int dim)
{
  return dim == 2 ? 0.04 : 0.08;
}
// 3D: the flank band is meshed at 1.5·h_f (0.3 mm for the default pair), h and the inset still
// counted in h_f, so the read lies two band cells deep. Measured 2026-12-02 (ltca47g, default
// pair, Q1, one unlocked run each): 4 layers 54.4k → 41.5k DoFs, the worst |Δk| against the exact
// path 0.547 → 0.541 % (positions +0.43 → +0.48, +0.55 → +0.54, +0.21 → +0.16, +0.29 →
// +0.32 %), K_Hβ within 0.02 %; 8 layers 102k → 75.7k DoFs, sweep 11.9 → 6.9 s, k +0.06 …
// +0.19 %.
constexpr double band_cell_factor(int dim)
{
  return dim == 2 ? 1. : 1.5;
}
// -, h_f of a helical pair's body over the spur value (0.04·m_n): the twisted Q1 body at
// 0.08·m_n is 0.5-0.8 % stiff. Measured 2026-12-03 (ltca47j; small pair z 19/29, β 10°, 10
// layers, against the exact path at h_c 0.075 mm, one unlocked run each): k +1.51, +1.69, +0.09,
// +1.05 % → +1.00, +1.10, −0.57, +0.27 %; body 73.5k → 111k DoFs, 7.0 → 18.1 s (medians of 3
// under the build lock), 0.85 → 1.37 GB.
constexpr double helical_flank_cell_factor = 0.5;
// -, the largest kinematic gap of a tip edge beyond the path (in normal modules) that gets an
// unknown: 0.02·m_n (40 µm for m_n 2 mm) is several times a loaded pair's approach; an edge
// further off carries nothing and only lengthens the active set.
constexpr double tip_edge_gap_modules = 0.02;
// -, a helical tip corner's radius in normal modules, for the near field of a tip-edge unknown
// (solve_position): the meshed tip corner is sharp, so its radius is a model choice; its effect is
// weak (ln a): measured 2026-12-03 (ltca47j; small pair, β 10°, 10 layers, position 0.625, one
// run each) 0.025·m_n −0.17 %, 0.1·m_n +0.09 %, 0.5·m_n +0.47 % against the exact path.
constexpr double tip_corner_modules = 0.1;
// h = 3·h_f: a point (or layer's line) load's FE response is wrong within a cell or two of the
// load and right at three cells' distance (docs/ltca.md §2: measured by the accuracy test).
constexpr double matching_depth_cells = 3.;
// The load points lie this many cells inside the surface: the meshed flank is a chord polygon of
// the involute. 3D: its sagitta h_f²/(8ρ) reaches 1 µm for h_f = 0.2 mm at ρ = 5 mm; 4 µm under a
// read 0.6 mm deep changes nothing the read sees. Where the flank bends more (ρ small, near the
// base circle) the load and its read sink further together (flank_sink).
constexpr double inset_cells(int dim)
{
  return dim == 2 ? 1e-3 : 0.02;
}

// m, how far the load and the read of a convex flank's point at ℓ = `at` move inward together
// beyond `inset`, so that the load lies inside the meshed chord polygon (linear cells): twice the
// sagitta c²/(8ρ) of a band cell c at the flank's transverse curvature radius ρ (ρ1 = ℓ, ρ2 =
// T1T2 − ℓ), less the inset. A ring's flank is concave: its chords lie outside the flank. Found
// 2026-12-05 on invariants case 23 of seed 20261201 (z 24, x −0.24, m 3 mm: ρ 2.7 mm at the
// grid's first point, sagitta 0.67 µm against the 2D inset 0.12 µm; exit 3 "a flank grid point
// lies outside the pinion's mesh"). The read keeps its distance under the load (the depth the
// near field is matched at).
double flank_sink(const PairFrame& frame, double at, bool wheel, double band, double inset)
{
  if (wheel && frame.pair.spec.wheel.internal)
    return 0.;
  const double rho = wheel ? frame.t2 - at : at;
  if (!(rho > 0.))
    return 0.;
  return std::max(0., band * band / (4. * rho) - inset);
}

Tensor<1, 2> turned(const Tensor<1, 2>& v, double angle)
{
  const double c = std::cos(angle), s = std::sin(angle);
  Tensor<1, 2> t;
  t[0] = c * v[0] - s * v[1];
  t[1] = s * v[0] + c * v[1];
  return t;
}

// The load and the read of the point of pair j's flank (pinion or `wheel`) that touches at ℓ =
// `at` in station i's plane, along its normal (`direction` 0) or across it (1): in 2D the point
// itself (the transverse section); in 3D a unit force spread over the hat function of node plane
// i along the pair's contact line (the mortar's line load between node planes is linear; two
// Gauss points per layer integrate the hat times the Q1/Q2 shape functions along z exactly), read
// at the matching depth on the plane. `removal(ℓ, wheel)`, `lead(z, wheel)` (m, transverse): the
// profile and lead modifications' removal, by which the flank lies under the nominal one.
void add_station_points(const PairFrame& frame, const Helix& /*helix*/, int j, double at,
                        bool wheel, unsigned int direction, double inset, double depth, double band,
                        const FaceStations& /*stations*/, std::size_t /*i*/, bool /*edge*/,
                        const std::function<double(double, bool)>& removal,
                        const std::function<double(double, bool)>& /*lead*/,
                        std::vector<BodyPoint<2>>& loads, std::vector<BodyPoint<2>>& reads)
{
  FlankPoint p = flank_point(frame, j, at, wheel);
  p.surface += (removal(at, wheel) + flank_sink(frame, at, wheel, band, inset)) * p.inward;
  const Tensor<1, 2> along = direction == 0 ? p.inward : p.across;
  loads.push_back({{p.surface + inset * p.inward}, {1.}, along, p.body});
  reads.push_back({{p.surface + depth * p.inward}, {1.}, along, p.body});
}
// 3D, helical: the Gauss points follow the contact line, ℓ(z) = at + rate·(z − z_i), each the
// transverse model's flank point at ℓ(z) turned by its section's twist; the read lies under the
// plane's point at the depth h along the helicoid's normal (a transverse offset h/cos β_b, to
// first order in the layer), and the direction is that normal: n_z = −φ'·((P − O) × n_t) keeps
// n ⊥ the helix through P, |n_z| = tan β_b before normalising.
void add_station_points(const PairFrame& frame, const Helix& helix, int j, double at, bool wheel,
                        unsigned int direction, double inset, double depth, double band,
                        const FaceStations& stations, std::size_t i, bool edge,
                        const std::function<double(double, bool)>& removal,
                        const std::function<double(double, bool)>& lead,
                        std::vector<BodyPoint<3>>& loads, std::vector<BodyPoint<3>>& reads)
{
  const double dz = stations.layer, z_i = stations.z[i];
  const double turn_rate = helix.turn_rate(frame, wheel);
  const Point<2> centre = wheel ? frame.wheel_centre : Point<2>();
  // A tip edge (`edge`): the flank point at ℓ = `at` (A or E) in every section, the tip's edge
  // along the face, not the inclined contact line.
  const auto roll = [&](double z) { return edge ? at : at + (helix.shift(z) - helix.shift(z_i)); };
  const double sink = flank_sink(frame, at, wheel, band, inset);
  const auto at_z = [&](double offset, double z)
  {
    const double l = roll(z);
    FlankPoint p = flank_point(frame, j, l, wheel);
    p.surface += removal(l, wheel) * p.inward;
    offset += sink;
    Point<2> q = p.surface + (lead(z, wheel) + offset / helix.cos_base) * p.inward;
    if (turn_rate != 0.)
      q = centre + turned(q - centre, turn_rate * (z - helix.middle));
    return Point<3>(q[0], q[1], z);
  };
  const FlankPoint p = flank_point(frame, j, at, wheel);
  Tensor<1, 3> along;
  if (turn_rate == 0.)
    along = Tensor<1, 3>({direction == 0 ? p.inward[0] : p.across[0],
                          direction == 0 ? p.inward[1] : p.across[1], 0.});
  else
  {
    const double angle = turn_rate * (z_i - helix.middle);
    const Tensor<1, 2> normal = turned(p.inward, angle), across = turned(p.across, angle);
    const Tensor<1, 2> arm = turned(p.surface - centre, angle);
    const double n_z = -turn_rate * (arm[0] * normal[1] - arm[1] * normal[0]);
    if (direction == 0)
      along = Tensor<1, 3>({normal[0], normal[1], n_z}) / std::sqrt(1. + n_z * n_z);
    else
      along = Tensor<1, 3>({across[0], across[1], 0.});
  }
  BodyPoint<3> load{{}, {}, along, p.body};
  if (helix.rate == 0.)
  {
    // A spur plane's unit force on its own node plane alone, not over the hat between its
    // neighbours: the exact path's contact force sits on each plane's nodes, and how its layer
    // answers between the planes is the layer kernel's, added in the small contact problem
    // (layer_kernel_departure; docs/ltca.md §3 "End faces").
    loads.push_back({{at_z(inset, z_i)}, {1.}, along, p.body});
    reads.push_back({{at_z(depth, z_i)}, {1.}, along, p.body});
    return;
  }
  double on_flank = 0.;
  for (const double side : {-1., 1.})
  {
    const double middle = z_i + 0.5 * side * dz;
    if (middle < 0. || middle > stations.z.back())
      continue;
    for (const double gauss : {-1., 1.})
    {
      const double z = middle + gauss * 0.5 * dz / std::sqrt(3.);
      // A helical line leaves the flanks at the path's ends (A: the wheel's tip, E: the
      // pinion's): the unit force stays on the part of the hat that lies on the path.
      const double l = roll(z);
      if (l < frame.pair.contact_start - 1e-9 || l > frame.pair.contact_end + 1e-9)
        continue;
      load.points.push_back(at_z(inset, z));
      load.weights.push_back((1. - std::abs(z - z_i) / dz) * 0.5 * dz / stations.width[i]);
      on_flank += load.weights.back();
    }
  }
  if (helix.rate != 0. && !edge && on_flank == 0.)
  {
    // A path end on an end plane, the line leaving the face on the plane's only side: the
    // plane's own point carries the load.
    load.points = {at_z(inset, z_i)};
    load.weights = {1.};
  }
  else if (helix.rate != 0. && !edge)
    for (double& weight : load.weights)
      weight /= on_flank;
  loads.push_back(load);
  reads.push_back({{at_z(depth, z_i)}, {1.}, along, p.body});
}

// The influence coefficients of both gears on their flank grids, interpolated to any ℓ: C (m/N)
// between every pair of items (station s, grid point a of station s's grids, direction p), item
// offset[s] + a·directions + p: a unit force at the surface point (in 3D over the node plane's
// hat along the contact line), the displacement read at the matching depth, along the flank
// normal (direction 0) and, for a modified flank, also across it (1; symmetric up to the depth
// offset). Each station has its own grids: a helical pair's plane z sees the ℓ of the sweep
// shifted by rate·(z − z₀) (spur: the same grids on every plane).
template <int dim>
class FlankCompliance
{
public:
  // `removal(ℓ, wheel)` (m): the profile modification's depth at the flank point, by which the
  // meshed flank lies under the nominal involute; `lead(z, wheel)` (m) the lead modification's.
  // `tilted`: the flanks are modified, so force lines turn (PairLine), or friction loads them
  // across the normal (pair_friction): the coefficients across the normal are computed too.
  // The items' load and read points of both gears (loads(), reads()); their coefficients follow
  // with set_coefficients, computed where the caller chooses (a gear a rank, docs/ltca.md "Cost").
  FlankCompliance(const PairFrame& frame, const Helix& helix,
                  std::vector<std::vector<FlankGrid>> grids, double step, double depth,
                  double inset, double band, const FaceStations& stations,
                  const std::function<double(double, bool)>& removal,
                  const std::function<double(double, bool)>& lead, bool tilted,
                  std::vector<std::pair<int, bool>> edges)
      : grids(std::move(grids)), step(step), directions(tilted ? 2 : 1), edges(std::move(edges)),
        path_end(frame.pair.contact_end)
  {
    for (const bool wheel : {false, true})
    {
      std::vector<BodyPoint<dim>>&loads = load_points[wheel], &reads = read_points[wheel];
      offset.clear();
      edge_offset.clear();
      for (std::size_t s = 0; s < stations.size(); ++s)
      {
        offset.push_back(loads.size());
        for (const FlankGrid& grid : this->grids[s])
          for (unsigned int g = 0; g < grid.count; ++g)
            for (unsigned int d = 0; d < directions; ++d)
              add_station_points(frame, helix, grid.pair, grid.first + g * step, wheel, d, inset,
                                 depth, band, stations, s, false, removal, lead, loads, reads);
        // A helical pair's tip edges on this plane (docs/ltca.md §3 "Tip edges"): the wheel's at
        // ℓ = A, the pinion's at E, of the flanks whose lines cross that end, loaded along the
        // edge.
        edge_offset.push_back(loads.size());
        for (const auto& [j, at_end] : this->edges)
          for (unsigned int d = 0; d < directions; ++d)
            add_station_points(frame, helix, j,
                               at_end ? frame.pair.contact_end : frame.pair.contact_start, wheel, d,
                               inset, depth, band, stations, s, true, removal, lead, loads, reads);
      }
    }
  }

  // The items' unit loads and reads of the pinion (`wheel` false) or the wheel.
  const std::vector<BodyPoint<dim>>& loads(bool wheel) const { return load_points[wheel]; }
  const std::vector<BodyPoint<dim>>& reads(bool wheel) const { return read_points[wheel]; }
  // m/N, [load][read] of one gear: body_compliance of its loads() and reads().
  void set_coefficients(bool wheel, std::vector<std::vector<double>> coefficients)
  {
    (wheel ? wheel_c : pinion_c) = std::move(coefficients);
  }
  // One gear's fillets and their displacements under each of its loads() (m/N, [load][row]),
  // and the stress law they are read with.
  void set_fillet(bool wheel, FilletStressPoints points, std::vector<std::vector<double>> values,
                  const fem::Material& material, fem::PlanarModel model)
  {
    fillet[wheel] = std::move(points);
    fillet_values[wheel] = std::move(values);
    stress_material = material;
    planar_model = model;
  }

  // Pa, the largest first principal stress on the fillets of the pinion (`wheel` false) or the
  // wheel under the forces (N, one per unknown) of a solved position: the FE body's
  // displacements there are the forces' sum of the unit loads' (each unknown's items and weights
  // as its coefficients take them, operator()). NaN where the fillets were not read (3D).
  // `friction` (N, one per unknown; empty: none): the friction forces across the normals.
  template <class Unknowns>
  double root_stress(bool wheel, const Unknowns& unknowns, const std::vector<double>& forces,
                     const std::vector<double>& friction) const
  {
    if (fillet[wheel].point_start.size() < 2) // no fillet read (3D): NaN, never a number
      return std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::vector<double>>& values = fillet_values[wheel];
    std::vector<double> displacement(fillet[wheel].dofs.size(), 0.);
    for (std::size_t k = 0; k < unknowns.size(); ++k)
    {
      if (!(forces[k] > 0.))
        continue;
      const auto& unknown = unknowns[k];
      const Item a = locate(unknown.station, unknown.pair, unknown.flank[wheel], unknown.edge);
      const double along[2] = {forces[k], forces[k] * unknown.line.tilt +
                                              (friction.empty() ? 0. : friction[k])};
      for (unsigned int p = 0; p < directions; ++p)
      {
        const double first = along[p] * (1. - a.u), next = along[p] * a.u;
        for (std::size_t r = 0; r < displacement.size(); ++r)
          displacement[r] += first * values[a.first + p][r] + next * values[a.next + p][r];
      }
    }
    return largest_fillet_stress(fillet[wheel], displacement, stress_material, planar_model);
  }

  // C (m/N), both gears, station s of pair j at ℓ_j loaded, station t of pair k at ℓ_k read,
  // their force lines turned by τ_j, τ_k (rad; 0 without modifications), the load's friction
  // force f_j times its normal force across it (pair_friction; the read is the gap's, along the
  // force line alone, so C is not symmetric with friction). The same flank at the
  // same ℓ (2D, a spur pair's planes, a helical pair's own plane) along its diagonal samples (its
  // near field varies over the depth h, not over the grid step); otherwise bilinearly (smooth:
  // a helical pair's other planes lie Δz or more away).
  // `edge_j`, `edge_k`: the unknown is a tip edge (ℓ = A or E), its own item, not the grid's.
  // `at_j`, `at_k`: ℓ of the pinion's and of the wheel's flank point (where modified flanks
  // touch off the line of action each gear's point lies off ℓ: touching_flanks).
  double operator()(int j, const std::array<double, 2>& at_j, double tilt_j, std::size_t s,
                    bool edge_j, int k, const std::array<double, 2>& at_k, double tilt_k,
                    std::size_t t, bool edge_k) const
  {
    const std::array<double, 2> along_j{{1., tilt_j}}, along_k{{1., tilt_k}};
    return coupling(j, at_j, along_j, s, edge_j, k, at_k, along_k, t, edge_k);
  }
  // The same for a load of components `along_j` (along the normal, across it: a friction force
  // loads across it) and a read of components `along_k` (the slip reads across it; docs/ltca.md
  // §4 "Friction").
  double coupling(int j, const std::array<double, 2>& at_j, const std::array<double, 2>& along_j,
                  std::size_t s, bool edge_j, int k, const std::array<double, 2>& at_k,
                  const std::array<double, 2>& along_k, std::size_t t, bool edge_k) const
  {
    double c = 0.;
    for (const bool wheel : {false, true})
    {
      const auto* body = wheel ? &wheel_c : &pinion_c;
      const Item a = locate(s, j, at_j[wheel], edge_j), b = locate(t, k, at_k[wheel], edge_k);
      for (unsigned int p = 0; p < directions; ++p)
        for (unsigned int q = 0; q < directions; ++q)
        {
          const auto m = [&](std::size_t x, std::size_t y) { return (*body)[x + p][y + q]; };
          const double weight = along_j[p] * along_k[q];
          if (j == k && at_j[wheel] == at_k[wheel] && !edge_j && !edge_k)
            c += weight * ((1. - a.u) * m(a.first, b.first) + a.u * m(a.next, b.next));
          else
            c += weight *
                 ((1. - a.u) * ((1. - b.u) * m(a.first, b.first) + b.u * m(a.first, b.next)) +
                  a.u * ((1. - b.u) * m(a.next, b.first) + b.u * m(a.next, b.next)));
        }
    }
    return c;
  }
  // m, the ℓ pair j's grid on station s covers (a point off it has no coefficients).
  std::pair<double, double> grid_span(std::size_t s, int j) const
  {
    for (const FlankGrid& grid : grids[s])
      if (grid.pair == j)
        return {grid.first, grid.first + (grid.count - 1) * step};
    return {0., 0.};
  }
  // Whether pair j's tip edge at E (`at_end`) or A has its own items.
  bool has_edge(int j, bool at_end) const
  {
    return std::find(edges.begin(), edges.end(), std::pair(j, at_end)) != edges.end();
  }
  // The load points of one gear (grid points × stations).
  std::size_t n_points() const { return load_points[0].size() / directions; }

private:
  // An unknown's items: the first of the two grid points about its ℓ, the next one and the
  // fraction u between them (a tip edge: its own item, u = 0).
  struct Item
  {
    std::size_t first = 0, next = 0;
    double u = 0.;
  };
  Item locate(std::size_t s, int j, double at, bool edge) const
  {
    if (edge)
    {
      const auto found = std::find(edges.begin(), edges.end(), std::pair(j, at == path_end));
      const std::size_t index =
          edge_offset[s] + static_cast<std::size_t>(found - edges.begin()) * directions;
      return {index, index, 0.};
    }
    const auto [first, u] = locate_on_grid(grids[s], step, j, at);
    return {offset[s] + first * directions, offset[s] + (first + 1) * directions, u};
  }

  std::vector<std::vector<FlankGrid>> grids; // by station
  double step;
  unsigned int directions;                 // 1: along the normals only; 2: across them too
  std::vector<std::pair<int, bool>> edges; // (pair, at E) of the tip edges with items
  double path_end = 0.;                    // m, E
  std::vector<std::size_t> offset;         // the first item of each station
  std::vector<std::size_t> edge_offset;    // the first tip-edge item of each station
  std::vector<BodyPoint<dim>> load_points[2], read_points[2]; // [wheel]
  std::vector<std::vector<double>> pinion_c, wheel_c;
  FilletStressPoints fillet[2];                      // [wheel]
  std::vector<std::vector<double>> fillet_values[2]; // [wheel]
  fem::Material stress_material;
  fem::PlanarModel planar_model = fem::PlanarModel::plane_strain;
};

// One position under every torque (ascending), each warm-started from the previous solve
// (`warm`: force per unknown j·stations + s, carried from position to position). One unknown per
// (pair, station) where the pair touches the station's plane: in 3D each node plane carries the
// plane-strain Hertz layer of its own line load (a line load's layer is plane strain where it
// varies over more than the depth h along the face; the FE body couples the planes below the
// depth), its gap the pair's profile separation at its ℓ plus both flanks' lead removal at the
// plane. A helical pair (docs/ltca.md §3 "Helical"): the unknowns are normal forces N; the
// pinion's roll e (transverse) approaches the flanks by e·cos β_b along the normal and the torque
// is Σ N·cos β_b·r_b1, so the lever ratio of every unknown is cos β_b (the transverse gap s
// alike); the near field is the Hertz layer of the normal line load N/(t/cos β_b) over the
// contact line's length in the plane's tributary width t, with the normal-section relative
// radius R_t/cos β_b.
template <int dim>
std::vector<GearMeshStiffnessResult>
solve_position(const PositionModel& model, const FlankCompliance<dim>& compliance, double position,
               const std::vector<double>& torques, std::map<int, double>& warm,
               unsigned int& newton_steps)
{
  const kinematics::GearPairGeometry& pair = model.frame.pair;
  const FaceStations& stations = model.stations;
  const std::size_t layers = stations.size();
  const Helix& helix = model.helix;
  std::vector<std::vector<int>> by_station;
  std::vector<int> pairs;
  for (std::size_t s = 0; s < layers; ++s)
  {
    by_station.push_back(
        geometry::gear_pairs_in_contact(pair, position + helix.shift(stations.z[s])));
    pairs.insert(pairs.end(), by_station.back().begin(), by_station.back().end());
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  MeshContactProblem problem;
  problem.friction_coefficient = model.friction_coefficient;
  problem.face_width = model.face_width;
  problem.pinion = model.pinion;
  problem.wheel = model.wheel;
  std::vector<Unknown> unknowns;
  std::vector<int> keys;
  // The force lines depend on the load where the flanks are modified (pair_line: the slopes the
  // contact zone sees, the strip sized by it): built under the first torque here, rebuilt under
  // each further one (lines_under) so that a torque list gives at each torque what that torque
  // gives alone. Built once under the list's largest torque until session 43, they made invariants
  // case 1 of seed 20261201 (9.9 µm reliefs on both) 3.7e-5 stiffer at T within T/2, T, 2T.
  double lines_force = torques.front() / model.frame.pinion_base_radius();
  std::vector<double> line_radius; // m, each unknown's relative radius for pair_line
  // m, the rounding radius of a tip edge unknown's own tip (the pinion's at E, the wheel's at A).
  const auto edge_rounding = [&](const Unknown& unknown)
  {
    return unknown.at == pair.contact_end ? pair.spec.pinion.tip_rounding_radius
                                          : pair.spec.wheel.tip_rounding_radius;
  };
  const auto set_force_line = [&](Unknown& unknown, double relative_radius, double force)
  {
    unknown.line = pair_line(model, unknown.at, relative_radius, force);
    // A sharp tip edge's near field is its corner's (Hertz at the corner radius, the wedge's
    // layer), never a strip: a strip at A or E samples the modified flank on both sides of the
    // path's end, as if the tooth went on past its tip. Measured 2026-12-06 (the small helical
    // pair, β 10°, 6 µm long tip reliefs, 20 layers, position 0.625, against the exact path on
    // the same planes; docs/ltca.md §3 "On the same node planes"): the wheel's relieved tip edge
    // carried 38.5 and 17.6 N/mm with the strip against the exact 27.0 and 15.1 (K_Hβ +5.0 %),
    // 22.0 and 12.6 with its corner (K_Hβ −0.3 %). A rounded tip's arc is material beyond the
    // path's end: its strip (flank and arc, rounded_tip_removal) stays.
    if (unknown.edge && edge_rounding(unknown) == 0.)
      unknown.line.strip = {};
    unknown.line.pinion_lever *= helix.cos_base;
    unknown.line.wheel_lever *= helix.cos_base;
  };
  const double corner_radius = tip_corner_modules * pair.spec.pinion.normal_module; // m
  for (const int j : pairs)
    for (std::size_t s = 0; s < layers; ++s)
    {
      Unknown unknown;
      unknown.pair = j;
      unknown.station = s;
      unknown.at = position + helix.shift(stations.z[s]) + j * pair.transverse_base_pitch;
      // A helical plane just beyond the path (its line ℓ(z_s) within one layer's shift past A
      // or E): an unknown at the tip edge, the tip corner in this plane (docs/ltca.md §3 "Line
      // ends"), its gap the corner's kinematic distance to the mate flank.
      double corner_gap = 0.;
      if (std::find(by_station[s].begin(), by_station[s].end(), j) == by_station[s].end())
      {
        if (helix.rate == 0. || dim != 3)
          continue;
        if (unknown.at > pair.contact_end && compliance.has_edge(j, true))
        {
          corner_gap = tip_corner_gap(model.frame, unknown.at - pair.contact_end, false,
                                      pair.spec.pinion.tip_rounding_radius);
          unknown.edge = true;
          unknown.at = pair.contact_end;
        }
        else if (unknown.at < pair.contact_start && compliance.has_edge(j, false))
        {
          corner_gap = tip_corner_gap(model.frame, pair.contact_start - unknown.at, true,
                                      pair.spec.wheel.tip_rounding_radius);
          unknown.edge = true;
          unknown.at = pair.contact_start;
        }
        else
          continue;
        if (corner_gap > tip_edge_gap_modules * pair.spec.pinion.normal_module)
          continue;
      }
      // ρ1 = ℓ, ρ2 = |ℓ − T1T2|; a ring's flank is concave (docs/ltca.md §3). A helical flank's
      // normal section: ρ/cos β_b.
      const double rho1 = unknown.at, rho2 = std::abs(unknown.at - model.frame.t2);
      const double relative_radius =
          1. / (1. / rho1 + (pair.spec.wheel.internal ? -1. : 1.) / rho2);
      set_force_line(unknown, relative_radius, lines_force);
      line_radius.push_back(relative_radius);
      // The gap where the pair touches (the near field, Hertz or strip, is centred there).
      const double lead = dim == 3 ? model.separation.lead(stations.z[s]) : 0.;
      unknown.touching = model.separation(unknown.at) + unknown.line.lowered + corner_gap + lead;
      unknown.flank = unknown.edge ? std::array<double, 2>{{unknown.at, unknown.at}}
                                   : touching_flanks(model.frame, model.separation, unknown.at);
      // Each gear's sharp tip corner from the contact's centre, where its layer is a wedge's
      // (corner_layer_excess). Measured 2026-12-05 on the planet–ring pair (24/69, m 2.5 mm,
      // T_d, 32 positions): at mesh position 0.0156 the ring's corner lies 0.036 mm of its flank
      // from the centre, inside the Hertz zone (a ≈ 0.06 mm), and without it the model was
      // 1.14 % stiff there. A tip edge's unknown has its own wedge (wedge_factor below).
      constexpr double none = std::numeric_limits<double>::quiet_NaN();
      problem.pinion_corner.push_back(
          unknown.edge ? none : model.separation.tip_corner_offset(unknown.flank[0], false));
      problem.wheel_corner.push_back(
          unknown.edge ? none : model.separation.tip_corner_offset(unknown.flank[1], true));
      // Within the pair's grid, which reaches a grid step beyond the ℓ the sweep sees (flank
      // grids reaching further put read points through thin tooth tips: invariants case 15 of
      // seed 20261201, a ring of m 1 mm with profile crowning and slope, exit 3 when they did).
      if (!unknown.edge)
      {
        const auto [from, to] = compliance.grid_span(s, j);
        for (double& flank : unknown.flank)
          flank = std::clamp(flank, from, to);
      }
      problem.separation.push_back(unknown.touching);
      // The near field's length: the contact line's part on the path within the station's strip
      // (a corner: the tip edge along the whole strip); a corner's radius against the mate's
      // flank radius there.
      double radius = relative_radius;
      if (unknown.edge)
      {
        const double mate = unknown.at == pair.contact_end
                                ? std::abs(unknown.at + corner_gap - model.frame.t2)
                                : unknown.at;
        // A rounded tip's arc is the corner (its radius, not the model's choice for a sharp
        // one); a ring's flank is concave.
        const double rounding = edge_rounding(unknown);
        const double corner = rounding > 0. ? rounding : corner_radius;
        const bool concave_mate = unknown.at == pair.contact_end && pair.spec.wheel.internal;
        radius = 1. / (1. / corner + (concave_mate ? -1. : 1.) / mate);
      }
      problem.width.push_back((unknown.edge
                                   ? stations.width[s]
                                   : std::max(on_path_width(stations, helix, pair, s, unknown.at),
                                              1e-3 * stations.layer)) /
                              helix.cos_base);
      // Near the end faces the layer is a quarter-space's, softer than plane strain, by as much
      // as the layers resolve (end_face_layer_excess; docs/ltca.md §3 "End faces"): each plane
      // takes both ends' excess.
      problem.end_excess.push_back(
          dim == 3 ? end_face_layer_excess(stations.layer, model.pinion.matching_depth, s) +
                         end_face_layer_excess(stations.layer, model.pinion.matching_depth,
                                               layers - 1 - s)
                   : 0.);
      // A tip edge's layer is a wedge's, softer than the flank's half-space (docs/ltca.md §3
      // "Tip edges"): the pinion's corner at E, the wheel's at A, each at its tip's transverse
      // pressure angle (roll length over base radius).
      const bool pinion_edge = unknown.edge && unknown.at == pair.contact_end;
      const bool wheel_edge = unknown.edge && unknown.at == pair.contact_start;
      problem.pinion_wedge.push_back(pinion_edge
                                         ? tip_edge_wedge_factor(std::atan(
                                               pair.contact_end / model.frame.pinion_base_radius()))
                                         : 1.);
      problem.wheel_wedge.push_back(wheel_edge ? tip_edge_wedge_factor(std::atan(
                                                     std::abs(model.frame.t2 - pair.contact_start) /
                                                     model.frame.wheel_base_radius()))
                                               : 1.);
      problem.relative_radius.push_back(radius / helix.cos_base);
      problem.lever_ratio.push_back(unknown.line.pinion_lever);
      // Friction (docs/ltca.md §4 "Friction"): the pinion's rigid roll slips its flank by ρ₁/r_b1
      // of it, a friction force turns it about its centre at the arm ρ₁ (a tip edge's at ℓ).
      unknown.friction = pair_friction(model.frame, unknown.at);
      problem.slip_per_approach.push_back(unknown.friction.slip_per_approach);
      problem.friction_arm.push_back(unknown.friction.pinion_arm);
      problem.strip.push_back(unknown.line.strip);
      keys.push_back(j * static_cast<int>(layers) + static_cast<int>(s));
      unknowns.push_back(unknown);
    }
  // The coefficients read along each force line's tilt.
  // N/m, each unknown's line load the layer kernel is scaled by (empty: the nominal T1/(r_b1·b)).
  std::vector<double> kernel_load;
  // m/N, the FE bodies' coefficients alone: the kernel is added to a copy each time the line
  // loads change, without interpolating the coefficients again.
  std::vector<std::vector<double>> body_compliance;
  const auto add_kernel = [&]
  {
    problem.compliance = body_compliance;
    if (dim != 3 || helix.rate != 0.)
      return;
    // Spur planes' layer coupling along the face (own-plane loads, add_station_points): the
    // kernel's departure from plane strain between the planes of one contact line, in units of
    // the loaded plane's own plane-strain layer per N/m at its line load (kernel_load), over its
    // width. Not on helical pairs: their neighbouring planes touch tan β_b·Δz apart along the
    // profile, several contact widths, where a straight line's kernel does not hold (built-in
    // helical pair, 13 layers: K_Hβ −11 % with it; docs/ltca.md §3 "End faces").
    const double w = lines_force / pair.common_face_width; // N/m
    for (std::size_t y = 0; y < unknowns.size(); ++y)
    {
      const double wy = kernel_load.empty() || !(kernel_load[y] > 0.) ? w : kernel_load[y];
      const double unit = hertz_line_contact(wy * pair.common_face_width, pair.common_face_width,
                                             problem.relative_radius[y], model.pinion, model.wheel)
                              .approach /
                          wy; // m per N/m
      for (std::size_t x = 0; x < unknowns.size(); ++x)
        if (unknowns[x].pair == unknowns[y].pair)
          problem.compliance[x][y] +=
              layer_kernel_departure(stations.layer, model.pinion.matching_depth, layers,
                                     unknowns[x].station, unknowns[y].station) *
              unit / problem.width[y];
    }
  };
  const auto couple = [&]
  {
    body_compliance.clear();
    for (const Unknown& a : unknowns)
    {
      body_compliance.emplace_back();
      for (const Unknown& b : unknowns)
        body_compliance.back().push_back(compliance(a.pair, a.flank, a.line.tilt, a.station, a.edge,
                                                    b.pair, b.flank, b.line.tilt, b.station,
                                                    b.edge));
    }
    if (model.friction_coefficient > 0.)
    {
      // Row a read at unknown a, column b loaded at unknown b (docs/ltca.md §4 "Friction"): the
      // gap under a friction force, the slip under a normal force and under a friction force.
      const std::array<double, 2> across{{0., 1.}};
      problem.gap_under_friction.clear();
      problem.slip_under_force.clear();
      problem.slip_under_friction.clear();
      for (const Unknown& a : unknowns)
      {
        problem.gap_under_friction.emplace_back();
        problem.slip_under_force.emplace_back();
        problem.slip_under_friction.emplace_back();
        const std::array<double, 2> normal_a{{1., a.line.tilt}};
        for (const Unknown& b : unknowns)
        {
          const std::array<double, 2> normal_b{{1., b.line.tilt}};
          problem.gap_under_friction.back().push_back(
              compliance.coupling(b.pair, b.flank, across, b.station, b.edge, a.pair, a.flank,
                                  normal_a, a.station, a.edge));
          problem.slip_under_force.back().push_back(
              compliance.coupling(b.pair, b.flank, normal_b, b.station, b.edge, a.pair, a.flank,
                                  across, a.station, a.edge));
          problem.slip_under_friction.back().push_back(
              compliance.coupling(b.pair, b.flank, across, b.station, b.edge, a.pair, a.flank,
                                  across, a.station, a.edge));
        }
      }
    }
    add_kernel();
  };
  couple();
  const auto lines_under = [&](double force) -> MeshContactProblem&
  {
    if (force == lines_force || !model.separation.modified())
      return problem;
    lines_force = force;
    for (std::size_t k = 0; k < unknowns.size(); ++k)
    {
      set_force_line(unknowns[k], line_radius[k], force);
      problem.lever_ratio[k] = unknowns[k].line.pinion_lever;
      problem.strip[k] = unknowns[k].line.strip;
    }
    couple();
    return problem;
  };
  // The kernel's unit is the loaded plane's plane-strain layer per N/m, which grows as ln(h/a) as
  // its load falls (a ∝ √w): at the nominal load for every plane a partly relieved plane at an end
  // relief's start was 4.6 % overloaded and its neighbour, the face's peak, 2.7 % underloaded, and
  // a double contact's planes (half the nominal load each) took a unit 10 % too small. So the
  // problem is solved with the nominal unit, recoupled at the line loads found, twice (a third
  // pass moved K_Hβ by < 0.03 %; docs/ltca.md §3 "End faces"), before the solve that is kept.
  const auto under = [&](double force) -> MeshContactProblem&
  {
    kernel_load.clear();
    MeshContactProblem& p = lines_under(force);
    if (dim != 3 || helix.rate != 0.)
      return p;
    add_kernel(); // lines_under keeps the last torque's coupling when the lines do not change
    p.total_force = force;
    for (int pass = 0; pass < 2; ++pass)
    {
      const MeshContactSolution found =
          solve_mesh_contact(p, std::vector<double>(unknowns.size(), 0.));
      kernel_load.assign(unknowns.size(), 0.);
      for (std::size_t k = 0; k < unknowns.size(); ++k)
        kernel_load[k] = found.force[k] / p.width[k];
      add_kernel();
    }
    return p;
  };
  return solve_torques(
      under, model.frame, keys, torques, warm, newton_steps,
      [&](const MeshContactSolution& solution, double torque)
      {
        GearMeshStiffnessResult r =
            position_result<dim>(model, position, pairs, unknowns, solution, torque);
        r.pinion_root_stress =
            compliance.root_stress(false, unknowns, solution.force, solution.friction);
        r.wheel_root_stress =
            compliance.root_stress(true, unknowns, solution.force, solution.friction);
        return r;
      });
}

// -, the μ the model applies (docs/ltca.md §4 "Friction"): the settings' in 2D, none in 3D, where
// the exact path's frictional contact gives no reference to verify it against (the built-in pair,
// Q1, 4 layers, 4 positions: exit 3 at μ 0.03 and 0.1, its Tresca fixed point not converging;
// the report and the input notes say so).
double applied_friction(const GearMeshStiffnessSettings& settings, int dim)
{
  return dim == 2 ? settings.contact.friction_coefficient : 0.;
}

// The flank grids of the sweep and their items (no coefficients yet); sets info.flanks.
template <int dim>
FlankCompliance<dim>
flank_items(const kinematics::GearPairGeometry& pair, const std::vector<double>& positions,
            const FaceStations& stations, const Helix& helix, const PairFrame& frame,
            const PairSeparation& separation, double friction_coefficient, InfluenceModelInfo& info)
{
  // Each station's grids cover the ℓ its plane sees in the sweep (a helical pair's: the
  // positions shifted by rate·(z − z₀)).
  std::vector<std::vector<FlankGrid>> grids;
  std::vector<int> flanks;
  for (std::size_t s = 0; s < stations.size(); ++s)
  {
    std::vector<double> seen;
    for (const double position : positions)
      seen.push_back(position + helix.shift(stations.z[s]));
    grids.push_back(flank_grids(pair, seen, info.grid_step));
    for (const FlankGrid& grid : grids.back())
      flanks.push_back(grid.pair);
  }
  std::sort(flanks.begin(), flanks.end());
  flanks.erase(std::unique(flanks.begin(), flanks.end()), flanks.end());
  if (helix.rate != 0.)
    for (std::size_t s = 0; s < stations.size(); ++s)
    {
      // A helical plane's tip-edge unknowns sit at A or E for pairs whose line lies up to one
      // layer's shift beyond the path: each plane's grids reach the ℓ it sees one layer's shift
      // either way, for the flanks some plane already has (other teeth may not be meshed).
      std::vector<double> seen;
      for (const double position : positions)
        for (const double side : {-1., 0., 1.})
          seen.push_back(position + helix.shift(stations.z[s]) +
                         side * std::abs(helix.rate) * stations.layer);
      grids[s].clear();
      for (const FlankGrid& wider : flank_grids(pair, seen, info.grid_step))
        if (std::binary_search(flanks.begin(), flanks.end(), wider.pair))
          grids[s].push_back(wider);
    }
  info.flanks = 2 * static_cast<unsigned int>(flanks.size());
  // A helical pair's tip edges: pair j's at E where its line lies on the path at one plane and
  // beyond E at another of some position (the pinion's tip edge then touches in the second), at
  // A alike (the wheel's).
  std::vector<std::pair<int, bool>> edges;
  if (helix.rate != 0. && dim == 3)
    for (const int j : flanks)
      for (const bool at_end : {false, true})
        for (const double position : positions)
        {
          bool on = false, beyond = false;
          for (std::size_t s = 0; s < stations.size(); ++s)
          {
            const double at =
                position + helix.shift(stations.z[s]) + j * pair.transverse_base_pitch;
            on |= at >= pair.contact_start && at <= pair.contact_end;
            beyond |= at_end ? at > pair.contact_end : at < pair.contact_start;
          }
          if (on && beyond)
          {
            edges.emplace_back(j, at_end);
            break;
          }
        }
  return FlankCompliance<dim>(
      frame, helix, grids, info.grid_step, info.matching_depth,
      inset_cells(dim) * info.flank_cell_size, band_cell_factor(dim) * info.flank_cell_size,
      stations, [&separation](double at, bool wheel) { return separation.removal(at, wheel); },
      [&separation](double z, bool wheel) { return separation.lead_removal(z, wheel); },
      separation.modified() || friction_coefficient > 0., edges);
}

// The whole run, collective over `mpi_communicator` (docs/ltca.md "Cost"): rank 0 meshes the
// FE body's scene; each gear's coefficients are one item of fem::distribute_items, computed on
// the rank that takes it from that gear alone, cut out of the scene and factored (two ranks: a
// gear each, in parallel; one rank: one after the other, one factor in memory at a time — the
// same factors, so the coefficients do not depend on the ranks); rank 0 solves every position.
// Every rank returns the run or throws the same failure.
template <int dim>
InfluenceRun run_influence(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& given,
                           const kinematics::GearPairGeometry& pair,
                           const std::vector<double>& positions, const std::vector<double>& torques,
                           const std::string& file,
                           const std::function<void(const std::string&)>& progress)
{
  GearMeshStiffnessSettings settings = given;
  settings.elasticity.thickness = pair.common_face_width; // as GearMeshStiffness: b (2D)
  const unsigned int layers = dim == 3 ? settings.scene.mesh.layers : 1;
  const FaceStations stations = face_stations(dim, layers, pair.common_face_width);
  const std::string model_name =
      dim == 3 ? "influence coefficients (3D)" : "influence coefficients";
  InfluenceRun run;
  InfluenceModelInfo& info = run.info;
  info.grid_points = settings.influence_grid_points;
  info.flank_cell_size = flank_cell_modules(dim) * pair.spec.pinion.normal_module *
                         (pair.spec.pinion.helix_angle != 0. ? helical_flank_cell_factor : 1.);
  info.matching_depth = matching_depth_cells * info.flank_cell_size;
  info.grid_step = pair.path_of_contact / (info.grid_points - 1);
  PairFrame frame(pair);
  const Helix helix(pair);
  // The designed separation in the transverse plane: a helical pair's normal amounts over
  // cos β_b (geometry::transverse_section_spec, as the exact path's unloaded TE).
  GearMeshStiffnessSettings section = settings;
  section.scene = geometry::transverse_section_spec(settings.scene);
  const PairSeparation separation(section, frame);
  check_grid_step(info.grid_step, info.matching_depth, separation);
  if (dim == 3)
    check_end_plane_spacing(settings, stations, info.matching_depth);

  // The scene: rank 0 meshes it into `file`, every rank reads it.
  const SceneStep meshed = fem::run_on_root(
      mpi_communicator,
      [&]()
      {
        const auto start = std::chrono::steady_clock::now();
        const geometry::GearPairScene scene = geometry::write_gear_pair_scene(
            body_scene(settings, pair, positions, info.flank_cell_size,
                       band_cell_factor(dim) * info.flank_cell_size, info.matching_depth, dim),
            file);
        return SceneStep{seconds_since(start), scene.reference_position, file};
      });
  info.scene_time = meshed.time;
  frame.scene_position = meshed.reference_position;

  // The flanks' grids and items, on every rank (each loads its own gears'), a failure agreed on
  // before the ranks part.
  std::optional<FlankCompliance<dim>> compliance;
  fem::first_failure(mpi_communicator,
                     fem::catch_failure(
                         [&]()
                         {
                           compliance.emplace(
                               flank_items<dim>(pair, positions, stations, helix, frame, separation,
                                                applied_friction(settings, dim), info));
                         }))
      .rethrow();

  // The coefficients, a gear an item: this rank reads the body once and factors the part of K
  // of the gear it takes.
  std::vector<GearCoefficients> mine;
  std::optional<BodyModel<dim>> model;
  unsigned int n_dofs = 0;
  double read_time = 0., factor_time = 0., coefficient_time = 0.; // s, wall, this rank
  fem::distribute_items(
      mpi_communicator, 2,
      [&](unsigned int wheel)
      {
        auto start = std::chrono::steady_clock::now();
        if (!model)
        {
          model = read_body_model<dim>(meshed.file);
          read_time = seconds_since(start);
        }
        start = std::chrono::steady_clock::now();
        factor_body_model(settings, *model, wheel != 0);
        const unsigned int gear_dofs = model->system->get_dof_handler().n_dofs();
        n_dofs += gear_dofs;
        const double factored = seconds_since(start);
        factor_time += factored;
        const std::string gear = wheel ? "the wheel's" : "the pinion's";
        if (progress)
          progress(model_name + ": FE body, " + gear + " " + std::to_string(gear_dofs) +
                   " DoFs, h_f " + format_number(info.flank_cell_size * 1e3, 3) + " mm, " +
                   (dim == 3 ? std::to_string(layers) + " layers, " : std::string()) +
                   "scene read in " + format_number(read_time, 3) +
                   " s, assembled and factored in " + format_number(factored, 3) + " s");
        start = std::chrono::steady_clock::now();
        // The longest silent step of a 3D sweep (tens of seconds a gear): how far it is, every
        // 10 s, with the time left at the rate so far.
        const std::size_t n_loads = compliance->loads(wheel).size();
        double reported = 0.; // s since start at the last line
        const auto solved = [&](std::size_t done)
        {
          const double elapsed = seconds_since(start);
          if (!progress || done >= n_loads || elapsed < reported + 10.)
            return;
          reported = elapsed;
          progress(model_name + ": " + gear + " coefficients, " +
                   std::to_string(static_cast<int>(100. * double(done) / double(n_loads))) +
                   " % of " + std::to_string(compliance->n_points()) + " load points in " +
                   format_number(elapsed, 3) + " s, ~" +
                   format_number(elapsed * double(n_loads - done) / double(done), 2) + " s left");
        };
        // The fillets' displacements under each load, for the root stress: in 2D (within 5.8 %
        // of the exact path on the same default sizes, the two meshes' fillet error; docs/ltca.md
        // "Root stress"); not in 3D, where the model and the exact path's Q1 fillets differ by
        // up to 13 % (not yet explained).
        GearCoefficients responses{
            wheel, {}, dim == 2 ? body_fillet_points(*model, pair) : FilletStressPoints{}, {}};
        responses.coefficients =
            body_compliance(*model, compliance->loads(wheel), compliance->reads(wheel), solved,
                            dim == 2 ? &responses.fillet : nullptr, &responses.fillet_values);
        mine.push_back(std::move(responses));
        const double computed = seconds_since(start);
        coefficient_time += computed;
        if (progress && dim == 3)
          progress(model_name + ": " + std::to_string(compliance->n_points()) + " load points, " +
                   gear + " coefficients in " + format_number(computed, 3) + " s");
      });
  model.reset();
  info.n_dofs = Utilities::MPI::sum(n_dofs, mpi_communicator); // both gears'
  // Reported as the slowest rank's (its walls are the sweep's).
  info.factorization_time = Utilities::MPI::max(read_time + factor_time, mpi_communicator);
  info.coefficient_time = Utilities::MPI::max(coefficient_time, mpi_communicator);
  // Both gears' to rank 0, which solves the positions.
  for (std::vector<GearCoefficients>& of_rank : Utilities::MPI::gather(mpi_communicator, mine, 0))
    for (GearCoefficients& gear : of_rank)
    {
      compliance->set_coefficients(gear.wheel != 0, std::move(gear.coefficients));
      compliance->set_fillet(gear.wheel != 0, std::move(gear.fillet), std::move(gear.fillet_values),
                             settings.material, settings.elasticity.model);
    }
  mine.clear();

  // Every position on rank 0 (milliseconds each, docs/ltca.md "Cost"), broadcast.
  return fem::run_on_root(
      mpi_communicator,
      [&]()
      {
        const auto start = std::chrono::steady_clock::now();
        LayerBody pinion_body{settings.material.youngs_modulus, settings.material.poisson_ratio,
                              info.matching_depth};
        LayerBody wheel_body = pinion_body;
        pinion_body.corner_pressure_angle = separation.tip_pressure_angle(false);
        wheel_body.corner_pressure_angle = separation.tip_pressure_angle(true);
        const PositionModel position_model{frame,
                                           separation,
                                           pinion_body,
                                           wheel_body,
                                           pair.common_face_width,
                                           stations,
                                           helix,
                                           applied_friction(settings, dim)};
        run.by_torque =
            solve_positions(positions, torques.size(),
                            [&](double position, std::map<int, double>& warm)
                            {
                              return solve_position<dim>(position_model, *compliance, position,
                                                         torques, warm, info.newton_steps);
                            });
        info.contact_time = seconds_since(start);
        const geometry::LeadModification &pinion_lead = settings.scene.pinion_modifications.lead,
                                         &wheel_lead = settings.scene.wheel_modifications.lead;
        if (dim == 3 && (pinion_lead.crowning != 0. || wheel_lead.crowning != 0.))
          check_crowned_contact_planes(run.by_torque, stations, layers, "crowned contact");
        else if (dim == 3 && (pinion_lead.slope != 0. || wheel_lead.slope != 0.))
          check_crowned_contact_planes(run.by_torque, stations, layers,
                                       "contact under the lead slope");
        return run;
      });
}
} // namespace

template <int dim>
StiffnessSweepResult
influence_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                const StiffnessSweepSpec& spec, const std::string& scene_file_stem,
                const std::function<void(const std::string&)>& progress)
{
  const auto start = std::chrono::steady_clock::now();
  check_influence_settings(settings);
  check_stiffness_settings(settings);
  if (!settings.torques.empty())
    check_torque_list(settings.torques);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  const std::vector<double> positions = sweep_positions(pair, spec);
  const std::vector<double> torques =
      settings.torques.empty() ? std::vector<double>{settings.pinion_torque} : settings.torques;
  const std::string file = scene_file_stem + "_influence.msh";
  // run_influence throws the same failure on every rank; the scene file goes either way.
  InfluenceRun run;
  const fem::Failure failure = fem::catch_failure(
      [&]()
      {
        run = run_influence<dim>(mpi_communicator, settings, pair, positions, torques, file,
                                 progress);
      });
  if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    std::filesystem::remove(file);
  failure.rethrow("");
  StiffnessSweepResult result;
  result.positions = run.by_torque.front();
  if (!settings.torques.empty())
  {
    result.torques = settings.torques;
    result.by_torque = run.by_torque;
  }
  result.n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  result.rank_of_position.assign(positions.size(), 0);
  result.mesh = SweepMesh::once; // one FE body for every position
  result.contact_model = ContactModel::influence_coefficients;
  result.influence = run.info;
  result.once_time = run.info.scene_time + run.info.factorization_time + run.info.coefficient_time;
  result.per_position_time = run.info.contact_time;
  result.wall_time = seconds_since(start);
  return result;
}

template StiffnessSweepResult influence_sweep<2>(MPI_Comm, const GearMeshStiffnessSettings&,
                                                 const StiffnessSweepSpec&, const std::string&,
                                                 const std::function<void(const std::string&)>&);
template StiffnessSweepResult influence_sweep<3>(MPI_Comm, const GearMeshStiffnessSettings&,
                                                 const StiffnessSweepSpec&, const std::string&,
                                                 const std::function<void(const std::string&)>&);
} // namespace gearstiff::stiffness
