// Every file beamrotor writes goes through here, so that no failed write goes unnoticed: the
// stream is flushed and closed and its state checked, and a failure (a full device, an I/O
// error, a read-only directory) becomes an exception naming the file and the system's reason.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace beamrotor {

/// A file being written: created (or truncated) when made, written through stream(), closed
/// and checked by finish(). Throws std::runtime_error "cannot write FILE: REASON" when it
/// cannot be created (made) or any byte was not written (finish), and Interrupted
/// (Interruption.hpp) when a deferred signal arrived before it was made. One dropped
/// unfinished (an exception on the way) is closed unchecked.
class OutputFile {
 public:
  explicit OutputFile(std::filesystem::path file);
  std::ostream& stream() { return out_; }
  void finish();

 private:
  std::filesystem::path file_;
  std::ofstream out_;
};

/// Writes `file` with `write` through an OutputFile (the same errors).
void writeFile(const std::filesystem::path& file, const std::function<void(std::ostream&)>& write);

/// writeFile into a temporary sibling that then replaces `file` in one rename: a reader sees
/// the old content or the new one, and a failure leaves the old file as it was. A `file` that
/// exists and is not a regular file (/dev/stdout, a pipe) is written directly.
void writeFileAtomically(const std::filesystem::path& file,
                         const std::function<void(std::ostream&)>& write);

/// "cannot write FILE: REASON" with errno's text (or `fallback` when errno says nothing).
std::string writeFailure(const std::filesystem::path& file, int error,
                         const std::string& fallback = "write error");

}  // namespace beamrotor
