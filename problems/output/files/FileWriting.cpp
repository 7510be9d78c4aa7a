// Checked file writes (see FileWriting.hpp).
#include "problems/output/files/FileWriting.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "problems/output/files/Interruption.hpp"

namespace beamrotor {

namespace fs = std::filesystem;

std::string writeFailure(const fs::path& file, int error, const std::string& fallback) {
  return "cannot write " + file.string() + ": " + (error != 0 ? std::strerror(error) : fallback);
}

OutputFile::OutputFile(fs::path file) : file_(std::move(file)) {
  throwIfInterrupted();
  errno = 0;
  out_.open(file_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error(writeFailure(file_, errno, "cannot create it"));
  errno = 0;
}

void OutputFile::finish() {
  // A buffer that filled up was written on the way (its error is the stream's last); the last
  // one reaches the device only here: check after the flush and after the close.
  int error = out_ ? 0 : errno;
  if (out_) {
    out_.flush();
    if (!out_) error = errno;
  }
  const bool written = bool(out_);
  out_.close();
  if (!written || !out_) throw std::runtime_error(writeFailure(file_, error ? error : errno));
}

void writeFile(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  OutputFile out(file);
  write(out.stream());
  out.finish();
}

void writeFileAtomically(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  // A device or pipe (/dev/stdout) is written as it is: renaming onto it would replace it.
  std::error_code ec;
  const fs::file_type type = fs::status(file, ec).type();
  if (type != fs::file_type::not_found && type != fs::file_type::regular) {
    writeFile(file, write);
    return;
  }
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
