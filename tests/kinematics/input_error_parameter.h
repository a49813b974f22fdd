// The parameter an InputError names (the one the user has to fix), for tests of bad input.
#pragma once

#include "errors/errors.h"

#include <string>

namespace gearstiff::test_support
{
// Runs f(); the parameter of the InputError it throws, or "no error".
template <typename F>
std::string input_error_parameter(F&& f)
{
  try
  {
    f();
  }
  catch (const InputError& e)
  {
    return e.parameter();
  }
  return "no error";
}
} // namespace gearstiff::test_support
