// The cycloid fields as the parameters the user writes: the cycloid scene ("Cycloid
// scene/...", geometry/fields.h), the profile correction of `gearstiff cycloid` ("Cycloid
// correction/..."; cycloid-loads maps the same fields to its own entries at the call) and the
// load analysis ("Cycloid loads/...", "Contact/Overlap tolerance": stiffness::cycloid_parameter).
// app/core/field_names.h says why.
#include "app/core/field_names.h"
#include "geometry/fields.h"
#include "stiffness/cycloid_loads.h"

namespace gearstiff::app
{
namespace
{
namespace field = geometry::field;

ParameterNames cycloid_loads_field_names()
{
  namespace name = stiffness::cycloid_parameter;
  return {{name::torque, "Cycloid loads/output torque"},
          {name::contact_arc_ratio, "Cycloid loads/contact arc ratio"},
          {name::young_modulus, "Cycloid loads/Young's modulus"},
          {name::roller_young_modulus, "Cycloid loads/roller Young's modulus"},
          {name::poisson_ratio, "Cycloid loads/Poisson's ratio"},
          {name::overlap_tolerance, "Contact/Overlap tolerance"}};
}

const FieldNamesRegistration scene(
    "cycloid scene", []
    { return field_family("Cycloid scene", field::cycloid_scene_fields(), field::cycloid_scene); });
const FieldNamesRegistration correction(
    "cycloid correction", []
    { return field_family("Cycloid correction", field::correction_fields(), field::correction); });
const FieldNamesRegistration loads("cycloid loads", cycloid_loads_field_names);
} // namespace
} // namespace gearstiff::app
