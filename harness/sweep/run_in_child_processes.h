// Running tasks in isolated child processes, a few at a time, so that a task that crashes,
// hangs or exhausts memory takes only itself down.
//
// In:  the number of tasks, how many may run at once, a time limit per task (seconds; 0 for
//      none), a resident-memory limit per task (kilobytes; 0 for none; checked every 50 ms,
//      the child is killed and reported crashed when over it), `work` (run in a forked child;
//      returns the text to send back) and `on_finish` (run in the parent, in completion
//      order, once per task).
// Out: for every task, through `on_finish`, how it ended: finished (`work` returned; its text
//      is in `output`), crashed (killed by a signal, or exited without returning, e.g. an
//      uncaught exception; `failure` says which), or timed out (killed after the limit), with
//      the peak resident memory of its child process from getrusage.
//
// Children are started, watched and reaped by process/child_process.h: forked from the
// calling process, which must be single-threaded, and killed if it dies. They start as a
// copy of it, so their peak memory includes the caller's resident memory at the fork. A
// child reports on its standard output, which is a pipe to the caller; `work` may also
// replace the child's process image (exec) with a program that reports there itself,
// through report_child_result.
#pragma once

#include <functional>
#include <string>

namespace curvebench {

struct ChildOutcome {
  enum class Ending { kFinished, kCrashed, kTimedOut };
  Ending ending = Ending::kFinished;
  std::string output;            // what `work` returned (only when finished)
  std::string failure;           // for a crash: the signal or exit status
  long peak_memory_kilobytes = 0;
  double wall_seconds = 0.0;
};

// Runs `work` and reports its text, or the exception it threw, on standard output in the
// form run_in_child_processes reads: what a child does with `work`, and what a program
// started in a child's place does with its own work.
void report_child_result(const std::function<std::string()>& work);

void run_in_child_processes(int task_count, int parallel_jobs, double timeout_seconds, long memory_limit_kilobytes,
                            const std::function<std::string(int task)>& work,
                            const std::function<void(int task, const ChildOutcome& outcome)>& on_finish);

}  // namespace curvebench
