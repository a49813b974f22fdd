// Stress intensity factors at the tip of a crack whose faces meet (issue 31), from the FE
// displacements by displacement correlation: near the tip of a crack in a linear elastic body the
// jump of the displacement across the faces at distance r behind the tip is (Williams' expansion,
// plane strain κ = 3 − 4ν, plane stress κ = (3 − ν)/(1 + ν))
//
//     Δu_n = 8 K_I /E' · √(r/2π),   Δu_t = 8 K_II /E' · √(r/2π),
//
// E' = E/(1 − ν²) in plane strain, E in plane stress; n is the normal to the faces (the upper
// face minus the lower one, "upper" on the left of the crack's direction from mouth to tip) and
// t the crack's direction. Each pair of coincident face nodes gives an apparent K(r); the next
// terms of the expansion make K(r) linear in r near the tip, so a straight line fitted over
// the nodes within [fit_from, fit_to] of the tip and extrapolated to r = 0 is the result
// (Chan, Tuba & Wilson 1970; docs/references.md §16 for the strip it is checked against).
// Where the faces are closed Δu_n = 0: K_I comes out near zero.
#pragma once

#include "fem/fields.h"

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/vector.h>

namespace gearstiff::stiffness
{
struct CrackTipFactors
{
  double mode_one = 0.;       // Pa·m^½, K_I (opening)
  double mode_two = 0.;       // Pa·m^½, K_II (in-plane shear; > 0: upper face ahead)
  double tip_x = 0.;          // m, the tip (the faces' common node)
  double tip_y = 0.;          // m
  double length = 0.;         // m, from the mouth to the tip
  unsigned int fit_nodes = 0; // -, node pairs in the fit

  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("mode_one", self.mode_one);
    visit("mode_two", self.mode_two);
    visit("tip_x", self.tip_x);
    visit("tip_y", self.tip_y);
    visit("length", self.length);
    visit("fit_nodes", self.fit_nodes);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

// The fit range of crack_tip_factors in cells of the tip size h_tip (the meshes of
// geometry/tooth_fault.h keep h_tip within 10 h_tip of the tip): from h_tip, past the first
// cell, whose non-singular displacement misses the √r shape most, to 8 h_tip.
constexpr double crack_fit_from = 1.;
constexpr double crack_fit_to = 8.;

// `face`, `other_face`: the boundary ids of the two faces (2D; they meet at the tip only);
// `plane_strain_modulus`: E' (Pa); nodes at distances in [fit_from, fit_to] (m) from the tip
// enter the fit (at least two: SolverFailure otherwise, naming "crack tip factors"). Works on
// the cells this rank owns or knows (a shared triangulation: all).
CrackTipFactors crack_tip_factors(const dealii::DoFHandler<2>& dof_handler,
                                  const dealii::Mapping<2>& mapping,
                                  const dealii::Vector<double>& displacement,
                                  dealii::types::boundary_id face,
                                  dealii::types::boundary_id other_face,
                                  double plane_strain_modulus, double fit_from, double fit_to);
} // namespace gearstiff::stiffness
