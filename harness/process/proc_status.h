// Reading the kernel's memory figures from /proc.
//
// proc_status_kib - In: a process id (0: this process) and a field of /proc/<pid>/status
//   ("VmRSS" resident now, "VmHWM" peak resident). Out: its value in KiB; 0 if the process
//   or the field is gone.
// meminfo_kib - In: a field of /proc/meminfo ("MemAvailable"). Out: its value in KiB, 0 if absent.
#pragma once

#include <sys/types.h>

#include <string>

namespace curvebench {

long proc_status_kib(pid_t pid, const std::string& field);
long meminfo_kib(const std::string& field);

}  // namespace curvebench
