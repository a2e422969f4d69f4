// The child-process module: output through the pipe, exit status, death by a signal, the
// time limit, the memory limit, rusage, this executable started again, and the /proc reader.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "process/child_process.h"
#include "process/proc_status.h"

namespace curvebench {
namespace {

TEST(ChildProcess, OutputAndExitStatus) {
  const ChildExit end = run_child(start_child([] {
                                    std::printf("hello");
                                    std::fflush(stdout);
                                    ::_exit(3);
                                  }),
                                  {});
  EXPECT_EQ(end.state, ChildState::kOutputEnded);
  EXPECT_EQ(end.output, "hello");
  ASSERT_TRUE(WIFEXITED(end.wait_status));
  EXPECT_EQ(WEXITSTATUS(end.wait_status), 3);
  EXPECT_GT(end.peak_memory_kilobytes, 0);
}

TEST(ChildProcess, CrashBySignal) {
  const ChildExit end = run_child(start_child([] { std::abort(); }), {});
  ASSERT_TRUE(WIFSIGNALED(end.wait_status));
  EXPECT_EQ(WTERMSIG(end.wait_status), SIGABRT);
}

TEST(ChildProcess, KilledAtTheTimeout) {
  const ChildExit end = run_child(start_child([] {
                                    for (;;) ::pause();
                                  }),
                                  {0.2, 0});
  EXPECT_EQ(end.state, ChildState::kTimedOut);
  ASSERT_TRUE(WIFSIGNALED(end.wait_status));
  EXPECT_EQ(WTERMSIG(end.wait_status), SIGKILL);
  EXPECT_GE(end.wall_seconds, 0.2);
}

TEST(ChildProcess, KilledOverTheMemoryLimit) {
  const long limit_kilobytes = proc_status_kib(0, "VmRSS") + 64 * 1024;
  const ChildExit end = run_child(start_child([] {
                                    std::vector<std::vector<char>> blocks;
                                    for (;;) blocks.emplace_back(std::size_t{16} << 20, 'x');
                                  }),
                                  {0, limit_kilobytes});
  EXPECT_EQ(end.state, ChildState::kOverMemory);
  EXPECT_TRUE(WIFSIGNALED(end.wait_status));
  EXPECT_GT(end.peak_memory_kilobytes, limit_kilobytes);
}

TEST(ChildProcess, CpuTimeOfABusyChild) {
  const ChildExit end = run_child(start_child([] {
                                    volatile double sum = 0;
                                    for (long i = 0; i < 50'000'000; ++i) sum = sum + 1e-9 * static_cast<double>(i);
                                  }),
                                  {});
  EXPECT_TRUE(WIFEXITED(end.wait_status) && WEXITSTATUS(end.wait_status) == 0);
  EXPECT_GT(end.cpu_seconds, 0.0);
}

TEST(ChildProcess, ThisExecutableStartedAgain) {
  const ChildExit end = run_child(start_this_executable({"--gtest_list_tests", "--gtest_filter=ChildProcess.*"}), {10, 0});
  EXPECT_EQ(end.state, ChildState::kOutputEnded);
  EXPECT_EQ(end.wait_status, 0);
  EXPECT_NE(end.output.find("ThisExecutableStartedAgain"), std::string::npos);
}

TEST(ProcStatus, ReadsThisProcessAndTheMachine) {
  // Resident memory first: the high-water mark read after it can only be as large or larger,
  // whereas memory may grow between the two reads.
  const long resident = proc_status_kib(0, "VmRSS");
  EXPECT_GT(resident, 0);
  EXPECT_GE(proc_status_kib(0, "VmHWM"), resident);
  EXPECT_GT(proc_status_kib(::getpid(), "VmHWM"), 0);
  EXPECT_EQ(proc_status_kib(0, "NoSuchField"), 0);
  EXPECT_GT(meminfo_kib("MemAvailable"), 0);
}

}  // namespace
}  // namespace curvebench
