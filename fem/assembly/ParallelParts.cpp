#include "fem/assembly/ParallelParts.hpp"

#include <sched.h>

#include <algorithm>
#include <cstdlib>

namespace beamrotor {

namespace {

constexpr std::size_t kItemsPerPart = 50000;

}  // namespace

int usableCores() {
  if (const char* text = std::getenv("BEAMROTOR_THREADS")) {
    char* end = nullptr;
    const long wanted = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && wanted > 0) return int(std::min(wanted, 1024L));
  }
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

int partsFor(std::size_t items) {
  return int(std::clamp<std::size_t>(items / kItemsPerPart, 1, std::size_t(usableCores())));
}

std::vector<int> evenRanges(int n, int parts) {
  std::vector<int> bounds(parts + 1);
  for (int p = 0; p <= parts; ++p) bounds[p] = int((long long)(n) * p / parts);
  return bounds;
}

}  // namespace beamrotor
