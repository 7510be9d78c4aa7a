// gnuplot runs shell commands, so what beamrotor hands it must be inert: any text as a
// single-quoted literal without control characters, file names confined to the chart's
// directory, and gnuplot itself started without a shell. A chart gnuplot could not finish
// (a full device) fails the write; a gnuplot that fails costs the chart only.
#include <doctest/doctest.h>
#include <sys/stat.h>

#include <fstream>

#include "problems/output/files/Gnuplot.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// An executable shell script standing in for gnuplot.
fs::path fakeGnuplot(const fs::path& file, const std::string& body) {
  std::ofstream(file) << "#!/bin/sh\n" << body;
  fs::permissions(file, fs::perms::owner_all);
  return file;
}

bool anyCanaryUnder(const fs::path& root) {
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.path().filename() == "canary") return true;
  return false;
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("hostile text as gnuplot literals: real gnuplot draws it and runs nothing") {
    REQUIRE(findGnuplot());  // the Makefile installs it; without it this proves nothing
    ScratchDir scratch;
    const fs::path dir = scratch / "charts";
    fs::create_directories(dir);
    const std::string canary = (scratch / "canary").string();
    const std::vector<std::string> hostile{
        "a\nsystem \"touch " + canary + "\"",
        "a\n!touch " + canary,
        "a\rsystem \"touch " + canary + "\"\r",
        "`touch " + canary + "`",
        "'; system \"touch " + canary + "\"; '",
        "''\nsystem \"touch " + canary + "\"\n''",
        "a\\\nsystem \"touch " + canary + "\"",
        "@x",
        "a" + std::string(1, '\0') + "\nsystem \"touch " + canary + "\"",
        "a\xE2\x80\xA8system \"touch " + canary + "\"",
        "\xFF\xFE\nsystem \"touch " + canary + "\"",
    };
    std::string body;
    for (std::size_t i = 0; i < hostile.size(); ++i)
      body += "  set label " + gnuplotText(hostile[i]) + " at graph 0.1, graph " +
              std::to_string(0.05 + 0.08 * double(i)) + "\n";
    body += "  set title " + gnuplotText(hostile[0]) + "\n  plot x title " +
            gnuplotText(hostile[1]) + "\n";
    ChartScript chart{"hostile", "a\nsystem \"touch " + canary + "\"\\", 600, 400, body};
    CHECK(drawChart(dir, chart));
    CHECK_FALSE(fs::exists(canary));
    CHECK_FALSE(anyCanaryUnder(scratch / ""));
    // Every literal is one line: the script has exactly the lines the body and frame have.
    const std::string script = readText(dir / "hostile.gp");
    for (const std::string& text : hostile) {
      const std::string literal = gnuplotText(text);
      CAPTURE(literal);
      CHECK(literal.find_first_of(std::string("\n\r\0", 3)) == std::string::npos);
      CHECK(script.find(literal) != std::string::npos);
    }
  }

  TEST_CASE("file names in scripts stay inside the chart's directory") {
    CHECK(gnuplotFile("static_fields.csv") == "'./static_fields.csv'");
    CHECK(gnuplotFile("value_000/static_fields.csv") == "'./value_000/static_fields.csv'");
    CHECK(gnuplotFile("-e_diagrams.svg") == "'./-e_diagrams.svg'");  // never an option
    for (const char* bad : {"", "/etc/passwd", "../x.csv", "a/../../x.csv", "a//b", "a/", "./a",
                            "<ls", "|ls", "it's", "a b.csv", "a\nb.csv", "a\xFF.csv", "$data"}) {
      CAPTURE(bad);
      CHECK_THROWS_AS(gnuplotFile(bad), std::invalid_argument);
    }
    // A quote never doubles inside a literal (gnuplot reads '' at a string's start as an
    // empty string): it is joined in.
    CHECK(gnuplotText("It's") == "'It'.\"'\".'s'");
    CHECK(gnuplotText("'") == "''.\"'\".''");
    CHECK(gnuplotText("u_y") == "'u\\_y'");
    ScratchDir scratch;
    fs::create_directories(scratch / "d");
    CHECK_THROWS_AS(drawChart(scratch / "d", {"../escape", "", 100, 100, "plot x\n"}),
                    std::invalid_argument);
    CHECK(scratch.entries() == std::vector<std::string>{"d"});
  }

  TEST_CASE("gnuplot is started directly: its arguments and directory, no shell between") {
    ScratchDir scratch;
    // A path a shell would expand: started without one, it is just a name.
    const fs::path tools = scratch / "tools $(touch canary) `touch canary`";
    fs::create_directories(tools);
    const fs::path record = scratch / "record.txt";
    const fs::path fake = fakeGnuplot(
        tools / "gnuplot", "printf '%s|%s|%s' \"$PWD\" \"$#\" \"$1\" > '" + record.string() +
                               "'\nread line && echo stdin-had-data >> '" + record.string() +
                               "'\nexit 3\n");
    const ScopedEnvironment gnuplot("BEAMROTOR_GNUPLOT", fake.c_str());
    const fs::path dir = scratch / "charts";
    fs::create_directories(dir);
    CHECK_FALSE(drawChart(dir, {"-e", "", 100, 100, "plot x\n"}));  // exit 3: a warning only
    CHECK(readText(record) == fs::canonical(dir).string() + "|1|./-e.gp");  // stdin: /dev/null
    CHECK_FALSE(anyCanaryUnder(scratch / ""));
    CHECK(fs::exists(dir / "-e.log"));  // gnuplot's output is kept when it fails
  }

  TEST_CASE("an image gnuplot left incomplete fails the write, naming the file") {
    ScratchDir scratch;
    const fs::path dir = scratch / "charts";
    fs::create_directories(dir);
    SUBCASE("cut short, as on a full device") {
      const ScopedEnvironment gnuplot(
          "BEAMROTOR_GNUPLOT",
          fakeGnuplot(scratch / "gp", "printf '<svg>' > c.svg; printf 'PNG' > c.png\n").c_str());
      CHECK_THROWS_WITH_AS(drawChart(dir, {"c", "", 100, 100, "plot x\n"}),
                           doctest::Contains("c.svg: gnuplot's output is incomplete"),
                           std::runtime_error);
    }
    SUBCASE("complete: drawn, and the log removed") {
      const ScopedEnvironment gnuplot(
          "BEAMROTOR_GNUPLOT",
          fakeGnuplot(scratch / "gp",
                      "printf '<svg>\\n</svg>\\n' > c.svg\n"
                      "printf 'x\\000\\000\\000\\000IEND\\256B`\\202' > c.png\n")
              .c_str());
      CHECK(drawChart(dir, {"c", "", 100, 100, "plot x\n"}));
      CHECK_FALSE(fs::exists(dir / "c.log"));
    }
  }
}
