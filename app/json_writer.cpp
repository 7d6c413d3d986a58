#include "json_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace delpsc::app {

namespace {

// The length of the valid UTF-8 sequence starting at s[i], or 0 if there is none (overlong
// forms, surrogates and code points above U+10FFFF are invalid, as RFC 3629 says).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) n = 2;
  else if (b0 >= 0xE0 && b0 <= 0xEF) n = 3, lo = b0 == 0xE0 ? 0xA0 : 0x80, hi = b0 == 0xED ? 0x9F : 0xBF;
  else if (b0 >= 0xF0 && b0 <= 0xF4) n = 4, lo = b0 == 0xF0 ? 0x90 : 0x80, hi = b0 == 0xF4 ? 0x8F : 0xBF;
  else return 0;
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  return n;
}

}  // namespace

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      const std::size_t n = utf8_sequence_length(s, i);
      if (n == 0) {
        out += "\\ufffd";
        ++i;
      } else {
        out.append(s.substr(i, n));
        i += n;
      }
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
    ++i;
  }
  out += '"';
  return out;
}

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  if (ec != std::errc{}) return "null";  // cannot happen: 32 chars hold any double
  return std::string(buf, end);
}

void JsonWriter::before_value() {
  if (open_.empty()) {
    if (!out_.empty()) throw std::logic_error("JsonWriter: a second top-level value");
    return;
  }
  if (open_.back() == Container::kObject) {
    if (!key_pending_) throw std::logic_error("JsonWriter: a value in an object without a key");
    key_pending_ = false;
    return;
  }
  if (has_members_.back()) out_ += ',';
  has_members_.back() = true;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  if (open_.empty() || open_.back() != Container::kObject || key_pending_)
    throw std::logic_error("JsonWriter: key() outside an object or twice in a row");
  if (has_members_.back()) out_ += ',';
  has_members_.back() = true;
  out_ += json_string(name);
  out_ += ':';
  key_pending_ = true;
  return *this;
}

void JsonWriter::open(Container c, char bracket) {
  before_value();
  out_ += bracket;
  open_.push_back(c);
  has_members_.push_back(false);
}

void JsonWriter::close(Container c, char bracket) {
  if (open_.empty() || open_.back() != c || key_pending_)
    throw std::logic_error("JsonWriter: closing a container that is not the innermost open one");
  out_ += bracket;
  open_.pop_back();
  has_members_.pop_back();
}

JsonWriter& JsonWriter::begin_object() { return open(Container::kObject, '{'), *this; }
JsonWriter& JsonWriter::end_object() { return close(Container::kObject, '}'), *this; }
JsonWriter& JsonWriter::begin_array() { return open(Container::kArray, '['), *this; }
JsonWriter& JsonWriter::end_array() { return close(Container::kArray, ']'), *this; }

JsonWriter& JsonWriter::value(std::string_view s) { return raw(json_string(s)); }
JsonWriter& JsonWriter::value(double x) { return raw(json_number(x)); }
JsonWriter& JsonWriter::value(bool b) { return raw(b ? "true" : "false"); }

JsonWriter& JsonWriter::raw(std::string_view json) {
  before_value();
  out_.append(json);
  return *this;
}

}  // namespace delpsc::app
