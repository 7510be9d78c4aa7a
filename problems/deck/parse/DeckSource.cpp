#include "problems/deck/parse/DeckSource.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/PlainText.hpp"

namespace beamrotor {

namespace {

/// Where a byte offset lies, 1-based.
DeckPlace placeAt(const std::string& text, std::size_t offset) {
  DeckPlace p{1, 1, ""};
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

/// Rejects bytes no hand-written YAML deck contains: NUL, other control characters, and
/// invalid UTF-8 (the usual signs of a binary file given by mistake).
void requireText(const std::string& text, const std::string& path) {
  const std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // byte-order mark
  const auto bad = firstNonPlain(std::string_view(text).substr(start), "\n\r\t");
  if (!bad) return;
  const std::size_t at = start + *bad;
  throw DeckError(path, placeAt(text, at),
                  "not a text deck: " + describeNonPlain(text, at) +
                      " is not printable UTF-8 text (is this a binary file?)");
}

/// YAML forbids tabs in indentation and yaml-cpp's message does not say so: add a hint when
/// the line of the error, or the one before it, is indented with a tab.
std::string tabHint(const std::string& text, const YAML::Mark& mark) {
  if (mark.is_null()) return {};
  int line = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == '\n') {
      const bool near = line == mark.line || line + 1 == mark.line;
      const std::size_t indentEnd = text.find_first_not_of(" \t", start);
      const std::size_t tab = text.find('\t', start);
      if (near && tab != std::string::npos && tab < std::min(i, indentEnd))
        return " (line " + std::to_string(line + 1) +
               " is indented with a tab; YAML allows only spaces)";
      if (line > mark.line) break;
      ++line;
      start = i + 1;
    }
  }
  return {};
}

/// Remembers where a document's first node starts.
class FirstNode : public YAML::EventHandler {
 public:
  std::optional<YAML::Mark> mark;
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { note(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { note(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                const std::string&) override {
    note(m);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    note(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    note(m);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& m) {
    if (!mark) mark = m;
  }
};

/// Rejects a file holding more than the one YAML document YAML::Load reads. yaml-cpp's
/// LoadAll is not used: on a token its parser never consumes (a stray ',' at the top) it
/// returns the same empty document forever. Here at most two documents are parsed, and a
/// second one starting where the first did is that stuck token.
void requireOneDocument(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  std::vector<std::optional<YAML::Mark>> starts;
  try {
    for (int i = 0; i < 2; ++i) {
      FirstNode first;
      if (!parser.HandleNextDocument(first)) break;
      starts.push_back(first.mark);
    }
  } catch (const YAML::Exception& e) {
    throw DeckError(path, placeOf(e.mark), "YAML syntax error: " + e.msg);
  }
  if (starts.size() < 2) return;
  const std::optional<YAML::Mark>& a = starts[0];
  const std::optional<YAML::Mark>& b = starts[1];
  if (a && b && a->pos == b->pos) {
    const char c = b->pos >= 0 && b->pos < int(text.size()) ? text[b->pos] : '?';
    throw DeckError(
        path, placeOf(*b),
        std::string("YAML syntax error: unexpected '") + c + "' outside a [list] or {map}");
  }
  throw DeckError(path, b ? placeOf(*b) : DeckPlace{},
                  "the file holds more than one YAML document (separated by '---'); a deck is "
                  "one document");
}

std::string stemOf(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  return stem.empty() ? "deck" : stem;
}

}  // namespace

DeckSource parseDeckText(const std::string& text, const std::string& path) {
  // 1. Plain text of a sensible size.
  if (text.size() > kLargestDeck)
    throw DeckError(path, {},
                    "the file is " + std::to_string(text.size()) +
                        " bytes; a deck may have at most " + std::to_string(kLargestDeck));
  requireText(text, path);

  // 2. YAML syntax: exactly one document.
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw DeckError(path, placeOf(e.mark),
                    "YAML nesting deeper than " + std::to_string(e.depth()) + " levels");
  } catch (const YAML::Exception& e) {
    throw DeckError(path, placeOf(e.mark), "YAML syntax error: " + e.msg + tabHint(text, e.mark));
  }
  requireOneDocument(text, path);

  // 3. A map at the top.
  if (!root.IsDefined() || root.IsNull())
    throw DeckError(path, {1, 1, ""},
                    "the deck is empty: expected a map with model, materials, sections, "
                    "segments, supports, analyses, ...");
  if (!root.IsMap())
    throw DeckError(path, placeOf(root.Mark()),
                    "expected a map at the top level (model:, segments:, ...), got " +
                        std::string(root.IsSequence() ? "a list" : "a single value"));
  return DeckSource{path, stemOf(path), DeckTree::fromYaml(root, path)};
}

DeckSource loadDeckFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  // Opened without blocking and checked before reading: a FIFO with no writer, a terminal or
  // a device would otherwise wait (or read) forever.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int error = errno;
    throw DeckError(name, {},
                    error == ENOENT ? std::string("cannot open the deck file (does it exist?)")
                                    : "cannot open the deck file: " + std::string(strerror(error)));
  }
  struct FileCloser {
    int fd;
    ~FileCloser() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw DeckError(name, {}, "cannot read the deck file");
  if (S_ISDIR(info.st_mode)) throw DeckError(name, {}, "is a directory, not a deck file");
  if (!S_ISREG(info.st_mode))
    throw DeckError(name, {},
                    "is not a regular file (a FIFO, socket or device); give the path of a deck "
                    "file");
  // Read at most one byte more than allowed so an enormous file is not loaded whole.
  std::string buffer(kLargestDeck + 1, '\0');
  std::size_t size = 0;
  while (size < buffer.size()) {
    const ssize_t n = ::read(fd, buffer.data() + size, buffer.size() - size);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw DeckError(name, {}, "cannot read the deck file: " + std::string(strerror(errno)));
    if (n == 0) break;
    size += std::size_t(n);
  }
  buffer.resize(size);
  return parseDeckText(buffer, name);
}

}  // namespace beamrotor
