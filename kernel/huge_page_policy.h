// Whether the large arrays (large_array.h) should ask Linux for transparent huge pages.
//
// Why a policy and not always: the first touch of fresh memory is a page fault, and which page
// size makes it cheaper depends on where the process runs. On bare metal and on ordinary virtual
// machines a 2 MiB huge page costs one fault and one clear instead of 512 faults, and fewer TLB
// misses after (the cube at 0.456%: -40% CPU time, BENCHMARKS.md "Session 18"). On a virtual
// machine whose balloon device reports free memory to the host (virtio-balloon's free page
// reporting, feature bit 5), first touching a fresh huge page cut from memory already reported
// to the host cost 2.0-3.3 ms a MiB against 0.4 ms a MiB for base pages, measured in fresh
// processes on our CI machines (huge pages were cheap there only while the memory freed by the
// previous process had not been reported yet, about 2 s); a mesher run at 0.5% touches 30-100 MiB
// (BENCHMARKS.md, "Session 29"). Why the host makes it so slow we did not find out.
//
// Cost: huge_pages_advised() reads the environment and a few sysfs files once per process (the
// answer is cached; thread-safe); huge_pages_worthwhile() reads them on every call.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace delpsc::kernel {

/// The decision, from its inputs: `override_value` is the environment variable DELPSC_HUGE_PAGES
/// ("1" to advise huge pages, "0" not to; absent or anything else decides nothing), and
/// `virtio_devices` a directory laid out as /sys/bus/virtio/devices (one subdirectory per device,
/// each with files "device", e.g. "0x0005" for a balloon, and "features", one '0'/'1' character
/// per feature bit from bit 0). Without an override: false when some balloon device has
/// negotiated free page reporting (bit 5), true otherwise (no such directory included).
bool huge_pages_worthwhile(std::optional<std::string_view> override_value,
                           const std::filesystem::path& virtio_devices);

/// huge_pages_worthwhile(getenv("DELPSC_HUGE_PAGES"), "/sys/bus/virtio/devices"), decided once.
/// Always false off Linux, where the advice does not exist.
bool huge_pages_advised();

}  // namespace delpsc::kernel
