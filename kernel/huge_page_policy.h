// Whether the large arrays (large_array.h) should ask Linux for transparent huge pages.
//
// Why a policy and not always: the first touch of fresh memory is a page fault, and which page
// size makes it cheaper depends on where the process runs. On bare metal and on ordinary virtual
// machines a 2 MiB huge page costs one fault and one clear instead of 512 faults, and fewer TLB
// misses after (the cube at 0.456%: -40% CPU time, BENCHMARKS.md "Session 18"). On a virtual
// machine whose balloon device reports free memory to the host (virtio-balloon's free page
// reporting, feature bit 5), first touching a fresh huge page cut from memory already reported
// to the host cost 2.0-3.3 ms a MiB against 0.4 ms a MiB for base pages (1.6 us a fault),
// measured in fresh processes on our CI machines (huge pages were cheap there only while the
// memory freed by the previous process had not been reported yet, about 2 s); a mesher run at
// 0.5% touches 30-100 MiB (BENCHMARKS.md, "Session 29"). Why the host makes it so slow we did not
// find out.
//
// But the balloon alone does not decide it: on the machines of session 35 (a paravirtualised
// guest, "PVM", that also reports free pages) every base-page fault costs 9-14 us (2.7-3.5 ms a
// MiB, warm or cold), a fresh huge page ~2 ms a MiB when cold and 0.06 ms when warm: huge pages
// win there whatever the host did before, and runs at 2% took 26-39% less CPU time with them
// (BENCHMARKS.md, "Session 35"). So each process times a few base-page faults once and advises
// huge pages when one costs more than kDearBasePageFault, balloon or not.
//
// Cost: huge_pages_advised() reads the environment, times 6 base-page faults (with the mapping,
// ~0.05 ms on the first kind of machine, ~0.2 ms on the second) and, unless they were dear,
// reads a few sysfs files, once per process; the answer is cached (thread-safe).
// huge_pages_worthwhile() asks its fault cost and reads the files on every call.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string_view>

namespace delpsc::kernel {

/// A base-page fault dearer than this (microseconds) makes huge pages worthwhile even where the
/// balloon reports free pages: between session 29's machines (1.6 us) and session 35's (9-14 us),
/// below the 8-13 us a 4 KiB share of a cold huge page cost on either.
inline constexpr double kDearBasePageFault = 4.0;

/// The decision, from its inputs: `override_value` is the environment variable DELPSC_HUGE_PAGES
/// ("1" to advise huge pages, "0" not to; absent or anything else decides nothing), and
/// `virtio_devices` a directory laid out as /sys/bus/virtio/devices (one subdirectory per device,
/// each with files "device", e.g. "0x0005" for a balloon, and "features", one '0'/'1' character
/// per feature bit from bit 0). Without an override: true when `base_page_fault_us()` (called
/// first, and only then) exceeds kDearBasePageFault, else when no balloon device has negotiated
/// free page reporting (bit 5; no such directory included).
bool huge_pages_worthwhile(std::optional<std::string_view> override_value,
                           const std::filesystem::path& virtio_devices,
                           const std::function<double()>& base_page_fault_us);

/// What the first touch of a fresh 4 KiB page costs this process, in microseconds: the least mean
/// of three batches of two pages of a fresh mapping advised against huge pages (the least, so
/// that a preemption in one batch does not count). Measured on the first call, then cached;
/// thread-safe. 0 off Linux.
double base_page_fault_microseconds();

/// huge_pages_worthwhile(getenv("DELPSC_HUGE_PAGES"), "/sys/bus/virtio/devices",
/// base_page_fault_microseconds), decided once.
/// Always false off Linux, where the advice does not exist.
bool huge_pages_advised();

}  // namespace delpsc::kernel
