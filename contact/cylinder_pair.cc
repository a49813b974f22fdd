#include "contact/cylinder_pair.h"

#include "fem/mesh.h"

#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <vector>

namespace gearstiff::contact
{
using namespace dealii;

namespace
{
// Cell sizes from 0 to `length`: `fine_zone` in cells of about `fine`, then growing by
// `growth` per cell, the graded part scaled to end exactly at `length`.
std::vector<double> graded_steps(double fine, double fine_zone, double growth, double length)
{
  std::vector<double> steps;
  const unsigned int n_fine = std::max(1., std::ceil(std::min(fine_zone, length) / fine));
  for (unsigned int i = 0; i < n_fine; ++i)
    steps.push_back(std::min(fine_zone, length) / n_fine);
  const double rest = length - std::min(fine_zone, length);
  std::vector<double> graded;
  double size = steps.back(), sum = 0.;
  while (sum < rest)
  {
    size *= growth;
    graded.push_back(size);
    sum += size;
  }
  if (!graded.empty() && sum - rest > 0.5 * graded.back())
  {
    sum -= graded.back();
    graded.pop_back();
  }
  for (const double s : graded)
    steps.push_back(s * rest / sum);
  return steps;
}

// The number of steps graded_steps returns, in closed form (the fine part alone could be
// billions of cells for an absurd fine size).
double graded_count(double fine, double fine_zone, double growth, double length)
{
  const double zone = std::min(fine_zone, length);
  const double n_fine = std::max(1., std::ceil(zone / fine));
  const double rest = length - zone;
  // Geometric sizes s·g^k, k = 1..n, sum s·g·(g^n − 1)/(g − 1) ≥ rest.
  const double first = zone / n_fine;
  const double n_graded =
      rest > 0.
          ? std::ceil(std::log(1. + rest * (growth - 1.) / (first * growth)) / std::log(growth))
          : 0.;
  return n_fine + n_graded;
}

double body_cells(double radius, double fine, const CylinderPairGeometry& geometry,
                  unsigned int dim)
{
  const double across = 2. * graded_count(fine, geometry.fine_zone, geometry.growth, 0.8 * radius);
  const double depth = graded_count(fine, 0.5 * geometry.fine_zone, geometry.growth, radius);
  return across * depth * (dim == 3 ? geometry.depth_cells : 1.);
}

// One body: the section |x| <= 0.8 R between the contact arc (y = ±(R − sqrt(R² − x²)))
// and the flat face y = ±R; `sign` +1 for the upper body, −1 for the lower one.
template <int dim>
void make_body(double radius, double fine, const CylinderPairGeometry& geometry, int sign,
               Triangulation<dim>& tria)
{
  const double half_width = 0.8 * radius;
  const std::vector<double> half =
      graded_steps(fine, geometry.fine_zone, geometry.growth, half_width);
  std::vector<std::vector<double>> steps(dim);
  steps[0].assign(half.rbegin(), half.rend());
  steps[0].insert(steps[0].end(), half.begin(), half.end());
  // Depth direction η: distance from the contact, from 0 to R.
  const std::vector<double> depth_steps =
      graded_steps(fine, 0.5 * geometry.fine_zone, geometry.growth, radius);
  if (sign > 0)
    steps[1] = depth_steps;
  else
    steps[1].assign(depth_steps.rbegin(), depth_steps.rend());
  Point<dim> low, high;
  low[0] = -half_width;
  high[0] = half_width;
  low[1] = sign > 0 ? 0. : -radius;
  high[1] = sign > 0 ? radius : 0.;
  if constexpr (dim == 3)
  {
    steps[2].assign(geometry.depth_cells, geometry.depth / geometry.depth_cells);
    high[2] = geometry.depth;
  }
  GridGenerator::subdivided_hyper_rectangle(tria, steps, low, high, true);

  GridTools::transform(
      [radius, sign](const Point<dim>& p)
      {
        Point<dim> q = p;
        const double arc = radius - std::sqrt(radius * radius - p[0] * p[0]);
        // η = |p[1]| runs from the arc (η = 0) to the flat face (η = R).
        const double eta = std::abs(p[1]) / radius;
        q[1] = sign * (arc + (radius - arc) * eta);
        return q;
      },
      tria);

  const types::material_id material = sign > 0 ? upper_body : lower_body;
  for (const auto& cell : tria.active_cell_iterators())
  {
    cell->set_material_id(material);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
      {
        const auto id = cell->face(f)->boundary_id();
        types::boundary_id next = 0;
        if (id == 2)
          next = sign > 0 ? upper_contact : lower_bottom;
        else if (id == 3)
          next = sign > 0 ? upper_top : lower_contact;
        else if (id >= 4)
          next = extrusion_faces;
        cell->face(f)->set_boundary_id(next);
      }
  }
}
} // namespace

double cylinder_pair_cells(const CylinderPairGeometry& geometry, const unsigned int dim)
{
  return body_cells(geometry.upper_radius, geometry.fine_size, geometry, dim) +
         body_cells(geometry.lower_radius, geometry.fine_size * geometry.lower_size_ratio, geometry,
                    dim);
}

template <int dim>
void make_cylinder_pair(const CylinderPairGeometry& geometry, Triangulation<dim>& tria)
{
  Triangulation<dim> upper, lower;
  make_body(geometry.upper_radius, geometry.fine_size, geometry, +1, upper);
  make_body(geometry.lower_radius, geometry.fine_size * geometry.lower_size_ratio, geometry, -1,
            lower);
  fem::join_bodies<dim>({&upper, &lower}, tria);
}

HertzLineContact fit_hertz_profile(const std::vector<double>& x, const std::vector<double>& p)
{
  double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
  for (unsigned int k = 0; k < x.size(); ++k)
  {
    const double x2 = x[k] * x[k], p2 = p[k] * p[k];
    s0 += 1;
    s1 += x2;
    s2 += x2 * x2;
    t0 += p2;
    t1 += p2 * x2;
  }
  const double det = s0 * s2 - s1 * s1;
  const double squared_peak = (s2 * t0 - s1 * t1) / det;
  const double slope = -(s0 * t1 - s1 * t0) / det;
  return {std::sqrt(squared_peak / slope), std::sqrt(squared_peak)};
}

template void make_cylinder_pair(const CylinderPairGeometry&, Triangulation<2>&);
template void make_cylinder_pair(const CylinderPairGeometry&, Triangulation<3>&);
} // namespace gearstiff::contact
