// The final report of a delpsc subcommand: key=value lines on stdout, as every subcommand has
// always printed them (tests and scripts parse them), recorded in order so that `--report
// FILE.json` can write the same report as one JSON object, with structured parts (phase times,
// per-patch topology, ...) that do not fit on a line.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace delpsc::app {

class Report {
 public:
  /// Print "key=value" on stdout and record the value for the JSON report. Numbers print with
  /// 6 significant digits (as before the JSON report existed) but are recorded exactly.
  void add(const std::string& key, const std::string& value);
  void add(const std::string& key, double value);
  void add(const std::string& key, long long value);
  void add(const std::string& key, std::size_t value);
  void add(const std::string& key, bool value);

  /// Record a member of the JSON report only (no stdout line); `json` is one complete JSON
  /// value (see json_writer.h).
  void add_json(const std::string& key, std::string json);

  /// The JSON object of every member recorded, in order, one member per line. A key recorded
  /// twice keeps its first position and its last value.
  std::string to_json() const;

  /// Writes to_json() to `path`; false (errno set) if the file cannot be written.
  bool write_json(const std::string& path) const;

 private:
  void record(const std::string& key, std::string json);

  std::vector<std::pair<std::string, std::string>> members_;  // key, JSON text of the value
};

/// The report of this run of the program, fed by report() in command.h and written by main()
/// when --report is given.
Report& final_report();

}  // namespace delpsc::app
