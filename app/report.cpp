#include "report.h"

#include <cstdio>
#include <memory>

#include <delpsc/io/error.h>
#include <delpsc/io/output_file.h>

#include "json_writer.h"

namespace delpsc::app {

void Report::record(const std::string& key, std::string json) {
  for (auto& [k, v] : members_)
    if (k == key) {
      v = std::move(json);
      return;
    }
  members_.emplace_back(key, std::move(json));
}

void Report::add(const std::string& key, const std::string& value) {
  std::printf("%s=%s\n", key.c_str(), value.c_str());
  record(key, json_string(value));
}

void Report::add(const std::string& key, double value) {
  std::printf("%s=%.6g\n", key.c_str(), value);
  record(key, json_number(value));
}

void Report::add(const std::string& key, long long value) {
  std::printf("%s=%lld\n", key.c_str(), value);
  record(key, std::to_string(value));
}

void Report::add(const std::string& key, std::size_t value) {
  std::printf("%s=%zu\n", key.c_str(), value);
  record(key, std::to_string(value));
}

void Report::add(const std::string& key, bool value) {
  std::printf("%s=%s\n", key.c_str(), value ? "true" : "false");
  record(key, value ? "true" : "false");
}

void Report::add_json(const std::string& key, std::string json) { record(key, std::move(json)); }

std::string Report::to_json() const {
  std::string out = "{";
  for (std::size_t i = 0; i < members_.size(); ++i) {
    out += i == 0 ? "\n  " : ",\n  ";
    out += json_string(members_[i].first);
    out += ": ";
    out += members_[i].second;
  }
  out += "\n}\n";
  return out;
}

bool Report::write_json(const std::string& path) const {
  try {
    io::write_output_file(path, to_json());  // no truncated report when the disk is full
    return true;
  } catch (const io::Error&) {
    return false;
  }
}

Report& final_report() {
  static Report report;
  return report;
}

}  // namespace delpsc::app
