#include <doctest/doctest.h>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

#include <delpsc/io/text_scanner.h>

using delpsc::io::detail::parse_double;
using delpsc::io::detail::TextScanner;

namespace {

// The oracle: strtod on the whole token (its own parser, independent of parse_double's fast path
// and of from_chars). Accepted iff strtod consumes every character - but hexadecimal, which
// strtod reads and the model formats do not have (from_chars' general format refuses it).
bool oracle(const std::string& token, double& value) {
  if (token.empty() || token.find_first_of("xX") != std::string::npos) return false;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

void check_same(const std::string& token) {
  CAPTURE(token);
  double want = 0, got = 0;
  const bool accepted = oracle(token, want);
  REQUIRE(parse_double(token, got) == accepted);
  if (accepted) CHECK(std::bit_cast<std::uint64_t>(got) == std::bit_cast<std::uint64_t>(want));
}

}  // namespace

TEST_CASE("parse_double agrees with strtod bit for bit, fast path and fallback alike") {
  for (const char* t : {"0", "-0", "+0", "0.0", "-0.000", "1", "-1", "+1", ".5", "-.5", "+.5", "5.", "-5.", "1e22",
                        "1e23", "9007199254740992", "9007199254740993", "9007199254740992e-22", "123456789012345678",
                        "1234567890123456789", "12345678901234567890", "0.1", "0.3", "2.2250738585072014e-308",
                        "4.9e-324", "1e-400", "1.7976931348623157e308", "1e309", "-1e309", "1e", "1e+", "e5", ".",
                        "-", "+", "+-1", "-+1", "++1", "--1", "1.2.3", "1e5.5", "1e99999", "0e99999", "00012.500",
                        "0.000000000000000000000000001", "inf", "-inf", "nan", "infinity", "0x1p3", "1,5", "1.5abc",
                        "3.14159", "-0.046", "0.1809", "1E-3", "1e-22", "1e-23", "4503599627370497.5"})
    check_same(t);

  // Random decimals of every shape the grammar allows, around the fast path's limits (19
  // digits, 2^53, exponents +-22) and beyond them.
  std::mt19937_64 rng(11);
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); };
  for (int k = 0; k < 200000; ++k) {
    std::string t;
    if (pick(3) == 0) t += pick(2) ? '-' : '+';
    const int digits = 1 + pick(21);
    const int point = pick(digits + 2) - 1;  // -1: no point
    for (int d = 0; d < digits; ++d) {
      if (d == point) t += '.';
      t += static_cast<char>('0' + (pick(4) == 0 ? 0 : pick(10)));
    }
    if (point == digits) t += '.';
    if (pick(2) == 0) {
      t += pick(2) ? 'e' : 'E';
      if (pick(2) == 0) t += pick(2) ? '-' : '+';
      t += std::to_string(pick(40));
    }
    check_same(t);
  }
  // Random strings over the grammar's alphabet: mostly malformed, which both must refuse.
  const std::string alphabet = "0123456789.eE+-";
  for (int k = 0; k < 100000; ++k) {
    std::string t;
    for (int n = 1 + pick(12); n > 0; --n) t += alphabet[static_cast<std::size_t>(pick(static_cast<int>(alphabet.size())))];
    check_same(t);
  }
}

TEST_CASE("TextScanner: tokens, blanks, comments and line ends") {
  TextScanner in("OFF # a comment\n\t 3  4\r\n\n#only a comment\n1.5 -2 x#y\nlast", '#');
  CHECK(in.token() == "OFF");
  CHECK(in.line() == 1);
  CHECK(in.token_on_line().empty());  // only the comment is left on line 1
  CHECK(in.at_line_end());
  CHECK(in.token() == "3");
  CHECK(in.line() == 2);
  CHECK(in.token_on_line() == "4");
  CHECK(in.at_line_end());  // '\r' is a blank
  CHECK(in.token() == "1.5");
  CHECK(in.line() == 5);
  CHECK(in.rest_of_line() == " -2 x#y");
  CHECK(in.token() == "-2");
  CHECK(in.token() == "x");  // a comment ends a token
  in.next_line();
  CHECK(in.line() == 6);
  CHECK(in.token() == "last");
  CHECK(in.token().empty());
  CHECK_FALSE(in.skip_to_content());

  // Without a comment character '#' is an ordinary byte, and so is '\0'.
  TextScanner plain(std::string_view("a#b c\0d", 7), '\0');
  CHECK(plain.token() == "a#b");
  CHECK(plain.token() == std::string_view("c\0d", 3));
}
