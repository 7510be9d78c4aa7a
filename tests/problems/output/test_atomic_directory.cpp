// Results directories: replaced in one step, only when beamrotor wrote everything in them (the
// .beamrotor marker lists it), never half-written after a failure or a signal, and what a
// killed run left behind is swept by the next one.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <thread>

#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/files/Interruption.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// Fills a results directory: results.json holding `text` and a sub-directory with a file.
std::function<void(const fs::path&)> resultsHolding(const std::string& text) {
  return [text](const fs::path& dir) {
    writeFile(dir / "results.json", [&](std::ostream& out) { out << text; });
    fs::create_directory(dir / "value_000");
    writeFile(dir / "value_000" / "a.csv", [&](std::ostream& out) { out << "x\n1\n"; });
  };
}

/// A temporary directory as a run killed while writing would leave it.
fs::path leftBehind(const fs::path& dir, const std::string& suffix, const std::string& marker) {
  const fs::path t = dir.string() + ".tmp-" + suffix;
  fs::create_directories(t / "value_000");
  std::ofstream(t / "results.json") << "{";
  std::ofstream(t / "value_000" / "a.csv") << "x\n";
  if (!marker.empty()) std::ofstream(t / kMarkerFile) << marker;
  return t;
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("the marker lists what beamrotor wrote; the next write replaces all of it") {
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    writeDirectoryAtomically(out, resultsHolding("first"));
    const std::string marker = readText(out / kMarkerFile);
    CHECK(marker.find("\nresults.json\nvalue_000/\nvalue_000/a.csv\n") != std::string::npos);
    writeDirectoryAtomically(out, [](const fs::path& dir) {
      writeFile(dir / "results.json", [](std::ostream& o) { o << "second"; });
    });
    CHECK(readText(out / "results.json") == "second");
    CHECK_FALSE(fs::exists(out / "value_000"));
    CHECK(scratch.entries() == std::vector<std::string>{"out"});
  }

  TEST_CASE("what beamrotor did not write is never replaced, and nothing is touched") {
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    const auto refused = [&](const std::string& expected) {
      CHECK_THROWS_WITH_AS(writeDirectoryAtomically(out, resultsHolding("new")),
                           doctest::Contains(expected.c_str()), std::runtime_error);
    };
    SUBCASE("a file the user added to a results directory") {
      writeDirectoryAtomically(out, resultsHolding("old"));
      std::ofstream(out / "value_000" / "notes.txt") << "mine";
      refused("it holds 'value_000/notes.txt', which beamrotor did not write");
      CHECK(readText(out / "value_000" / "notes.txt") == "mine");
      CHECK(readText(out / "results.json") == "old");
    }
    SUBCASE("the deck itself, copied into its results") {
      writeDirectoryAtomically(out, resultsHolding("old"));
      std::ofstream(out / "deck.yaml") << "title: x\n";
      refused("it holds 'deck.yaml'");
      CHECK(fs::exists(out / "deck.yaml"));
    }
    SUBCASE("results of another tool, or of a beamrotor without markers") {
      fs::create_directories(out);
      std::ofstream(out / "results.json") << "{}";
      refused("beamrotor did not write it (it has no .beamrotor marker");
      CHECK(readText(out / "results.json") == "{}");
    }
    SUBCASE("a marker of someone else's making lists nothing beamrotor wrote") {
      fs::create_directories(out);
      std::ofstream(out / kMarkerFile) << "results.json\n";
      std::ofstream(out / "results.json") << "{}";
      refused("no .beamrotor marker");
    }
    SUBCASE("a symbolic link to a directory, and a plain file") {
      fs::create_directories(scratch / "elsewhere");
      std::ofstream(scratch / "elsewhere" / "keep.txt") << "keep";
      fs::create_directory_symlink(scratch / "elsewhere", out);
      refused("it exists and is not a directory; choose another output directory with --out");
      CHECK(readText(scratch / "elsewhere" / "keep.txt") == "keep");
    }
    SUBCASE("a symbolic link inside a results directory") {
      writeDirectoryAtomically(out, resultsHolding("old"));
      fs::create_directories(scratch / "elsewhere");
      std::ofstream(scratch / "elsewhere" / "keep.txt") << "keep";
      fs::create_directory_symlink(scratch / "elsewhere", out / "link");
      refused("it holds 'link'");
      CHECK(readText(scratch / "elsewhere" / "keep.txt") == "keep");
    }
    for (const auto& entry : fs::directory_iterator(scratch / ""))
      CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
  }

  TEST_CASE("an empty directory is filled (nothing in it to lose)") {
    ScratchDir scratch;
    fs::create_directories(scratch / "out");
    writeDirectoryAtomically(scratch / "out", resultsHolding("new"));
    CHECK(readText(scratch / "out" / "results.json") == "new");
    CHECK(scratch.entries() == std::vector<std::string>{"out"});
  }

  TEST_CASE("a reader polling the directory always finds complete results") {
    // The reader-poll experiment of issue 15, as a test: the old scheme (remove, then rename)
    // showed readers no results in about 1.6 % of reads; one exchange shows none.
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    const std::string big(200000, 'x');
    writeDirectoryAtomically(out, resultsHolding("0" + big));
    std::atomic<bool> done{false};
    std::atomic<int> reads{0}, missing{0};
    std::thread reader([&] {
      while (!done) {
        std::ifstream in(out / "results.json");
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ++reads;
        if (text.size() != big.size() + 1) ++missing;
      }
    });
    // At least 40 exchanges, and on until the reader has read 40 times (a loaded machine may
    // run the writer for a while before it schedules the reader).
    for (int i = 1; i <= 40 || (reads <= 40 && i <= 4000); ++i)
      writeDirectoryAtomically(out, resultsHolding(std::to_string(i % 10) + big));
    done = true;
    reader.join();
    CHECK(reads > 40);
    CHECK(missing == 0);
  }

  TEST_CASE("a signal while writing: the temporary directory goes, the earlier results stay") {
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    writeDirectoryAtomically(out, resultsHolding("earlier"));
    struct sigaction before {};
    sigaction(SIGINT, nullptr, &before);
    const auto interrupted = [](const fs::path& dir) {
      writeFile(dir / "results.json", [](std::ostream& o) { o << "half"; });
      ::raise(SIGINT);  // recorded, not acted on: the next file stops the write
      writeFile(dir / "more.csv", [](std::ostream& o) { o << "never"; });
    };
    CHECK_THROWS_AS(writeDirectoryAtomically(out, interrupted), Interrupted);
    CHECK(pendingInterruption() == SIGINT);
    clearInterruption();
    CHECK(readText(out / "results.json") == "earlier");
    CHECK(scratch.entries() == std::vector<std::string>{"out"});
    struct sigaction after {};
    sigaction(SIGINT, nullptr, &after);
    CHECK(bool(after.sa_handler == before.sa_handler));  // the previous handler is back
  }

  TEST_CASE("temporary directories a killed run left are swept; a live writer's are not") {
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    const fs::path killedWhileWriting = leftBehind(out, "aaaaaa", "# beamrotor: being written\n");
    const fs::path killedBeforeRemoving = leftBehind(
        out, "bbbbbb",
        "# beamrotor results: the next run replaces this directory unless it holds anything "
        "not listed here\nresults.json\nvalue_000/\nvalue_000/a.csv\n");
    std::ofstream(killedBeforeRemoving / "notes.txt") << "not ours";
    const fs::path notOurs = leftBehind(out, "cccccc", "");
    const fs::path stillWriting = leftBehind(out, "dddddd", "# beamrotor: being written\n");
    const int lock = ::open((stillWriting / kMarkerFile).c_str(), O_RDONLY);
    REQUIRE(::flock(lock, LOCK_EX) == 0);
    const fs::path otherOutput =
        leftBehind(scratch / "other", "eeeeee", "# beamrotor: being written\n");

    writeDirectoryAtomically(out, resultsHolding("new"));
    ::close(lock);
    CHECK_FALSE(fs::exists(killedWhileWriting));
    CHECK_FALSE(fs::exists(killedBeforeRemoving / "results.json"));
    CHECK(readText(killedBeforeRemoving / "notes.txt") == "not ours");  // kept, and so the dir
    CHECK(fs::exists(notOurs / "results.json"));
    CHECK(fs::exists(stillWriting / "results.json"));
    CHECK(fs::exists(otherOutput / "results.json"));
  }

  TEST_CASE("checked writes: a full device or a missing directory names the file and reason") {
    const auto fails = [](const fs::path& file, const std::string& reason) {
      CHECK_THROWS_WITH_AS(
          writeFile(file, [](std::ostream& o) { o << std::string(1 << 16, 'x'); }),
          doctest::Contains(("cannot write " + file.string() + ": " + reason).c_str()),
          std::runtime_error);
    };
    fails("/dev/full", "No space left on device");
    ScratchDir scratch;
    fails(scratch / "missing" / "a.csv", "No such file or directory");
    CHECK_THROWS_WITH_AS(writeFileAtomically("/dev/full", [](std::ostream& o) { o << "{}"; }),
                         doctest::Contains("cannot write /dev/full: No space left on device"),
                         std::runtime_error);
    CHECK(fs::is_character_file("/dev/full"));  // written to, never renamed over
    writeFileAtomically(scratch / "a.json", [](std::ostream& o) { o << "{}"; });
    CHECK(readText(scratch / "a.json") == "{}");
    CHECK(scratch.entries() == std::vector<std::string>{"a.json"});
  }
}
