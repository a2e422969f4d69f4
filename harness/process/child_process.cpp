#include "process/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <system_error>

#include "process/proc_status.h"

namespace curvebench {
namespace {

using Clock = std::chrono::steady_clock;

// How often a child's resident memory is checked against the limit.
constexpr int kMemoryCheckMilliseconds = 50;

[[noreturn]] void fail_system(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double seconds_of(const timeval& time) { return static_cast<double>(time.tv_sec) + 1e-6 * static_cast<double>(time.tv_usec); }

}  // namespace

ChildProcess start_child(const std::function<void()>& body) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) fail_system("pipe");
  std::cout.flush();  // or the child would print the parent's buffered output again
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) fail_system("fork");
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // do not outlive an interrupted parent
    ::close(ends[0]);
    ::dup2(ends[1], STDOUT_FILENO);  // without O_CLOEXEC: a program exec'd by `body` inherits it
    ::close(ends[1]);
    body();
    std::cout.flush();
    ::_exit(0);  // skip the parent's atexit handlers and static destructors
  }
  ::close(ends[1]);
  ChildProcess child;
  child.pid = pid;
  child.output_fd = ends[0];
  child.started = Clock::now();
  return child;
}

void exec_this_executable(const std::vector<std::string>& arguments) {
  std::vector<std::string> text{"curvebench"};
  text.insert(text.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  ::execv("/proc/self/exe", argv.data());
}

ChildProcess start_this_executable(const std::vector<std::string>& arguments, bool stderr_too) {
  return start_child([&] {
    if (stderr_too) ::dup2(STDOUT_FILENO, STDERR_FILENO);
    exec_this_executable(arguments);
    ::_exit(127);
  });
}

ChildState watch_child(ChildProcess& child, bool readable, const ChildLimits& limits) {
  if (readable) {
    char buffer[65536];
    const ssize_t n = ::read(child.output_fd, buffer, sizeof buffer);
    if (n > 0) child.output.append(buffer, static_cast<size_t>(n));
    if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) return ChildState::kOutputEnded;
  }
  if (limits.timeout_seconds > 0 && seconds_since(child.started) >= limits.timeout_seconds) return ChildState::kTimedOut;
  if (limits.memory_limit_kilobytes > 0 && process_tree_resident_kib(child.pid) > limits.memory_limit_kilobytes) {
    return ChildState::kOverMemory;
  }
  return ChildState::kRunning;
}

int next_check_milliseconds(std::span<const ChildProcess> running, const ChildLimits& limits) {
  int wait_milliseconds = -1;
  if (limits.timeout_seconds > 0) {
    double soonest = limits.timeout_seconds;
    for (const auto& child : running) soonest = std::min(soonest, limits.timeout_seconds - seconds_since(child.started));
    wait_milliseconds = static_cast<int>(std::ceil(std::max(0.0, soonest) * 1000.0));
  }
  if (limits.memory_limit_kilobytes > 0) {
    wait_milliseconds = wait_milliseconds < 0 ? kMemoryCheckMilliseconds : std::min(wait_milliseconds, kMemoryCheckMilliseconds);
  }
  return wait_milliseconds;
}

ChildExit finish_child(ChildProcess& child, ChildState state) {
  if (state == ChildState::kTimedOut || state == ChildState::kOverMemory) ::kill(child.pid, SIGKILL);
  ChildExit end;
  rusage usage{};
  while (::wait4(child.pid, &end.wait_status, 0, &usage) < 0) {
    if (errno != EINTR) fail_system("wait4");
  }
  ::close(child.output_fd);
  end.state = state;
  end.output = std::move(child.output);
  end.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
  end.peak_memory_kilobytes = usage.ru_maxrss;  // kilobytes on Linux
  end.wall_seconds = seconds_since(child.started);
  return end;
}

ChildExit run_child(ChildProcess child, const ChildLimits& limits) {
  for (;;) {
    pollfd watched{child.output_fd, POLLIN, 0};
    if (::poll(&watched, 1, next_check_milliseconds({&child, 1}, limits)) < 0 && errno != EINTR) fail_system("poll");
    const ChildState state = watch_child(child, watched.revents != 0, limits);
    if (state != ChildState::kRunning) return finish_child(child, state);
  }
}

}  // namespace curvebench
