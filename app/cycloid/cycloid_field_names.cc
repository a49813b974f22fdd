// The cycloid fields as the parameters the user writes: the cycloid scene ("Cycloid
// scene/...", geometry/fields.h), the profile correction of `gearstiff cycloid` ("Cycloid
// correction/..."; cycloid-loads maps the same fields to its own entries at the call) and the
// load analysis ("Cycloid loads/...", stiffness::field::cycloid_loads; "Contact/Overlap tolerance"
// is the contact table's, app/scenes/fe_contact_parameters.cc). app/core/field_names.h says why.
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
  return field_family("Cycloid loads", stiffness::field::cycloid_loads_fields(),
                      stiffness::field::cycloid_loads,
                      {{"young_modulus", "Young's modulus"},
                       {"roller_young_modulus", "roller Young's modulus"},
                       {"poisson_ratio", "Poisson's ratio"}});
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
