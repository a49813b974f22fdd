// Entries of the Train subsection that the rotational (`Train/model = train`) and the lateral
// (`Train/model = lateral`) dynamics share: lists of "name: v1 v2 ..., ..." and plain text
// entries declared from a table (app/core/parameter_table.h).
#pragma once

#include "app/core/parameter_table.h"

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::app
{
enum class NumberSign
{
  non_negative, // suspensions, widths, bores, stiffnesses
  any           // angles, pin errors
};

// "name: v1 v2 ..., ..." → (name, numbers) in the order given: `count` finite numbers per name
// (0: one or more). InputError naming `parameter` for an entry that is not
// 'name: <units>' (with non-negative numbers unless `sign` is any) or that repeats a name.
std::vector<std::pair<std::string, std::vector<double>>>
parse_named_numbers(const std::string& text, unsigned int count, const std::string& parameter,
                    const std::string& units, NumberSign sign = NumberSign::non_negative);
} // namespace gearstiff::app
