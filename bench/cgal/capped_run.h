// Runs one measurement in a forked child with a wall-clock cap, so a mesher that runs too long
// (or crashes, or aborts on an assertion) costs at most the cap and is reported, not fatal to
// the whole comparison. The child sends back a trivially copyable result through a pipe.
// POSIX only (fork, pipe, poll, waitpid); the parent must not have started threads.
#pragma once

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <type_traits>

namespace delpsc::bench {

enum class RunEnd { kDone, kTimedOut, kFailed };

template <class Result>
struct CappedRun {
  RunEnd end = RunEnd::kFailed;
  Result result{};
};

/// Calls `measure()` (returning a Result) in a child process; gives up after `cap_seconds`.
template <class Result, class Measure>
CappedRun<Result> run_capped(Measure&& measure, double cap_seconds) {
  static_assert(std::is_trivially_copyable_v<Result>);
  CappedRun<Result> run;
  int fds[2];
  if (pipe(fds) != 0) return run;
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t child = fork();
  if (child < 0) return run;
  if (child == 0) {
    close(fds[0]);
    const Result r = measure();
    const char* p = reinterpret_cast<const char*>(&r);
    for (std::size_t left = sizeof r; left > 0;) {
      const ssize_t n = write(fds[1], p, left);
      if (n <= 0) _exit(1);
      p += n, left -= static_cast<std::size_t>(n);
    }
    _exit(0);
  }
  close(fds[1]);
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(cap_seconds);
  char* p = reinterpret_cast<char*>(&run.result);
  std::size_t left = sizeof run.result;
  run.end = RunEnd::kTimedOut;
  while (left > 0) {
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (ms <= 0) break;  // the cap
    pollfd pfd{fds[0], POLLIN, 0};
    const int ready = poll(&pfd, 1, static_cast<int>(ms));
    if (ready < 0) continue;  // a signal: wait again
    if (ready == 0) break;    // the cap
    const ssize_t n = read(fds[0], p, left);
    if (n <= 0) {  // the child died without a result
      run.end = RunEnd::kFailed;
      break;
    }
    p += n, left -= static_cast<std::size_t>(n);
  }
  if (left == 0) run.end = RunEnd::kDone;
  if (run.end == RunEnd::kTimedOut) kill(child, SIGKILL);
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (run.end == RunEnd::kDone && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) run.end = RunEnd::kFailed;
  return run;
}

}  // namespace delpsc::bench
