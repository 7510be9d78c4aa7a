// Checked file writes (see FileWriting.hpp).
#include "problems/output/FileWriting.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "problems/output/Interruption.hpp"

namespace beamrotor {

namespace fs = std::filesystem;

std::string writeFailure(const fs::path& file, int error, const std::string& fallback) {
  return "cannot write " + file.string() + ": " + (error != 0 ? std::strerror(error) : fallback);
}

void writeFile(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  throwIfInterrupted();
  errno = 0;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(writeFailure(file, errno, "cannot create it"));
  write(out);
  // The last buffer reaches the device only here: check after the flush and after the close.
  errno = 0;
  out.flush();
  const int flushError = out ? 0 : errno;
  const bool flushed = bool(out);
  out.close();
  if (!flushed || !out)
    throw std::runtime_error(writeFailure(file, flushError ? flushError : errno));
}

void writeFileAtomically(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  const fs::path temporary = file.string() + ".tmp-" + std::to_string(::getpid());
  try {
    writeFile(temporary, write);
    std::error_code ec;
    fs::rename(temporary, file, ec);
    if (ec) throw std::runtime_error(writeFailure(file, ec.value()));
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

}  // namespace beamrotor
