// Internal to geometry/: the gmsh entities of a planar model and the steps of
// mesh_planar_model (geometry/mesh_planar.h) that live in files of their own —
// mesh_generation.cc (the gmsh model of the transverse section, generation, writing),
// face_width.cc (the face-width stage: transverse model -> 3D), mesh_crack.cc (2D cracks whose
// faces meet), mesh_quality.cc (cell checks). Included by those files only.
#pragma once

#include "geometry/mesh_planar.h"

#include <Eigen/Core>
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gearstiff::geometry::detail
{
using Clock = std::chrono::steady_clock;

inline double seconds_since(const Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The gmsh tags of one loop: per piece (in the order of BoundaryLoop::pieces, not of the
// traversal) its curves and end points in the piece's own direction.
struct LoopTags
{
  int loop = 0;
  std::vector<std::vector<int>> piece_curves; // signed: negative where gmsh's curve runs against
  std::vector<std::pair<int, int>> piece_ends;
};

// The gmsh entities of the model and their ids.
struct GmshEntities
{
  std::map<int, std::vector<int>> curves_by_id;
  std::vector<std::pair<int, int>> curve_ids;             // (curve tag, boundary id), every curve
  std::vector<std::pair<int, int>> surfaces;              // (surface tag, material id)
  std::vector<std::pair<int, int>> volumes;               // (volume tag, material id), 3D
  std::map<int, std::vector<int>> lateral_surfaces_by_id; // boundary id -> surfaces, 3D
  std::vector<int> side_faces;                            // z = 0 and z = face width, 3D
  std::vector<int> lateral_surfaces;                      // 3D
  // Per body: its surface's index in `surfaces` and its fills' (PlanarFill) surface tags.
  std::vector<std::pair<std::size_t, std::vector<int>>> body_fills;
  // 3D: the fills' volumes and the test of the cells they leave out.
  std::vector<std::pair<int, std::function<bool(const Eigen::Vector3d&)>>> fill_volumes;
  // 2D: the cracks whose faces meet (PlanarFill::crack_id)
  struct Crack
  {
    int id = 0;              // boundary id of the body's face (the fill's: id + 1)
    int fill = 0;            // surface tag of the fill
    std::vector<int> curves; // curve tags from the mouth to the tip
    int tip = 0;             // point tag
  };
  std::vector<Crack> cracks;
};

// mesh_quality.cc
std::unordered_map<std::size_t, Eigen::Vector3d> node_coordinates();
// Every cell must be a quadrilateral (hexahedron) with positive scaled Jacobian. Fills the cell
// counts and quality of `statistics`; SolverFailure otherwise.
void check_cells(const MeshOptions& options, const SizeGrading& grading,
                 const std::vector<std::pair<int, int>>& surfaces,
                 const std::vector<std::pair<int, int>>& volumes,
                 const std::map<int, BodyTwist>& twist, MeshStatistics& statistics);

// face_width.cc: the face-width stage (before meshing: the extrusion; after: the node moves of
// the path and the lead modifications, then the cells partial-width faults remove).
void extrude_surfaces(const PlanarModel& model, const MeshOptions& options, GmshEntities& entities);
void label_lateral_surfaces(GmshEntities& entities);
bool moves_nodes(const PlanarModel& model);
void move_nodes(const PlanarModel& model, const GmshEntities& entities);
std::map<int, unsigned long> remove_fill_cells(const GmshEntities& entities);

// mesh_crack.cc
GmshEntities::Crack crack_entities(const PlanarFill& fill, const BoundaryLoop& outer,
                                   const LoopTags& tags, int surface);
void split_crack(const PlanarModel& model, const GmshEntities::Crack& crack);
} // namespace gearstiff::geometry::detail
