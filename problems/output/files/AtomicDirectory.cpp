// Atomic output directory (see AtomicDirectory.hpp): temporary sibling with a locked marker,
// guarded exchange, removal of only what the marker lists, sweep of stale temporaries.
#include "problems/output/files/AtomicDirectory.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "problems/output/files/FileWriting.hpp"
#include "problems/output/files/Interruption.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

constexpr const char* kWrittenHeader =
    "# beamrotor results: the next run replaces this directory unless it holds anything not "
    "listed here";
constexpr const char* kInProgressHeader = "# beamrotor: being written";
/// Follows kInProgressHeader on the first line when the writer said what is worth keeping.
constexpr const char* kResumableNote = "; if left unfinished, keep it: ";
constexpr const char* kTemporaryInfix = ".tmp-";
constexpr const char* kAnotherDirectory = "choose another output directory with --out DIR";

/// "out/" and "out" name the same directory; the temporary sibling needs the latter.
fs::path withoutTrailingSeparator(const fs::path& dir) {
  fs::path p = dir.lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  return p;
}

bool isDirectory(const fs::path& p) {
  std::error_code ec;
  return fs::symlink_status(p, ec).type() == fs::file_type::directory;
}

/// Everything under dir, relative, symbolic links not followed: "a.csv", "sub/", "sub/b.vtu".
std::vector<std::string> treeEntries(const fs::path& dir) {
  std::vector<std::string> entries;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator();
       ++it) {
    std::string name = it->path().lexically_relative(dir).generic_string();
    if (it->symlink_status().type() == fs::file_type::directory) name += '/';
    entries.push_back(std::move(name));
  }
  return entries;
}

/// The first line of a marker file (empty when there is none, or it is not a plain file).
std::string markerHeader(const fs::path& dir, std::vector<std::string>* listed = nullptr) {
  std::error_code ec;
  const fs::path marker = dir / kMarkerFile;
  if (fs::symlink_status(marker, ec).type() != fs::file_type::regular) return {};
  std::ifstream in(marker);
  std::string header;
  std::getline(in, header);
  if (listed)
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) listed->push_back(line);
  return header;
}

/// What a marker lists when beamrotor finished writing the directory; nullopt otherwise.
std::optional<std::set<std::string>> writtenFiles(const fs::path& dir) {
  std::vector<std::string> listed;
  if (markerHeader(dir, &listed) != kWrittenHeader) return std::nullopt;
  return std::set<std::string>(listed.begin(), listed.end());
}

void requireReplaceable(const fs::path& dir) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(dir, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status))
    throw std::runtime_error("cannot write results to '" + dir.string() +
                             "': it exists and is not a directory; " + kAnotherDirectory);
  const std::vector<std::string> entries = treeEntries(dir);
  if (entries.empty()) return;
  const auto listed = writtenFiles(dir);
  if (!listed)
    throw std::runtime_error("refusing to replace '" + dir.string() +
                             "': beamrotor did not write it (it has no " + kMarkerFile +
                             " marker listing its files); " + kAnotherDirectory +
                             ", or move it away yourself");
  for (const std::string& e : entries)
    if (e != kMarkerFile && !listed->count(e))
      throw std::runtime_error("refusing to replace '" + dir.string() + "': it holds '" + e +
                               "', which beamrotor did not write; move that out of it or " +
                               kAnotherDirectory);
}

/// Removes from dir what its marker lists (files before the directories holding them), then
/// the marker and dir itself when nothing else is left; says so when something is.
void removeWritten(const fs::path& dir) {
  std::vector<std::string> doomed;
  if (const auto listed = writtenFiles(dir))
    for (const std::string& e : treeEntries(dir))
      if (listed->count(e)) doomed.push_back(e);
  std::sort(doomed.rbegin(), doomed.rend());  // "sub/b" before "sub/"
  std::error_code ec;
  for (std::string e : doomed) {
    if (!e.empty() && e.back() == '/') e.pop_back();
    fs::remove(dir / e, ec);
  }
  fs::remove(dir / kMarkerFile, ec);
  fs::remove(dir, ec);
  if (fs::exists(fs::symlink_status(dir, ec)))
    std::cerr << "beamrotor: warning: kept '" << dir.string()
              << "': it holds files beamrotor did not write\n";
}

/// The marker of a temporary directory, locked while its writer lives.
class LockedMarker {
 public:
  LockedMarker(const fs::path& dir, const std::string& resumable) : file_(dir / kMarkerFile) {
    fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0 || ::flock(fd_, LOCK_EX | LOCK_NB) != 0)
      throw std::runtime_error(writeFailure(file_, errno));
    std::string header = kInProgressHeader;
    if (!resumable.empty()) {
      header += kResumableNote;
      header += resumable;
    }
    replace(header + "\n");
  }
  ~LockedMarker() {
    if (fd_ >= 0) ::close(fd_);
  }
  LockedMarker(const LockedMarker&) = delete;
  LockedMarker& operator=(const LockedMarker&) = delete;

  /// The marker's whole content.
  void replace(const std::string& text) {
    if (::ftruncate(fd_, 0) != 0) throw std::runtime_error(writeFailure(file_, errno));
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::pwrite(fd_, text.data() + done, text.size() - done, off_t(done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) throw std::runtime_error(writeFailure(file_, n < 0 ? errno : 0));
      done += std::size_t(n);
    }
  }

 private:
  fs::path file_;
  int fd_ = -1;
};

bool startsWith(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

/// Temporary directories of earlier runs writing `dir` that no process is writing any more
/// (their marker's lock is free): killed before they could clean up, or kept because the
/// swap was interrupted. A finished one loses what it lists; an unfinished one, which only its
/// run wrote into, is removed whole, unless its writer said it holds work worth resuming:
/// that one is kept and named on stderr with what its writer said.
void sweepStaleTemporaries(const fs::path& dir) {
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  const std::string prefix = dir.filename().string() + kTemporaryInfix;
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !isDirectory(entry.path())) continue;
    const int fd = ::open((entry.path() / kMarkerFile).c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
    if (fd < 0) continue;
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) stale.push_back(entry.path());
    ::close(fd);
  }
  const std::string resumable = std::string(kInProgressHeader) + kResumableNote;
  for (const fs::path& p : stale) {
    const std::string header = markerHeader(p);
    if (startsWith(header, resumable))
      std::cerr << "beamrotor: warning: kept '" << p.string()
                << "', left unfinished by an earlier run that was killed: it holds "
                << header.substr(resumable.size()) << "\n";
    else if (header == kInProgressHeader)
      fs::remove_all(p, ec);
    else
      removeWritten(p);
  }
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
    const fs::path candidate = dir.string() + kTemporaryInfix + suffix;
    if (fs::create_directory(candidate)) return candidate;  // false: the name is taken
  }
  throw std::runtime_error("cannot create a temporary directory next to '" + dir.string() + "'");
}

bool unsupported(int error) {
  return error == EINVAL || error == ENOSYS || error == ENOTSUP;
}

std::runtime_error swapFailure(const fs::path& dir, int error) {
  return std::runtime_error("cannot put the new results in place of '" + dir.string() +
                            "': " + std::strerror(error));
}

/// Puts `temporary` in `dir`'s place; returns where the earlier `dir` now is (empty when
/// there was none). One renameat2(RENAME_EXCHANGE) where the filesystem has it; elsewhere
/// the earlier directory is first renamed aside (a reader may then briefly find none).
fs::path swapIn(const fs::path& temporary, const fs::path& dir) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (!fs::exists(fs::symlink_status(dir))) {
      if (::renameat2(AT_FDCWD, temporary.c_str(), AT_FDCWD, dir.c_str(), RENAME_NOREPLACE) == 0)
        return {};
      if (errno == EEXIST) continue;  // it appeared meanwhile: check it and exchange
      if (!unsupported(errno)) throw swapFailure(dir, errno);
      if (::rename(temporary.c_str(), dir.c_str()) != 0) throw swapFailure(dir, errno);
      return {};
    }
    requireReplaceable(dir);  // it may have changed while we wrote
    if (::renameat2(AT_FDCWD, temporary.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0)
      return temporary;
    if (!unsupported(errno)) throw swapFailure(dir, errno);
    const fs::path aside = temporary.string() + "-old";
    if (::rename(dir.c_str(), aside.c_str()) != 0) throw swapFailure(dir, errno);
    if (::rename(temporary.c_str(), dir.c_str()) != 0) {
      const int error = errno;
      ::rename(aside.c_str(), dir.c_str());
      throw swapFailure(dir, error);
    }
    return aside;
  }
  throw std::runtime_error("cannot put the new results in place of '" + dir.string() +
                           "': another process keeps creating it");
}

std::string manifest(const fs::path& temporary) {
  std::string text = std::string(kWrittenHeader) + "\n";
  std::vector<std::string> entries = treeEntries(temporary);
  std::sort(entries.begin(), entries.end());
  for (const std::string& e : entries)
    if (e != kMarkerFile) text += e + "\n";
  return text;
}

}  // namespace

void writeDirectoryAtomically(const fs::path& requested,
                              const std::function<void(const fs::path&)>& fill,
                              const std::string& resumable) {
  const fs::path dir = withoutTrailingSeparator(requested);
  const std::string leaf = dir.filename().string();
  if (leaf.empty() || leaf == "." || leaf == "..")
    throw std::invalid_argument("output directory '" + requested.string() +
                                "' must name a directory");
  requireReplaceable(dir);
  if (dir.has_parent_path()) fs::create_directories(dir.parent_path());
  sweepStaleTemporaries(dir);

  const DeferredSignals deferred;
  const fs::path temporary = makeTemporarySibling(dir);
  fs::path earlier;
  try {
    LockedMarker marker(temporary, resumable);
    fill(temporary);
    // A resumable fill stops early by itself when signalled and keeps what it wrote.
    if (resumable.empty()) throwIfInterrupted();
    marker.replace(manifest(temporary));
    earlier = swapIn(temporary, dir);
  } catch (...) {
    std::error_code ignored;  // the original exception is the one worth reporting
    fs::remove_all(temporary, ignored);
    throw;
  }
  if (!earlier.empty()) removeWritten(earlier);
}

bool isUnfinishedDirectory(const fs::path& dir) {
  return startsWith(markerHeader(dir), kInProgressHeader);
}

UnfinishedDirectory::UnfinishedDirectory(const fs::path& dir) : dir_(withoutTrailingSeparator(dir)) {
  if (!isDirectory(dir_) || !isUnfinishedDirectory(dir_) ||
      dir_.filename().string().find(kTemporaryInfix) == std::string::npos)
    throw std::runtime_error("'" + dir.string() +
                             "' is not a directory a beamrotor run left unfinished");
  const fs::path marker = dir_ / kMarkerFile;
  fd_ = ::open(marker.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (fd_ < 0) throw std::runtime_error("cannot open " + marker.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("'" + dir.string() + "' is being written by a beamrotor run "
                             "that is still going");
  }
}

UnfinishedDirectory::~UnfinishedDirectory() {
  if (fd_ >= 0) ::close(fd_);
}

fs::path UnfinishedDirectory::destination() const {
  const std::string name = dir_.string();
  return name.substr(0, name.rfind(kTemporaryInfix));
}

void UnfinishedDirectory::remove() {
  std::error_code ignored;
  fs::remove_all(dir_, ignored);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

}  // namespace beamrotor
