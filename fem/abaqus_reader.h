// Reading CalculiX/Abaqus input decks (.inp) as meshes, so meshes from other pre-processors (and
// decks written by `gearstiff mesh --set "Mesh/format=inp"`) run in gearstiff.
//
// What is read: *NODE, *ELEMENT (CPE4, CPE4R, CPS4, CPS4R in 2D; C3D8, C3D8R, C3D8I in 3D — the
// corner topology only, gearstiff chooses its own element), *ELSET (lists and GENERATE) and
// *SURFACE of TYPE=ELEMENT (lines "element or element set, Sn"), *INCLUDE (INPUT= relative to
// the including file). Every other keyword and its data lines are skipped: material, steps and
// loads are gearstiff's own parameters.
//
// Groups: every element set is a cell group (material id: sets numbered 1, 2, ... in the order
// they first appear; a cell takes the id of the first set that lists it) and every element-face
// surface a face group (boundary ids 1, 2, ... likewise). A set "PINION_BODY" is named "pinion
// body" (lower case, '_' to ' ': the inverse of geometry/abaqus_deck.h's naming). Nodes that no
// element uses (rigid-body reference nodes) are dropped.
//
// Bad input — an unsupported element type, a set or element a line refers to that does not
// exist, an *INCLUDE that cannot be opened, a malformed data line — throws InputError(parameter)
// whose reason names the file, the line number and the keyword.
#pragma once

#include "fem/mesh.h"

#include <deal.II/grid/tria.h>
#include <string>

namespace gearstiff::fem
{
template <int dim>
PhysicalNames read_abaqus(const std::string& file_name, double scale,
                          dealii::Triangulation<dim>& tria, const std::string& parameter);

// "PINION_BODY" -> "pinion body".
std::string group_name_from_abaqus(const std::string& set_name);
} // namespace gearstiff::fem
