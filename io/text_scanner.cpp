#include "text_scanner.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace delpsc::io::detail {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The powers of ten that are exact doubles (5^22 < 2^53).
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// Clinger's fast path ("How to read floating point numbers accurately", PLDI 1990): a decimal
// [sign] digits [. digits] [e [sign] digits] whose significant digits form an integer m <= 2^53
// and whose exponent e has |e| <= 22 is m * 10^e or m / 10^-e, both operands exact doubles, so
// the one correctly rounded operation gives the correctly rounded value - what from_chars gives.
// Most model files write a few decimals per coordinate (fandisk.off: four); there this does in
// ~40 instructions what from_chars does in ~150. False (value untouched) for anything else:
// more digits, a larger exponent, "inf", "nan", or not a number at all; parse_double then asks
// from_chars, so both accept and reject exactly the same tokens.
bool parse_short_decimal(const char* p, const char* last, double& value) {
  bool negative = false;
  if (p != last && (*p == '-' || *p == '+')) negative = *p++ == '-';
  std::uint64_t mantissa = 0;
  int digits = 0;    // significant digits in mantissa (leading zeros are not)
  int exponent = 0;  // minus the digits after the point
  bool any = false;
  const auto take_digit = [&](char c) {
    any = true;
    if (mantissa == 0 && c == '0') return true;
    if (++digits > 19) return false;  // 19 digits fit in 64 bits
    mantissa = 10 * mantissa + static_cast<std::uint64_t>(c - '0');
    return true;
  };
  for (; p != last && is_digit(*p); ++p)
    if (!take_digit(*p)) return false;
  if (p != last && *p == '.')
    for (++p; p != last && is_digit(*p); ++p, --exponent)
      if (!take_digit(*p)) return false;
  if (!any) return false;
  if (p != last && (*p == 'e' || *p == 'E')) {
    ++p;
    bool negative_exponent = false;
    if (p != last && (*p == '-' || *p == '+')) negative_exponent = *p++ == '-';
    int e = 0, exponent_digits = 0;
    for (; p != last && is_digit(*p); ++p) {
      if (++exponent_digits > 4) return false;
      e = 10 * e + (*p - '0');
    }
    if (exponent_digits == 0) return false;
    exponent += negative_exponent ? -e : e;
  }
  if (p != last) return false;
  double v = 0;
  if (mantissa != 0) {
    if (mantissa > (std::uint64_t{1} << 53) || exponent < -22 || exponent > 22) return false;
    v = static_cast<double>(mantissa);
    v = exponent < 0 ? v / kExactPowersOfTen[-exponent] : v * kExactPowersOfTen[exponent];
  }
  value = negative ? -v : v;
  return true;
}

}  // namespace

bool parse_double(std::string_view token, double& value) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  if (parse_short_decimal(first, last, value)) return true;
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
