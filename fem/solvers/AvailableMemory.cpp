// Memory still available to the process (see AvailableMemory.hpp), from /proc, getrlimit and
// the cgroup files.
#include "fem/solvers/AvailableMemory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace beamrotor {

namespace {

constexpr std::size_t kUnlimited = std::numeric_limits<std::size_t>::max();

/// A number in a file (cgroup limits and usage); `fallback` when absent or "max".
std::size_t numberIn(const std::string& file, std::size_t fallback) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word == "max") return fallback;
  try {
    return std::size_t(std::stoull(word));
  } catch (const std::exception&) {
    return fallback;
  }
}

/// "MemAvailable:  19142796 kB" from /proc/meminfo, in bytes.
std::size_t systemAvailable() {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string key;
    std::size_t kb = 0;
    if (s >> key >> kb && key == "MemAvailable:") return kb * 1024;
  }
  return kUnlimited;
}

/// What a resource limit leaves beyond `used` bytes.
std::size_t leftUnder(int resource, std::size_t used) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kUnlimited;
  return limit.rlim_cur > used ? std::size_t(limit.rlim_cur) - used : 0;
}

/// Virtual size and data segment (bytes) from /proc/self/statm.
void mappedNow(std::size_t& virtualSize, std::size_t& data) {
  std::ifstream in("/proc/self/statm");
  std::size_t size = 0, resident = 0, shared = 0, text = 0, lib = 0, dataPages = 0;
  in >> size >> resident >> shared >> text >> lib >> dataPages;
  const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  virtualSize = size * page;
  data = dataPages * page;
}

/// The memory cgroup's limit minus its usage (v2, else v1).
std::size_t cgroupLeft() {
  std::ifstream in("/proc/self/cgroup");
  std::size_t left = kUnlimited;
  for (std::string line; std::getline(in, line);) {
    const std::size_t a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    std::string limitFile, usageFile;
    if (controllers.empty()) {  // v2
      limitFile = "/sys/fs/cgroup" + path + "/memory.max";
      usageFile = "/sys/fs/cgroup" + path + "/memory.current";
    } else if (controllers == "memory") {  // v1 (in a container the group is often the root)
      for (const std::string& base :
           {"/sys/fs/cgroup/memory" + path, std::string("/sys/fs/cgroup/memory")}) {
        if (numberIn(base + "/memory.limit_in_bytes", 0) == 0) continue;
        limitFile = base + "/memory.limit_in_bytes";
        usageFile = base + "/memory.usage_in_bytes";
        break;
      }
    }
    if (limitFile.empty()) continue;
    const std::size_t limit = numberIn(limitFile, kUnlimited), usage = numberIn(usageFile, 0);
    if (limit != kUnlimited && limit < (std::size_t(1) << 60))
      left = std::min(left, limit > usage ? limit - usage : 0);
  }
  return left;
}

}  // namespace

std::size_t availableMemoryBytes() {
  std::size_t virtualSize = 0, data = 0;
  mappedNow(virtualSize, data);
  return std::min({systemAvailable(), leftUnder(RLIMIT_AS, virtualSize),
                   leftUnder(RLIMIT_DATA, data), cgroupLeft()});
}

std::string memoryText(double bytes) {
  char text[32];
  if (bytes >= 1e9)
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  else if (bytes >= 1e6)
    std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
  else
    std::snprintf(text, sizeof text, "%.0f kB", bytes / 1e3);
  return text;
}

}  // namespace beamrotor
