#include "problems/cli/HugePages.hpp"

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

namespace beamrotor::cli {

namespace {

constexpr const char* kVariable = "GLIBC_TUNABLES";
constexpr const char* kTunable = "glibc.malloc.hugetlb";
constexpr const char* kBlasThreads = "OPENBLAS_NUM_THREADS";

/// The kernel's setting reads "always [madvise] never" when huge pages come on advice only.
bool hugePagesOnAdvice() {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  return std::getline(setting, line) && line.find("[madvise]") != std::string::npos;
}

}  // namespace

void restartWithHugePages(char** argv) {
  const char* tunables = std::getenv(kVariable);
  if (tunables && std::strstr(tunables, kTunable)) return;  // already set, by us or the user
  if (!hugePagesOnAdvice()) return;
  const std::string kept = tunables ? tunables : "";
  const std::string value = (kept.empty() ? "" : kept + ":") + kTunable + "=1";
  if (setenv(kVariable, value.c_str(), 1) != 0) return;
  // OpenBLAS reads its thread count when it is loaded, and starts that many threads less one,
  // which spin for about 0.1 s before they sleep: CPU taken from the run's own threads and
  // its charts. The run calls it with one thread anyway (fem/solvers/BlasThreads.hpp), so the
  // restarted program asks for one from the start, unless the environment names a count.
  const bool blasThreadsSet = std::getenv(kBlasThreads) != nullptr;
  if (!blasThreadsSet) setenv(kBlasThreads, "1", 0);
  execv("/proc/self/exe", argv);
  // No /proc (a container without it): go on as started.
  if (tunables)
    setenv(kVariable, kept.c_str(), 1);
  else
    unsetenv(kVariable);
  if (!blasThreadsSet) unsetenv(kBlasThreads);
}

}  // namespace beamrotor::cli
