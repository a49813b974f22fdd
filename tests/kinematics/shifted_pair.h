// A spur pair of module 4 mm, α_n 20°, face width 30 mm with the given teeth and profile shifts
// (the own pair of issue 41 is 23/61, x 0.2/−0.1): the gear-pair module's oracle for the train
// model's shifted meshes (tests/kinematics/test_gear_train.cc, tests/dynamics/test_train_model.cc).
#pragma once

#include "kinematics/gear_pair.h"

#include <cmath>

namespace gearstiff::test_support
{
inline kinematics::GearPairSpec shifted_pair(unsigned int z1, unsigned int z2, double x1, double x2,
                                             bool internal)
{
  kinematics::GearPairSpec spec;
  for (kinematics::GearSpec* g : {&spec.pinion, &spec.wheel})
  {
    g->normal_module = 4e-3;
    g->pressure_angle = 20. * M_PI / 180.;
    g->face_width = 30e-3;
  }
  spec.pinion.teeth = z1;
  spec.wheel.teeth = z2;
  spec.pinion.profile_shift = x1;
  spec.wheel.profile_shift = x2;
  spec.wheel.internal = internal;
  return spec;
}
} // namespace gearstiff::test_support
