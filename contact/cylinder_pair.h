// The Hertz line-contact case: two cylinders of radii R1 (upper) and R2 (lower) touching at the
// origin along the y axis, each modelled by a segment |x| <= 0.8 R of its cross-section cut
// off by a flat face (upper body: y <= R1, lower body: y >= −R2), meshed with quadrilaterals
// graded geometrically from `fine_size` at the contact point. The two meshes differ (non-
// matching interface). With `depth` > 0 the sections are extruded along z into hexahedra (3D).
//
// Ids: material 1 upper body, 2 lower body; boundary 1 upper contact arc, 2 upper flat top,
// 3 lower contact arc, 4 lower flat bottom, 5 the z faces (3D), 0 the rest (free).
// The Hertz solution it is compared with (Johnson 1985, §4.3) is kinematics/hertz.h.
#pragma once

#include <deal.II/grid/tria.h>
#include <vector>

namespace gearstiff::contact
{
struct CylinderPairGeometry
{
  double upper_radius = 10e-3;   // m, R1
  double lower_radius = 15e-3;   // m, R2
  double fine_size = 5e-6;       // m, cell size at the contact point (upper body)
  double fine_zone = 0.2e-3;     // m, half-width of the uniformly fine zone about x = 0
  double growth = 1.2;           // -, size ratio of neighbouring cells outside the fine zone
  double lower_size_ratio = 1.3; // -, lower cells are this much coarser (non-matching)
  double depth = 0.;             // m, extrusion length in z (0: 2D)
  unsigned int depth_cells = 2;  // cells along z when extruded
};

enum CylinderPairIds : unsigned int
{
  upper_body = 1,
  lower_body = 2,
  upper_contact = 1,
  upper_top = 2,
  lower_contact = 3,
  lower_bottom = 4,
  extrusion_faces = 5
};

// -, cells make_cylinder_pair would create (both bodies; 3D: times depth_cells), counted
// without building anything, so that an absurd fine size can be refused before it runs.
double cylinder_pair_cells(const CylinderPairGeometry& geometry, unsigned int dim);

template <int dim>
void make_cylinder_pair(const CylinderPairGeometry& geometry, dealii::Triangulation<dim>& tria);

struct HertzLineContact
{
  double half_width;    // m, a
  double peak_pressure; // Pa, p0
};

// Least-squares fit of the Hertz profile p² = p0² (1 − x²/a²) to nodal pressures (x measured
// from the first contact point, m; p in Pa): resolves a finer than the node spacing.
HertzLineContact fit_hertz_profile(const std::vector<double>& x, const std::vector<double>& p);
} // namespace gearstiff::contact
