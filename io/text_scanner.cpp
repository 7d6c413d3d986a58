#include "text_scanner.h"

#include <charconv>
#include <cstdlib>
#include <string>

namespace delpsc::io::detail {

bool parse_double(std::string_view token, double& value) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (*first == '+') {  // from_chars refuses a leading '+'; files have them
    ++first;
    if (first == last || *first == '+' || *first == '-') return false;
  }
  const auto [end, ec] = std::from_chars(first, last, value);
  if (end != last) return false;
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves value untouched; strtod gives the conventional +-inf / denormal / 0.
    const std::string copy(first, last);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return ec == std::errc();
}

bool parse_int(std::string_view token, std::int64_t& value) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (*first == '+') {
    ++first;
    if (first == last || *first == '+' || *first == '-') return false;
  }
  const auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

}  // namespace delpsc::io::detail
