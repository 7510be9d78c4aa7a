// Hostile suite, the slow cases (`make hostile`, never `make test`): a full device (a small
// tmpfs, mounted when the tests run as root; skipped with a note otherwise), signals while a
// large result is written, and address-space limits.
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <thread>

#include "problems/output/files/AtomicDirectory.hpp"
#include "tests/hostile/HostileSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// A small tmpfs at `dir` for one test, unmounted at the end; empty() when mounting failed.
class SmallDevice {
 public:
  SmallDevice(const fs::path& dir, const std::string& size) : dir_(dir) {
    fs::create_directories(dir);
    mounted_ = ::mount("tmpfs", dir.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
    if (!mounted_) MESSAGE("cannot mount a tmpfs (not root?): the full-device cases are skipped");
  }
  ~SmallDevice() {
    if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
  }
  bool mounted() const { return mounted_; }

 private:
  fs::path dir_;
  bool mounted_ = false;
};

/// A deck whose results are large (many frames of a fine line) and quick to solve.
std::string largeOutputDeck(int elements, int frames) {
  std::string deck = hostileBaseDeck();
  deck.replace(deck.find("elements: 4"), 11, "elements: " + std::to_string(elements));
  deck.replace(deck.find("end: 0.004"), 10, "end: 0.02\n    frames: " + std::to_string(frames));
  return deck;
}

bool completeImage(const fs::path& p) {
  const std::string text = fileContents(p);
  if (p.extension() == ".svg") return text.find("</svg>") != std::string::npos;
  return text.size() >= 8 && text.compare(text.size() - 8, 4, "IEND") == 0;
}

/// The results directory is complete (its marker lists every file, each image finished) or
/// absent, and no temporary sibling is left.
void requireCompleteOrAbsent(const fs::path& out) {
  for (const auto& entry : fs::directory_iterator(out.parent_path()))
    CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
  if (!fs::exists(out)) return;
  std::ifstream marker(out / kMarkerFile);
  std::string line;
  REQUIRE(std::getline(marker, line));
  CHECK(line.find("# beamrotor results") == 0);
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".svg" || ext == ".png") CHECK(completeImage(entry.path()));
  }
}

}  // namespace

TEST_SUITE("slow hostile: full device") {
  TEST_CASE("a full device: exit 1 naming the file, earlier results intact, nothing left") {
    const fs::path root = scratchDir("full-device");
    const SmallDevice device(root / "disk", "2m");
    if (!device.mounted()) return;
    std::ofstream(root / "small.yaml") << hostileBaseDeck();
    std::ofstream(root / "large.yaml") << largeOutputDeck(2000, 200);
    const ProcessResult small = runBeamrotor({"solve", "small.yaml", "--out", "disk/out"}, root);
    REQUIRE(small.exitCode == 0);
    const std::string earlier = fileContents(root / "disk" / "out" / "results.json");
    const ProcessResult large = runBeamrotor({"solve", "large.yaml", "--out", "disk/out"}, root);
    CAPTURE(large.err);
    CHECK(large.exitCode == 1);
    CHECK(std::regex_search(
        large.err,
        std::regex(
            R"(^disk/out: cannot write the results: cannot write disk/out\.tmp-\w+/\S+: (No space left on device|gnuplot's output is incomplete; the device has \d+ kB free))")));
    CHECK(large.out.find("results: not written") != std::string::npos);
    CHECK(fileContents(root / "disk" / "out" / "results.json") == earlier);
    requireCompleteOrAbsent(root / "disk" / "out");
  }

  TEST_CASE("whatever space is left, exit 0 means every file complete (charts included)") {
    const fs::path root = scratchDir("nearly-full");
    std::ofstream(root / "deck.yaml") << hostileBaseDeck();
    int failed = 0, succeeded = 0;
    for (int kb : {16, 48, 96, 160, 240, 320, 480, 640, 960}) {
      CAPTURE(kb);
      const SmallDevice device(root / "disk", std::to_string(kb) + "k");
      if (!device.mounted()) return;
      const ProcessResult r = runBeamrotor({"solve", "deck.yaml", "--out", "disk/out"}, root);
      CAPTURE(r.err);
      CHECK((r.exitCode == 0 || r.exitCode == 1));
      if (r.exitCode == 1) {
        ++failed;
        CHECK(std::regex_search(
            r.err,
            std::regex(
                R"(cannot write \S+: (No space left on device|gnuplot's output is incomplete))")));
        CHECK_FALSE(fs::exists(root / "disk" / "out"));
      } else {
        ++succeeded;
        CHECK(fs::exists(root / "disk" / "out" / "bend_diagrams.png"));
      }
      requireCompleteOrAbsent(root / "disk" / "out");
    }
    CHECK(failed > 0);
    CHECK(succeeded > 0);
  }

  TEST_CASE("bench --json and a checked script write on a full device") {
    const fs::path root = scratchDir("full-json");
    const SmallDevice device(root / "disk", "64k");
    if (!device.mounted()) return;
    {
      std::ofstream filler(root / "disk" / "filler");
      filler << std::string(64 * 1024, 'x');
    }
    const ProcessResult r = runBeamrotor({"bench", "--kind", "planar", "--elements", "10",
                                          "--modes", "0", "--repeat", "1", "--json", "disk/b.json"},
                                         root);
    CAPTURE(r.err);
    CHECK(r.exitCode == 1);
    CHECK(r.err.find("cannot write disk/b.json") != std::string::npos);
    CHECK_FALSE(fs::exists(root / "disk" / "b.json"));
  }
}

TEST_SUITE("slow hostile: signals") {
  TEST_CASE("SIGINT or SIGTERM at any moment: gone by the signal, nothing half-written left") {
    const fs::path root = scratchDir("signals");
    std::ofstream(root / "deck.yaml") << largeOutputDeck(4000, 300);
    int whileWriting = 0;
    for (int signal : {SIGINT, SIGTERM})
      for (int ms : {50, 150, 300, 500, 800, 1200, 1800, 2500}) {
        CAPTURE(signal);
        CAPTURE(ms);
        const pid_t pid = startBeamrotor(root, {"solve", "deck.yaml", "--out", "out"});
        std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        const bool writing = [&] {
          for (const auto& entry : fs::directory_iterator(root))
            if (entry.path().filename().string().rfind("out.tmp-", 0) == 0) return true;
          return false;
        }();
        ::kill(pid, signal);
        int status = 0;
        ::waitpid(pid, &status, 0);
        whileWriting += writing;
        // Ended by the signal, or finished just before it arrived.
        CHECK(((WIFSIGNALED(status) && WTERMSIG(status) == signal) ||
               (WIFEXITED(status) && WEXITSTATUS(status) == 0)));
        requireCompleteOrAbsent(root / "out");
      }
    CHECK(whileWriting > 0);  // some signals did arrive during a write
  }

  TEST_CASE("killed outright while writing: the next run sweeps what was left") {
    const fs::path root = scratchDir("killed");
    std::ofstream(root / "deck.yaml") << largeOutputDeck(4000, 300);
    bool leftSomething = false;
    for (int ms : {600, 1000, 1500, 2200}) {
      const pid_t pid = startBeamrotor(root, {"solve", "deck.yaml", "--out", "out"});
      std::this_thread::sleep_for(std::chrono::milliseconds(ms));
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
      for (const auto& entry : fs::directory_iterator(root))
        leftSomething =
            leftSomething || entry.path().filename().string().find(".tmp-") != std::string::npos;
    }
    const ProcessResult next = runBeamrotor({"solve", "deck.yaml", "--out", "out"}, root);
    CHECK(next.exitCode == 0);
    requireCompleteOrAbsent(root / "out");
    CHECK(leftSomething);  // the kills did catch a write (else this proves nothing)
  }
}

TEST_SUITE("slow hostile: memory") {
  TEST_CASE(
      "under an address-space limit: refused with the estimate, or out of memory; never a crash") {
    const fs::path root = scratchDir("memory");
    std::ofstream(root / "frames.yaml") << largeOutputDeck(100000, 1000);
    std::string modal = hostileBaseDeck();
    modal.replace(modal.find("elements: 4"), 11, "elements: 100000");
    modal.insert(modal.find("  - type: transient"), "  - {type: modal, name: vib, modes: 100}\n");
    std::ofstream(root / "modal.yaml") << modal;
    const auto limited = [&](const std::string& kb, const std::vector<std::string>& args) {
      const std::string dir = shellQuoted(root.string()), exe = shellQuoted(BEAMROTOR_EXE);
      std::string command = "cd " + dir + " && ulimit -v " + kb + " && exec " + exe;
      for (const std::string& a : args) command += ' ' + shellQuoted(a);
      command += " >log 2>&1";
      const int status = std::system(command.c_str());
      return std::pair<int, std::string>(WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                                         fileContents(root / "log"));
    };
    {
      const auto [code, log] = limited("1000000", {"solve", "frames.yaml", "--out", "out"});
      CAPTURE(log);
      CHECK(code == 1);
      CHECK(std::regex_search(
          log,
          std::regex(
              R"(^frames\.yaml:\d+:\d+: analyses\[1\]: this run needs about [0-9.]+ GB but [0-9.]+ [MG]B are available; the largest part is transient 'shake': 1000 frames)")));
    }
    for (const char* kb : {"300000", "600000", "900000", "1500000"}) {
      CAPTURE(kb);
      const auto [code, log] = limited(kb, {"solve", "modal.yaml", "--out", "out2"});
      CAPTURE(log);
      CHECK((code == 0 || code == 1));  // never a signal (a crash)
      if (code == 1)
        CHECK(std::regex_search(log, std::regex("this run needs about|out of memory")));
    }
    for (const char* elements : {"1000000", "10000000", "100000000"}) {
      CAPTURE(elements);
      const auto [code, log] = limited("1000000", {"bench", "--kind", "planar", "--elements",
                                                   elements, "--modes", "0", "--repeat", "1"});
      CAPTURE(log);
      CHECK((code == 0 || code == 1 || code == 2));
      if (code != 0)
        CHECK(std::regex_search(log, std::regex("needs about .* available|out of memory")));
    }
  }
}
