// The pairing window of the mortar coupling (contact/mortar.h), on its own so that the
// surface-face helpers (contact/mortar_faces.h) need it without the coupling's header.
#pragma once

#include <cmath>
#include <deal.II/base/point.h>

namespace gearstiff::contact
{
// A pairing restricted to the surfaces near where the contact can be (rolling sweeps pair
// long swept flanks at every position: contact/contact_problem.h). Distances are measured in
// the x–y plane: in 3D the window is a cylinder parallel to z (a spur gear's contact lines).
template <int dim>
struct PairingWindow
{
  dealii::Point<dim> centre; // m, in the frame the pairing is made in (z ignored)
  double radius = 0.;        // m; 0: no window, the whole surfaces are paired

  // m, distance of p from the centre in the x–y plane
  double distance(const dealii::Point<dim>& p) const
  {
    return std::hypot(p[0] - centre[0], p[1] - centre[1]);
  }
};
} // namespace gearstiff::contact
