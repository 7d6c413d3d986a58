#include "huge_page_policy.h"

#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace delpsc::kernel {

namespace {

constexpr std::string_view kBalloonDevice = "0x0005";  // virtio device id of a memory balloon
constexpr std::size_t kFreePageReportingBit = 5;       // VIRTIO_BALLOON_F_REPORTING

std::string first_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

bool reports_free_pages(const std::filesystem::path& virtio_devices) {
  std::error_code error;
  std::filesystem::directory_iterator it(virtio_devices, error), end;
  // Unreadable or absent (not Linux, not a virtio guest): nothing reports free memory.
  for (; !error && it != end; it.increment(error)) {
    if (first_line(it->path() / "device") != kBalloonDevice) continue;
    const std::string features = first_line(it->path() / "features");
    if (features.size() > kFreePageReportingBit && features[kFreePageReportingBit] == '1') return true;
  }
  return false;
}

}  // namespace

bool huge_pages_worthwhile(std::optional<std::string_view> override_value,
                           const std::filesystem::path& virtio_devices) {
  if (override_value == "1") return true;
  if (override_value == "0") return false;
  return !reports_free_pages(virtio_devices);
}

bool huge_pages_advised() {
#if defined(__linux__)
  static const bool advised = [] {
    const char* value = std::getenv("DELPSC_HUGE_PAGES");
    return huge_pages_worthwhile(value ? std::optional<std::string_view>(value) : std::nullopt,
                                 "/sys/bus/virtio/devices");
  }();
  return advised;
#else
  return false;
#endif
}

}  // namespace delpsc::kernel
