#include "geometry/tooth_profiles.h"

#include "geometry/tooth_fault.h"

#include <utility>

namespace gearstiff::geometry
{
ToothProfiles::ToothProfiles(ToothProfile nominal, GearModifications modifications,
                             FlankRollRange range, int loaded_side, std::string parameter)
    : nominal_tooth(std::move(nominal)), modifications(std::move(modifications)), range(range),
      loaded_side(loaded_side), parameter(std::move(parameter))
{
  // Every list is checked once here, before anything is meshed.
  if (!this->modifications.all_teeth.empty())
    check_modifications(this->modifications.all_teeth, nominal_tooth, range, this->parameter);
  for (const auto& [index, list] : this->modifications.by_tooth)
    if (!list.empty())
    {
      check_modifications(modifications_of(index), nominal_tooth, range, this->parameter);
      check_faults(modifications_of(index), nominal_tooth, range, loaded_side, this->parameter);
    }
}

const std::vector<ToothModification>& ToothProfiles::modifications_of(int index) const
{
  const auto own = modifications.by_tooth.find(index);
  if (own == modifications.by_tooth.end() || own->second.empty())
    return modifications.all_teeth;
  // The gear's list first, then the tooth's own (kept so the reference stays valid).
  auto& list = joined[index];
  list = modifications.all_teeth;
  list.insert(list.end(), own->second.begin(), own->second.end());
  return list;
}

const ToothProfile& ToothProfiles::tooth(int index) const
{
  const auto& list = modifications_of(index);
  if (list.empty())
    return nominal_tooth; // a healthy tooth is the nominal outline itself
  const auto found = built.find(index);
  if (found != built.end())
    return found->second;
  // The profile modifications first (faults change no flank depth), then the faults cut the
  // modified outline (geometry/tooth_fault.h).
  return built.emplace(index, apply_faults(unfaulted_tooth(index), list, loaded_side))
      .first->second;
}

ToothProfile ToothProfiles::unfaulted_tooth(int index) const
{
  return modified_tooth(nominal_tooth, modifications_of(index), range, loaded_side, parameter);
}

double ToothProfiles::loaded_flank_removal(int index, double roll) const
{
  return removed_depth(modifications_of(index), range, roll, true) +
         fault_flank_depth(modifications_of(index), nominal_tooth, roll);
}
} // namespace gearstiff::geometry
