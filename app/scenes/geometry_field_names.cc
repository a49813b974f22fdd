// The geometry library's fields (geometry/fields.h) as the parameters the user writes: the mesh
// settings ("Mesh/...", every command that meshes a scene), the CalculiX deck ("Abaqus
// deck/..."), the cylinder scene ("Cylinders/...") and the cycloid disc ("Cycloid disc/...").
// app/core/field_names.h says why.
#include "app/core/field_names.h"
#include "geometry/fields.h"

namespace gearstiff::app
{
namespace
{
namespace field = geometry::field;

ParameterNames mesh_field_names()
{
  ParameterNames names = field_family("Mesh", field::mesh_fields(), field::mesh);
  names[field::mesh("file")] = "Scene/mesh file";
  return names;
}

const FieldNamesRegistration mesh("mesh", mesh_field_names);
const FieldNamesRegistration
    deck("abaqus deck",
         [] { return field_family("Abaqus deck", field::deck_fields(), field::deck); });
const FieldNamesRegistration
    cylinders("cylinders",
              []
              {
                return field_family(
                    "Cylinders", field::cylinders_fields(), field::cylinders,
                    {{"young_modulus", "Young's modulus"}, {"poisson_ratio", "Poisson's ratio"}});
              });
const FieldNamesRegistration
    disc("cycloid disc",
         [] { return field_family("Cycloid disc", field::disc_fields(), field::disc); });
} // namespace
} // namespace gearstiff::app
