#include "huge_page_policy.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

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
                           const std::filesystem::path& virtio_devices,
                           const std::function<double()>& base_page_fault_us) {
  if (override_value == "1") return true;
  if (override_value == "0") return false;
  // The fault cost first: timing six faults (~0.2 ms where they are dear) is cheaper than a first
  // walk of sysfs through std::filesystem and iostreams (~0.7 ms on those machines, most of it
  // the faults of their own first use), which the answer then does not need.
  return base_page_fault_us() > kDearBasePageFault || !reports_free_pages(virtio_devices);
}

double base_page_fault_microseconds() {
#if defined(__linux__)
  static const double cost = [] {
    constexpr int kBatches = 3, kPagesPerBatch = 2;
    const long page = ::sysconf(_SC_PAGESIZE);
    if (page <= 0) return 0.0;
    const std::size_t bytes = std::size_t(page) * kBatches * kPagesPerBatch;
    void* block = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (block == MAP_FAILED) return 0.0;
#if defined(MADV_NOHUGEPAGE)
    (void)::madvise(block, bytes, MADV_NOHUGEPAGE);  // base pages even where THP is "always"
#endif
    auto* bytes_of = static_cast<volatile char*>(block);
    double least = std::numeric_limits<double>::infinity();
    for (int b = 0; b < kBatches; ++b) {
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < kPagesPerBatch; ++i) bytes_of[std::size_t(b * kPagesPerBatch + i) * std::size_t(page)] = 1;
      const std::chrono::duration<double, std::micro> took = std::chrono::steady_clock::now() - start;
      least = std::min(least, took.count() / kPagesPerBatch);
    }
    ::munmap(block, bytes);
    return least;
  }();
  return cost;
#else
  return 0.0;
#endif
}

bool huge_pages_advised() {
#if defined(__linux__)
  static const bool advised = [] {
    const char* value = std::getenv("DELPSC_HUGE_PAGES");
    return huge_pages_worthwhile(value ? std::optional<std::string_view>(value) : std::nullopt,
                                 "/sys/bus/virtio/devices", base_page_fault_microseconds);
  }();
  return advised;
#else
  return false;
#endif
}

}  // namespace delpsc::kernel
