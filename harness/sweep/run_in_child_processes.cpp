#include "sweep/run_in_child_processes.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "process/child_process.h"

namespace curvebench {
namespace {

// The first byte a child sends says whether `work` returned or threw.
constexpr char kReturned = 'R';
constexpr char kThrew = 'T';

void write_fully(int fd, const std::string& text) {
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return;  // the parent is gone; nothing left to tell
    written += static_cast<size_t>(n);
  }
}

ChildOutcome outcome_of(const ChildExit& end, long memory_limit_kilobytes) {
  ChildOutcome outcome;
  outcome.peak_memory_kilobytes = end.peak_memory_kilobytes;
  outcome.wall_seconds = end.wall_seconds;
  const int status = end.wait_status;
  const bool exited_cleanly = WIFEXITED(status) && WEXITSTATUS(status) == 0 && !end.output.empty();
  if (end.state == ChildState::kTimedOut) {
    outcome.ending = ChildOutcome::Ending::kTimedOut;
  } else if (end.state == ChildState::kOverMemory) {
    outcome.ending = ChildOutcome::Ending::kCrashed;
    outcome.failure = "killed: resident memory over the limit of " + std::to_string(memory_limit_kilobytes / 1024) + " MiB";
  } else if (exited_cleanly && end.output.front() == kReturned) {
    outcome.ending = ChildOutcome::Ending::kFinished;
    outcome.output = end.output.substr(1);
  } else {
    outcome.ending = ChildOutcome::Ending::kCrashed;
    if (exited_cleanly) {
      outcome.failure = "uncaught exception: " + end.output.substr(1);
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
  const ChildLimits limits{timeout_seconds, memory_limit_kilobytes};
  std::vector<ChildProcess> running;
  std::vector<int> running_tasks;  // the task of each running child
  int next_task = 0;
  while (next_task < task_count || !running.empty()) {
    while (next_task < task_count && static_cast<int>(running.size()) < parallel_jobs) {
      const int task = next_task++;
      running.push_back(start_child([&] { report_child_result([&] { return work(task); }); }));
      running_tasks.push_back(task);
    }
    std::vector<pollfd> watched;
    for (const auto& child : running) watched.push_back({child.output_fd, POLLIN, 0});
    if (::poll(watched.data(), watched.size(), next_check_milliseconds(running, limits)) < 0 && errno != EINTR) {
      throw std::system_error(errno, std::generic_category(), "poll");
    }
    std::vector<ChildProcess> still_running;
    std::vector<int> still_running_tasks;
    for (size_t i = 0; i < running.size(); ++i) {
      const ChildState state = watch_child(running[i], watched[i].revents != 0, limits);
      if (state == ChildState::kRunning) {
        still_running.push_back(std::move(running[i]));
        still_running_tasks.push_back(running_tasks[i]);
      } else {
        on_finish(running_tasks[i], outcome_of(finish_child(running[i], state), memory_limit_kilobytes));
      }
    }
    running = std::move(still_running);
    running_tasks = std::move(still_running_tasks);
  }
}

}  // namespace curvebench
