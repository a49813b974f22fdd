#include "stiffness/crack_tip.h"

#include "errors/errors.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <iterator>
#include <map>
#include <set>
#include <vector>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
// A node of a crack face: where it is, how it moved, and on which side of the crack its cell
// lies (cell centre, for the orientation).
struct FaceNode
{
  Point<2> position;         // m
  Tensor<1, 2> displacement; // m
  Point<2> cell_centre;      // m
};

struct CrackFaces
{
  std::vector<FaceNode> nodes[2];                 // [face]
  std::set<unsigned int> vertices[2];             // global vertex indices of each face
  std::map<unsigned int, Point<2>> vertex_points; // m
};

// The nodes of the boundary faces with the two ids (the Lagrange support points j/p along each
// face), with the solution evaluated there.
CrackFaces collect_faces(const DoFHandler<2>& dof_handler, const Mapping<2>& mapping,
                         const Vector<double>& displacement, types::boundary_id face,
                         types::boundary_id other_face)
{
  const unsigned int degree = dof_handler.get_fe().degree;
  std::vector<Point<1>> points;
  for (unsigned int j = 0; j <= degree; ++j)
    points.emplace_back(double(j) / degree);
  const Quadrature<1> nodes(points, std::vector<double>(points.size(), 1. / points.size()));
  FEFaceValues<2> values(mapping, dof_handler.get_fe(), nodes,
                         update_values | update_quadrature_points);
  std::vector<Vector<double>> u(points.size(), Vector<double>(2));
  CrackFaces faces;
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
    {
      if (!cell->face(f)->at_boundary())
        continue;
      const types::boundary_id id = cell->face(f)->boundary_id();
      if (id != face && id != other_face)
        continue;
      const unsigned int side = id == face ? 0 : 1;
      values.reinit(cell, f);
      values.get_function_values(displacement, u);
      for (unsigned int q = 0; q < points.size(); ++q)
        faces.nodes[side].push_back(
            {values.quadrature_point(q), Tensor<1, 2>({u[q][0], u[q][1]}), cell->center()});
      for (unsigned int v = 0; v < 2; ++v)
      {
        faces.vertices[side].insert(cell->face(f)->vertex_index(v));
        faces.vertex_points[cell->face(f)->vertex_index(v)] = cell->face(f)->vertex(v);
      }
    }
  return faces;
}

// The straight-line fit K(r) = K0 + c·r over the samples (r, K); returns K0.
double extrapolate_to_tip(const std::vector<std::pair<double, double>>& samples)
{
  Eigen::MatrixXd a(samples.size(), 2);
  Eigen::VectorXd b(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    a(i, 0) = 1.;
    a(i, 1) = samples[i].first;
    b(i) = samples[i].second;
  }
  return a.colPivHouseholderQr().solve(b)(0);
}
} // namespace

CrackTipFactors crack_tip_factors(const DoFHandler<2>& dof_handler, const Mapping<2>& mapping,
                                  const Vector<double>& displacement, types::boundary_id face,
                                  types::boundary_id other_face, double plane_strain_modulus,
                                  double fit_from, double fit_to)
{
  const CrackFaces faces = collect_faces(dof_handler, mapping, displacement, face, other_face);
  std::vector<unsigned int> common;
  std::set_intersection(faces.vertices[0].begin(), faces.vertices[0].end(),
                        faces.vertices[1].begin(), faces.vertices[1].end(),
                        std::back_inserter(common));
  if (common.size() != 1 || faces.nodes[0].empty())
    throw SolverFailure("crack tip factors", "the two crack faces do not meet at one tip (" +
                                                 std::to_string(common.size()) +
                                                 " common vertices)");
  const Point<2> tip = faces.vertex_points.at(common.front());
  // The mouth: the face node farthest from the tip; the crack runs from it to the tip.
  Point<2> mouth = tip;
  for (const FaceNode& node : faces.nodes[0])
    if (node.position.distance(tip) > mouth.distance(tip))
      mouth = node.position;
  Tensor<1, 2> direction = tip - mouth;
  const double length = direction.norm();
  direction /= length;
  const Tensor<1, 2> normal({-direction[1], direction[0]}); // to the upper face's side
  const unsigned int upper = (faces.nodes[0].front().cell_centre - tip) * normal > 0. ? 0 : 1;

  CrackTipFactors result;
  result.tip_x = tip[0];
  result.tip_y = tip[1];
  result.length = length;
  const double scale = plane_strain_modulus / 8.;
  // Coincident nodes of the two faces (parted by 0.1 nm in the mesh, geometry/mesh_crack.cc).
  const double tolerance = 1e-9;
  std::vector<std::pair<double, double>> mode_one, mode_two;
  std::set<std::pair<long, long>> seen;
  for (const FaceNode& a : faces.nodes[upper])
  {
    const double r = a.position.distance(tip);
    if (r <= tolerance || !seen.insert({std::lround(a.position[0] / tolerance),
                                        std::lround(a.position[1] / tolerance)})
                               .second)
      continue;
    const auto twin = std::find_if(faces.nodes[1 - upper].begin(), faces.nodes[1 - upper].end(),
                                   [&](const FaceNode& b)
                                   { return b.position.distance(a.position) <= tolerance; });
    if (twin == faces.nodes[1 - upper].end())
      continue;
    const Tensor<1, 2> jump = a.displacement - twin->displacement;
    if (r < fit_from || r > fit_to)
      continue;
    const double factor = scale * std::sqrt(2. * M_PI / r);
    mode_one.emplace_back(r, factor * (jump * normal));
    mode_two.emplace_back(r, factor * (jump * direction));
  }
  if (mode_one.size() < 2)
    throw SolverFailure("crack tip factors",
                        "fewer than two face nodes within the fit range of the tip");
  result.fit_nodes = mode_one.size();
  result.mode_one = extrapolate_to_tip(mode_one);
  result.mode_two = extrapolate_to_tip(mode_two);
  return result;
}
} // namespace gearstiff::stiffness
