// Atomic output directory (see AtomicDirectory.hpp): temporary sibling, guarded replace.
#include "problems/output/AtomicDirectory.hpp"

#include <random>
#include <stdexcept>
#include <string>

#include "problems/output/FileNames.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

/// "out/" and "out" name the same directory; the temporary sibling needs the latter.
fs::path withoutTrailingSeparator(const fs::path& dir) {
  fs::path p = dir.lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  return p;
}

void requireReplaceable(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec))) return;
  if (!fs::is_directory(fs::symlink_status(dir, ec)))
    throw std::runtime_error("cannot write results to '" + dir.string() +
                             "': it exists and is not a directory");
  const bool ours = fs::exists(dir / kResultsJson) || fs::exists(dir / kSweepJson) ||
                    fs::exists(dir / kConvergenceJson);
  if (!ours && !fs::is_empty(dir))
    throw std::runtime_error("refusing to replace '" + dir.string() +
                             "': it is not a beamrotor results directory (no " + kResultsJson +
                             ", " + kSweepJson + " or " + kConvergenceJson +
                             "); choose another output directory");
}

/// DIR.tmp-XXXXXX, created by mkdir (so the finished directory gets the usual umask
/// permissions, which mkdtemp's 0700 would not give); a taken name is simply tried again.
fs::path makeTemporarySibling(const fs::path& dir) {
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device entropy;
  std::uniform_int_distribution<int> pick(0, int(sizeof kLetters) - 2);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string suffix(6, ' ');
    for (char& c : suffix) c = kLetters[pick(entropy)];
    const fs::path candidate = dir.string() + ".tmp-" + suffix;
    if (fs::create_directory(candidate)) return candidate;  // false: the name is taken
  }
  throw std::runtime_error("cannot create a temporary directory next to '" + dir.string() + "'");
}

}  // namespace

void writeDirectoryAtomically(const fs::path& requested,
                              const std::function<void(const fs::path&)>& fill) {
  const fs::path dir = withoutTrailingSeparator(requested);
  const std::string leaf = dir.filename().string();
  if (leaf.empty() || leaf == "." || leaf == "..")
    throw std::invalid_argument("output directory '" + requested.string() +
                                "' must name a directory");
  requireReplaceable(dir);
  if (dir.has_parent_path()) fs::create_directories(dir.parent_path());

  const fs::path temporary = makeTemporarySibling(dir);
  try {
    fill(temporary);
    requireReplaceable(dir);  // it may have appeared while we wrote
    fs::remove_all(dir);
    fs::rename(temporary, dir);
  } catch (...) {
    std::error_code ignored;  // the original exception is the one worth reporting
    fs::remove_all(temporary, ignored);
    throw;
  }
}

}  // namespace beamrotor
