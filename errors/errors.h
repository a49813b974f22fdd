// Error types shared by every gearstiff module. They are a module of their own, below every
// other one and free of deal.II and MPI, so that any module can throw them.
//
// The `gearstiff` command turns an InputError into one line naming the parameter and a non-zero
// exit code, and a SolverFailure into one line naming the method and why it failed. Neither is
// ever caught and replaced by a number.
#pragma once

#include <stdexcept>
#include <string>

namespace gearstiff
{
// Bad input: a value that is out of range, an impossible gear, a missing file, a mesh that
// lacks a named group. `parameter` is the name the user wrote (e.g. "Gear pair/teeth pinion").
class InputError : public std::runtime_error
{
public:
  InputError(const std::string& parameter, const std::string& reason)
      : std::runtime_error(parameter + ": " + reason), parameter_name(parameter),
        reason_text(reason)
  {
  }

  const std::string& parameter() const { return parameter_name; }
  const std::string& reason() const { return reason_text; }

private:
  std::string parameter_name;
  std::string reason_text;
};

// A numerical method that did not deliver: time step above the stability limit, diverging
// integration, contact active-set cycling, Newton iteration limit, singular system.
class SolverFailure : public std::runtime_error
{
public:
  SolverFailure(const std::string& method, const std::string& reason)
      : std::runtime_error(method + ": " + reason), method_name(method), reason_text(reason)
  {
  }

  const std::string& method() const { return method_name; }
  const std::string& reason() const { return reason_text; }

private:
  std::string method_name;
  std::string reason_text;
};
} // namespace gearstiff
