#include "process/proc_status.h"

#include <filesystem>
#include <fstream>
#include <vector>

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

long process_tree_resident_kib(pid_t pid) {
  long total = 0;
  std::vector<pid_t> pending{pid};
  while (!pending.empty()) {  // a work list, not recursion: the tree may be deep
    const pid_t process = pending.back();
    pending.pop_back();
    total += proc_status_kib(process, "VmRSS");
    try {
      for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(process) + "/task")) {
        std::ifstream children(task.path() / "children");
        for (pid_t child = 0; children >> child;) pending.push_back(child);
      }
    } catch (const std::filesystem::filesystem_error&) {
      // the process ended since it was listed: it has no memory left to count
    }
  }
  return total;
}

long meminfo_kib(const std::string& field) { return field_kib("/proc/meminfo", field); }

}  // namespace curvebench
