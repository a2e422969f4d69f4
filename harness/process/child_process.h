// One way to run a child process: forked to run a function, or this executable started
// again with arguments; its standard output is a pipe to the parent; a time limit and a
// resident-memory limit (polled from /proc, the child and its descendants together) are enforced by killing it; on exit, its
// getrusage (CPU time, peak resident memory).
//
// start_child - In: `body`, run in a forked copy of the caller (which must be single-threaded)
//   with standard output on the pipe; the child exits with status 0 when body returns
//   (skipping the parent's atexit handlers). Body may exec. Out: the running child.
// start_this_executable - In: arguments after argv[0]; `stderr_too` sends the child's standard
//   error down the pipe as well. Out: the running child (exit status 127 if exec failed).
// Both: the child is killed if the parent dies.
// exec_this_executable - replaces this process with this executable run with `arguments`
//   (after argv[0]); returns only if that fails.
// watch_child - In: a running child, whether poll() found its pipe readable, the limits.
//   Reads what is there and checks the limits. Out: whether it still runs, its output ended
//   (it closed the pipe, normally by exiting), or it is over a limit.
// next_check_milliseconds - In: running children and the limits. Out: how long a poll() may
//   wait before a limit needs checking (-1: no limit).
// finish_child - In: a child that watch_child no longer reports running. Kills it if it is
//   over a limit, waits for it and closes the pipe. Out: how it ended, with its rusage.
// run_child - start to finish of one child: watch_child and finish_child until it ends.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace curvebench {

struct ChildLimits {
  double timeout_seconds = 0;       // 0: none
  long memory_limit_kilobytes = 0;  // resident memory; 0: none
};

struct ChildProcess {
  pid_t pid = -1;
  int output_fd = -1;  // read end of the pipe
  std::string output;  // received so far
  std::chrono::steady_clock::time_point started;
};

enum class ChildState { kRunning, kOutputEnded, kTimedOut, kOverMemory };

struct ChildExit {
  ChildState state = ChildState::kOutputEnded;  // kTimedOut or kOverMemory if it was killed for it
  int wait_status = 0;                          // as waitpid gives it
  std::string output;
  double cpu_seconds = 0;          // user + system
  long peak_memory_kilobytes = 0;  // ru_maxrss
  double wall_seconds = 0;
};

ChildProcess start_child(const std::function<void()>& body);
ChildProcess start_this_executable(const std::vector<std::string>& arguments, bool stderr_too = false);
void exec_this_executable(const std::vector<std::string>& arguments);
ChildState watch_child(ChildProcess& child, bool readable, const ChildLimits& limits);
int next_check_milliseconds(std::span<const ChildProcess> running, const ChildLimits& limits);
ChildExit finish_child(ChildProcess& child, ChildState state);
ChildExit run_child(ChildProcess child, const ChildLimits& limits);

}  // namespace curvebench
