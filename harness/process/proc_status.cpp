#include "process/proc_status.h"

#include <fstream>

namespace curvebench {
namespace {

// The number after "<field>:" in a file of "Field:   value kB" lines.
long field_kib(const std::string& path, const std::string& field) {
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
  }
  return 0;
}

}  // namespace

long proc_status_kib(pid_t pid, const std::string& field) {
  return field_kib(pid == 0 ? "/proc/self/status" : "/proc/" + std::to_string(pid) + "/status", field);
}

long meminfo_kib(const std::string& field) { return field_kib("/proc/meminfo", field); }

}  // namespace curvebench
