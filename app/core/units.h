// Units of the parameter files and reports (mm, degrees, rpm) in SI, the units every module
// computes in, and the text form of numbers in parameter defaults, report texts and the
// parameter files the commands write (gearstiff::format_number, errors/format.h).
#pragma once

#include "errors/format.h"
#include "errors/limits.h"

#include <cmath>
#include <string>

namespace gearstiff::app
{
constexpr double mm = 1e-3;            // m
constexpr double degree = M_PI / 180.; // rad
constexpr double rpm = M_PI / 30.;     // rad/s

// Units are written one way (docs/developers.md "Units"): UTF-8 symbols in report values and
// texts, parameter documentation and charts (µm, N/µm, N·m, kg·m², µs), ASCII in table headers —
// the CSV files and the tables of summary.json, which scripts read back and users type (um,
// N/um, N*m, kg*m^2, us). The table spelling of `unit`: µ -> u, · -> *, ² -> ^2, ³ -> ^3,
// ° -> deg; Report::add_table applies it, so a table written with a report's symbol still
// follows the rule.
std::string table_unit(const std::string& unit);

// A user's text as echoed in a message: at most `length` characters, longer text cut with "…"
// and its size, so that a 200 kB value does not become a 200 kB error line.
std::string shortened(const std::string& text, unsigned int length = limits::echoed_value_length);

// The number a whole parameter text spells (trailing blanks allowed): false for anything else.
bool read_whole_number(const std::string& text, double& number);

// A length parameter that reads a number >= 0 [mm] or `auto`: true for `auto` (`value` left as
// is), else `value` in m; anything else is an InputError naming `parameter` ("a `what` >= 0").
bool read_length_or_auto(const std::string& text, const std::string& parameter,
                         const std::string& what, double& value);
} // namespace gearstiff::app
