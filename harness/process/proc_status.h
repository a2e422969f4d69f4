// Reading the kernel's memory figures from /proc.
//
// proc_status_kib - In: a process id (0: this process) and a field of /proc/<pid>/status
//   ("VmRSS" resident now, "VmHWM" peak resident). Out: its value in KiB; 0 if the process
//   or the field is gone.
// process_tree_resident_kib - In: a process id. Out: the resident memory (VmRSS, KiB) of it and
//   of all its descendants, found through /proc/<pid>/task/<tid>/children: a run's memory
//   includes the programs it starts (an external algorithm).
// meminfo_kib - In: a field of /proc/meminfo ("MemAvailable"). Out: its value in KiB, 0 if absent.
#pragma once

#include <sys/types.h>

#include <string>

namespace curvebench {

long proc_status_kib(pid_t pid, const std::string& field);
long process_tree_resident_kib(pid_t pid);
long meminfo_kib(const std::string& field);

}  // namespace curvebench
