// A checker's problem lines as one doctest message. INFO lasts only to the end of its scope, so
// `for (p : problems) INFO(p);` before a CHECK shows nothing when the CHECK fails; pass this to
// CHECK_MESSAGE instead.
#pragma once

#include <string>
#include <vector>

namespace delpsc::test {

inline std::string problem_lines(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& p : problems) text += "\n  " + p;
  return problems.empty() ? std::string("(no problem lines)") : text;
}

}  // namespace delpsc::test
