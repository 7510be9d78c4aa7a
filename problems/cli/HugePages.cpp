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
  execv("/proc/self/exe", argv);
  // No /proc (a container without it): go on as started.
  if (tunables)
    setenv(kVariable, kept.c_str(), 1);
  else
    unsetenv(kVariable);
}

}  // namespace beamrotor::cli
