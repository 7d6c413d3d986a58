// Writing JSON text (RFC 8259) for the reports of the delpsc command (`--report FILE.json`): a
// small streaming writer of objects, arrays, strings, numbers, booleans and null. It only writes;
// nothing in the project reads JSON back (tests validate it with python3 -m json.tool).
#pragma once

#include <concepts>
#include <string>
#include <string_view>
#include <vector>

namespace delpsc::app {

/// `s` as a JSON string literal, quotes included: '"', '\\' and control characters escaped;
/// valid UTF-8 kept as it is, every byte that is not part of a valid UTF-8 sequence replaced by
/// U+FFFD (file names need not be UTF-8, JSON text must be). O(|s|).
std::string json_string(std::string_view s);

/// `x` as a JSON number: the shortest decimal that reads back as the same double; null when
/// x is infinite or NaN (JSON has no such numbers).
std::string json_number(double x);

/// Builds one JSON value in a string. Calls must nest properly (begin_object ... end_object,
/// and inside an object key() before each value); a misuse throws std::logic_error.
class JsonWriter {
 public:
  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  /// The name of the next member of the enclosing object.
  JsonWriter& key(std::string_view name);

  JsonWriter& value(std::string_view s);
  JsonWriter& value(const char* s) { return value(std::string_view(s)); }
  JsonWriter& value(const std::string& s) { return value(std::string_view(s)); }
  JsonWriter& value(double x);
  JsonWriter& value(bool b);
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  JsonWriter& value(T n) {
    return raw(std::to_string(n));
  }
  JsonWriter& null() { return raw("null"); }
  /// Inserts `json`, which must already be one complete JSON value.
  JsonWriter& raw(std::string_view json);

  /// The text written so far; a complete value once every container is closed.
  const std::string& str() const { return out_; }
  bool complete() const { return open_.empty() && !out_.empty(); }

 private:
  enum class Container : char { kObject, kArray };
  void before_value();
  void open(Container c, char bracket);
  void close(Container c, char bracket);

  std::string out_;
  std::vector<Container> open_;
  std::vector<bool> has_members_;  // per open container
  bool key_pending_ = false;       // inside an object: key() written, its value not yet
};

}  // namespace delpsc::app
