// Lengths given on the command line (--size of `protect` and `mesh`): absolute, in the model's
// units, or a percentage of the model's bounding-box diagonal ("1%"), as users of CGAL Mesh_3
// scripts usually think of sizes.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "command.h"

namespace delpsc::app {

/// The length named by `text` ("0.05" or "1%"), for the option `option` (in messages). Throws
/// Failure (bad input) unless it is a finite positive number, optionally followed by '%'.
inline double parse_size(const std::string& text, double diagonal, const char* option = "--size") {
  std::string number = text;
  const bool percent = !number.empty() && number.back() == '%';
  if (percent) number.pop_back();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || errno == ERANGE || !std::isfinite(value) ||
      !(value > 0))
    throw Failure{kBadInput, std::string(option) + " " + text +
                                 ": expected a positive length or a percentage of the diagonal (e.g. 0.05 or 1%)"};
  return percent ? value / 100 * diagonal : value;
}

}  // namespace delpsc::app
