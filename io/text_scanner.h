// Internal to io/: a forward cursor over the text of a model file that counts lines, so that every
// error can say where it happened, and strict number parsing (a token is a number entirely or
// not at all: "1.5abc" is garbage, not 1.5).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace delpsc::io::detail {

class TextScanner {
 public:
  /// `comment`: the character starting a comment to the end of the line, or '\0' for none.
  /// `first_line`: the number of the line `text` starts on (PLY bodies follow a header).
  TextScanner(std::string_view text, char comment, std::size_t first_line = 1)
      : text_(text), line_(first_line) {
    for (const char c : {' ', '\t', '\r', '\f', '\v'}) kind_[byte(c)] = kBlank;
    kind_[byte('\n')] = kLineEnd;
    if (comment != '\0') kind_[byte(comment)] = kComment;
  }

  /// The next token on the current line, or empty if only blanks or a comment remain on it.
  std::string_view token_on_line() {
    skip_blanks();
    return take_token();
  }

  /// The next token, crossing line ends and comments; empty at the end of the text.
  std::string_view token() {
    skip_to_content();
    return take_token();
  }

  /// True if only blanks or a comment remain on the current line.
  bool at_line_end() {
    skip_blanks();
    return pos_ == text_.size() || text_[pos_] == '\n';
  }

  /// Moves past the end of the current line (or to the end of the text).
  void next_line() {
    pos_ = line_end(pos_);
    if (pos_ < text_.size()) {
      ++pos_;
      ++line_;
    }
  }

  /// Skips blanks, comments and line ends; true if text remains.
  bool skip_to_content() {
    for (;;) {
      skip_blanks();
      if (pos_ == text_.size()) return false;
      if (text_[pos_] != '\n') return true;
      ++pos_;
      ++line_;
    }
  }

  /// The rest of the current line, without its line end (the scanner stays on the line).
  std::string_view rest_of_line() const { return text_.substr(pos_, line_end(pos_) - pos_); }

  std::size_t line() const { return line_; }
  std::size_t offset() const { return pos_; }

 private:
  // What each byte is to the scanner, from a table filled once per scanner: a token's bytes cost
  // one load and one compare each instead of a chain of compares (the readers' text formats are
  // mostly bytes of tokens; this halved parse_off's own instructions on fandisk.off).
  enum Kind : unsigned char { kToken = 0, kBlank, kLineEnd, kComment };
  static unsigned char byte(char c) { return static_cast<unsigned char>(c); }
  Kind kind(std::size_t i) const { return static_cast<Kind>(kind_[byte(text_[i])]); }

  /// The position of the first '\n' at or after `from`, or the text's size.
  std::size_t line_end(std::size_t from) const {
    const std::size_t end = text_.find('\n', from);
    return end == std::string_view::npos ? text_.size() : end;
  }

  void skip_blanks() {
    while (pos_ < text_.size() && kind(pos_) == kBlank) ++pos_;
    if (pos_ < text_.size() && kind(pos_) == kComment) pos_ = line_end(pos_);
  }

  std::string_view take_token() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && kind(pos_) == kToken) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
  unsigned char kind_[256] = {};  // Kind of each byte value; kToken unless set
};

/// Parses the whole token as a double (decimal or "inf"/"nan" forms, optional sign); false if it
/// is not exactly one number. Overflow gives +-inf and underflow a denormal or 0, as strtod does:
/// callers reject non-finite coordinates with their place.
bool parse_double(std::string_view token, double& value);

/// Parses the whole token as a decimal integer with optional sign; false if it is not exactly
/// one integer or does not fit in int64.
bool parse_int(std::string_view token, std::int64_t& value);

/// Case-insensitive ASCII comparison (STL and PLY keywords).
bool equals_ignoring_case(std::string_view a, std::string_view b);

}  // namespace delpsc::io::detail
