#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <delpsc/kernel/huge_page_policy.h>

#include <unistd.h>

using namespace delpsc;

namespace {

// A fake /sys/bus/virtio/devices under a fresh temporary directory, removed at the end.
struct FakeVirtio {
  std::filesystem::path root;
  FakeVirtio() {
    static int made = 0;
    root = std::filesystem::temp_directory_path() /
           ("delpsc-virtio-" + std::to_string(::getpid()) + "-" + std::to_string(made++));
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root);
  }
  ~FakeVirtio() { std::filesystem::remove_all(root); }
  void device(const std::string& name, const std::string& id, const std::string& features) const {
    std::filesystem::create_directories(root / name);
    std::ofstream(root / name / "device") << id << "\n";
    std::ofstream(root / name / "features") << features << "\n";
  }
};

}  // namespace

TEST_CASE("huge pages: where base-page faults are dear, or where no balloon reports free memory; overridable") {
  const FakeVirtio sys;
  // `asked` counts the calls: the fault cost is asked unless the environment decides.
  int asked = 0;
  const auto cheap = [&asked] { return ++asked, 1.6; };  // session 29's machines
  const auto dear = [&asked] { return ++asked, 11.0; };  // session 35's
  // No virtio devices at all (bare metal, or another hypervisor): worthwhile.
  CHECK(kernel::huge_pages_worthwhile(std::nullopt, sys.root, cheap));
  CHECK(kernel::huge_pages_worthwhile(std::nullopt, sys.root / "absent", cheap));
  // A network device with bit 5 set is no balloon; a balloon without bit 5 does not report.
  sys.device("virtio0", "0x0001", "01100101000000000000000000000000");
  sys.device("virtio1", "0x0005", "01100001000000000000000000000000");
  CHECK(kernel::huge_pages_worthwhile(std::nullopt, sys.root, cheap));
  CHECK(asked == 3);
  // A balloon that negotiated free page reporting (the machines of BENCHMARKS.md, session 29):
  // huge pages only where a base-page fault is dearer than kDearBasePageFault.
  sys.device("virtio2", "0x0005", "01100101000000000000000000000000");
  CHECK_FALSE(kernel::huge_pages_worthwhile(std::nullopt, sys.root, cheap));
  CHECK(kernel::huge_pages_worthwhile(std::nullopt, sys.root, dear));
  CHECK(asked == 5);
  CHECK_FALSE(kernel::huge_pages_worthwhile(std::nullopt, sys.root, [] { return kernel::kDearBasePageFault; }));
  // Dear faults decide without the balloon, even where sysfs cannot be read.
  CHECK(kernel::huge_pages_worthwhile(std::nullopt, sys.root / "absent", dear));
  // DELPSC_HUGE_PAGES decides either way, without a measurement; any other value decides nothing.
  CHECK(kernel::huge_pages_worthwhile("1", sys.root, cheap));
  CHECK_FALSE(kernel::huge_pages_worthwhile("0", sys.root, dear));
  CHECK(asked == 6);
  CHECK_FALSE(kernel::huge_pages_worthwhile("yes", sys.root, cheap));
  CHECK_FALSE(kernel::huge_pages_worthwhile("", sys.root, cheap));
  CHECK(kernel::huge_pages_worthwhile("", sys.root, dear));
  FakeVirtio bare;
  CHECK_FALSE(kernel::huge_pages_worthwhile("0", bare.root, cheap));
  CHECK(kernel::huge_pages_worthwhile("2", bare.root, cheap));
}

TEST_CASE("huge pages: a base-page fault is timed once, and costs something") {
#ifdef __linux__
  const double first = kernel::base_page_fault_microseconds();
  // A fault takes at least a trap into the kernel (well above 10 ns) and, even on the slowest
  // machine seen (14 us), far below a second.
  CHECK(first > 0.01);
  CHECK(first < 1e6);
  CHECK(kernel::base_page_fault_microseconds() == first);  // cached: the same answer, bit for bit
#else
  CHECK(kernel::base_page_fault_microseconds() == 0.0);
#endif
}

TEST_CASE("huge pages: the process-wide answer is this machine's, from the real environment and sysfs") {
#ifdef __linux__
  // Fails if huge_pages_advised() read another variable or directory than it documents, or
  // cached a different answer; the environment is not changed while the suite runs.
  const char* value = std::getenv("DELPSC_HUGE_PAGES");
  const std::optional<std::string_view> override_value =
      value ? std::optional<std::string_view>(value) : std::nullopt;
  CHECK(kernel::huge_pages_advised() ==
        kernel::huge_pages_worthwhile(override_value, "/sys/bus/virtio/devices",
                                      kernel::base_page_fault_microseconds));
#else
  CHECK_FALSE(kernel::huge_pages_advised());
#endif
}
