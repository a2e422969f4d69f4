#include "sweep/run_in_child_processes.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace curvebench {
namespace {

using Clock = std::chrono::steady_clock;

// The first byte a child sends says whether `work` returned or threw.
constexpr char kReturned = 'R';
constexpr char kThrew = 'T';

struct RunningChild {
  int task = 0;
  pid_t pid = -1;
  int pipe_read_end = -1;
  std::string received;
  Clock::time_point started;
};

[[noreturn]] void fail_system(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

void write_fully(int fd, const std::string& text) {
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return;  // the parent is gone; nothing left to tell
    written += static_cast<size_t>(n);
  }
}

RunningChild start_child(int task, const std::function<std::string(int)>& work) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) fail_system("pipe");
  std::cout.flush();  // or the child would print the parent's buffered output again
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) fail_system("fork");
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // do not outlive an interrupted sweep
    ::close(ends[0]);
    ::dup2(ends[1], STDOUT_FILENO);  // without O_CLOEXEC: a program exec'd by `work` inherits it
    ::close(ends[1]);
    report_child_result([&] { return work(task); });
    ::_exit(0);  // skip the parent's atexit handlers and static destructors
  }
  ::close(ends[1]);
  return {task, pid, ends[0], {}, Clock::now()};
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Resident memory of a running child in kilobytes, from /proc (0 if it is already gone).
long resident_kilobytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  long size_pages = 0, resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return 0;
  return resident_pages * (::sysconf(_SC_PAGESIZE) / 1024);
}

ChildOutcome reap(RunningChild& child, bool timed_out, long over_memory_limit_kilobytes) {
  if (timed_out || over_memory_limit_kilobytes > 0) ::kill(child.pid, SIGKILL);
  int status = 0;
  rusage usage{};
  while (::wait4(child.pid, &status, 0, &usage) < 0) {
    if (errno != EINTR) fail_system("wait4");
  }
  ::close(child.pipe_read_end);
  ChildOutcome outcome;
  outcome.peak_memory_kilobytes = usage.ru_maxrss;  // kilobytes on Linux
  outcome.wall_seconds = seconds_since(child.started);
  const bool exited_cleanly = WIFEXITED(status) && WEXITSTATUS(status) == 0 && !child.received.empty();
  if (timed_out) {
    outcome.ending = ChildOutcome::Ending::kTimedOut;
  } else if (over_memory_limit_kilobytes > 0) {
    outcome.ending = ChildOutcome::Ending::kCrashed;
    outcome.failure = "killed: resident memory over the limit of " + std::to_string(over_memory_limit_kilobytes / 1024) + " MiB";
  } else if (exited_cleanly && child.received.front() == kReturned) {
    outcome.ending = ChildOutcome::Ending::kFinished;
    outcome.output = child.received.substr(1);
  } else {
    outcome.ending = ChildOutcome::Ending::kCrashed;
    if (exited_cleanly) {
      outcome.failure = "uncaught exception: " + child.received.substr(1);
    } else if (WIFSIGNALED(status)) {
      outcome.failure = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    } else {
      outcome.failure = "exited with status " + std::to_string(WEXITSTATUS(status)) + " without a result";
    }
  }
  return outcome;
}

}  // namespace

void report_child_result(const std::function<std::string()>& work) {
  std::string message;
  try {
    message = kReturned + work();
  } catch (const std::exception& e) {
    message = std::string(1, kThrew) + e.what();
  } catch (...) {
    message = std::string(1, kThrew) + "an exception that is not a std::exception";
  }
  std::cout.flush();  // nothing else may follow on the pipe
  write_fully(STDOUT_FILENO, message);
}

void run_in_child_processes(int task_count, int parallel_jobs, double timeout_seconds, long memory_limit_kilobytes,
                            const std::function<std::string(int task)>& work,
                            const std::function<void(int task, const ChildOutcome& outcome)>& on_finish) {
  if (parallel_jobs < 1) throw std::invalid_argument("at least one job must run at a time");
  std::vector<RunningChild> running;
  int next_task = 0;
  while (next_task < task_count || !running.empty()) {
    while (next_task < task_count && static_cast<int>(running.size()) < parallel_jobs) {
      running.push_back(start_child(next_task++, work));
    }
    int wait_milliseconds = -1;
    if (timeout_seconds > 0) {
      double soonest = timeout_seconds;
      for (const auto& child : running) soonest = std::min(soonest, timeout_seconds - seconds_since(child.started));
      wait_milliseconds = static_cast<int>(std::ceil(std::max(0.0, soonest) * 1000.0));
    }
    if (memory_limit_kilobytes > 0) {
      constexpr int kMemoryCheckMilliseconds = 50;
      wait_milliseconds = wait_milliseconds < 0 ? kMemoryCheckMilliseconds : std::min(wait_milliseconds, kMemoryCheckMilliseconds);
    }
    std::vector<pollfd> watched;
    for (const auto& child : running) watched.push_back({child.pipe_read_end, POLLIN, 0});
    if (::poll(watched.data(), watched.size(), wait_milliseconds) < 0 && errno != EINTR) fail_system("poll");

    std::vector<RunningChild> still_running;
    for (size_t i = 0; i < running.size(); ++i) {
      RunningChild& child = running[i];
      bool finished = false;
      if (watched[i].revents != 0) {
        char buffer[65536];
        const ssize_t n = ::read(child.pipe_read_end, buffer, sizeof buffer);
        if (n > 0) child.received.append(buffer, static_cast<size_t>(n));
        finished = n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN);
      }
      const bool timed_out = !finished && timeout_seconds > 0 && seconds_since(child.started) >= timeout_seconds;
      const bool over_memory = !finished && !timed_out && memory_limit_kilobytes > 0 &&
                               resident_kilobytes(child.pid) > memory_limit_kilobytes;
      if (finished || timed_out || over_memory) {
        on_finish(child.task, reap(child, timed_out, over_memory ? memory_limit_kilobytes : 0));
      } else {
        still_running.push_back(std::move(child));
      }
    }
    running = std::move(still_running);
  }
}

}  // namespace curvebench
