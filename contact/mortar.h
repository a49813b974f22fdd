// Dual-mortar coupling of a slave surface to a master surface, computed once in the reference
// configuration (small sliding).
//
// For each slave node s the dual basis function Φ_s (biorthogonal to the slave shape functions on
// every slave face, Wohlmuth 2000, "A mortar finite element method using dual spaces for the
// Lagrange multiplier", SIAM J. Numer. Anal. 38:989) turns the weak non-penetration condition
// ∫ Φ_s (x̄ + u_m − x − u_s)·n_s ≥ 0 into a nodal one:
//     n_s·( Σ_m (M_sm/D_s) u_m − u_s ) + g_s ≥ 0,   D_s = ∫Φ_s,  M_sm = ∫Φ_s N_m(x̄),
// with x̄ the closest-point projection of the slave point onto the master surface (along the
// master normal) and g_s = n_s·∫Φ_s (x̄ − x) / D_s the weighted initial gap. Once closed it is an
// affine constraint of one slave DoF; because Σ_m M_sm = D_s and the slave faces are split at the
// projected master vertices (2D), a uniform pressure is transmitted exactly across
// non-matching meshes (patch test). In 3D the slave faces are integrated with an iterated Gauss
// rule instead of an exact segmentation (the patch test then holds to the quadrature error).
#pragma once

#include "contact/pairing_window.h"
#include "fem/elastic_system.h"

#include <cmath>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <functional>
#include <vector>

namespace gearstiff::contact
{
// The exact surfaces the meshed (MappingQ1) ones stand for: the point a point of a body's
// trilinear geometry represents, by the material id of its cell. The gap g_s and the offset are
// integrated between these points, so a faceted or chorded surface (a twisted hexahedron's edge
// between two layers is a chord of its helix) does not open or close the contact by its own
// error. Empty: the mesh is the geometry.
template <int dim>
using SurfaceGeometry =
    std::function<dealii::Point<dim>(const dealii::Point<dim>&, dealii::types::material_id)>;

template <int dim>
struct MortarMaster
{
  fem::Node<dim> node;
  double weight; // M_sm / D_s, -; the weights of one slave node sum to 1
};

template <int dim>
struct SlaveNode
{
  fem::Node<dim> node;
  dealii::Tensor<1, dim> normal;                // unit, outward of the slave body
  std::vector<dealii::Tensor<1, dim>> tangents; // dim−1 unit vectors ⟂ normal
  double area = 0.;                             // m², D_s times the 2D thickness
  double initial_gap = 0.;                      // m, g_s (negative: overlap)
  dealii::Tensor<1, dim> initial_offset;        // m, ∫Φ_s (x̄ − x) / D_s
  std::vector<MortarMaster<dim>> masters;
  // Rolling bodies (ContactProblem::roll): the DoFs of the slave and of its masters keep the
  // components of their bodies' own, unrotated frames; frame[c][d] turns component d of such a
  // DoF pair into component c of the frame of `normal`. Unused (identity) unless `rotated`.
  bool rotated = false;
  dealii::Tensor<2, dim> slave_frame, master_frame;
};

// Couples every slave node whose dual support projects onto the master surface within
// `search_distance` (m). `depth` is the 2D thickness (1 in 3D). Identical on every rank.
// `geometry` (optional) corrects the gap and offset for the meshed surfaces' own error.
// With a window, only the slave faces whose centres lie within its radius are paired, and a
// slave node is coupled only when all of its faces are: every coupled node gets exactly the
// mortar data (bit for bit) the whole surfaces would give it — the master faces kept reach far
// enough beyond the window that each slave face meets the same candidates and no cut end of the
// master surface is ever within the search distance —, the nodes outside are not coupled.
template <int dim>
std::vector<SlaveNode<dim>>
mortar_coupling(const dealii::DoFHandler<dim>& dof_handler,
                const std::vector<dealii::types::boundary_id>& slave_boundaries,
                const std::vector<dealii::types::boundary_id>& master_boundaries,
                double search_distance, double depth, const PairingWindow<dim>& window = {},
                const SurfaceGeometry<dim>& geometry = {});
} // namespace gearstiff::contact
