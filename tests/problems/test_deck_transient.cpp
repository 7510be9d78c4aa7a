// Transient analyses written in decks, on a body of mass m on a spring k (omega = sqrt(k/m)),
// a model without beams: free vibration from an initial state, a step load written in each of
// the four forms of a load in time, Rayleigh damping, the central scheme's limit, HHT, a stop
// with restitution, and the files a run writes.
#include <doctest/doctest.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
namespace fs = std::filesystem;

namespace {

/// m = 2 kg, k = 800 N/m: omega = 20 rad/s, T = pi/10 s. `analysis` is the body of the
/// transient analysis's map (indented 4), `extra` any top-level keys.
std::string deck(const std::string& analysis, const std::string& extra = "") {
  return "parameters: {m: 2, k: 800, F: 40, dt: 0.001}\n"
         "derived: {w: sqrt(k/m)}\n"
         "points:\n  - {name: body}\n"
         "masses:\n  - {at: body, m: m}\n"
         "springs:\n  - {at: body, dof: ux, k: k}\n" +
         extra +
         "analyses:\n  - type: transient\n    name: run\n    record: [{name: x, at: body, dof: "
         "ux}]\n" +
         analysis;
}

RunResult solveTransientDeck(const std::string& text, std::vector<std::string> sets = {}) {
  StudyRequest r;
  r.deckPath = "transient.yaml";
  r.sets = std::move(sets);
  Study s = solveStudyText(text, r);
  REQUIRE(s.run);
  return std::move(*s.run);
}

const TransientOutcome& outcome(const RunResult& run) {
  REQUIRE(resultOf<TransientOutcome>(run.analyses.at(0)));
  return *resultOf<TransientOutcome>(run.analyses.at(0));
}

/// Largest |x(t) - exact(t)| over the samples.
template <class Exact>
double worstError(const RunResult& run, Exact exact) {
  const TransientOutcome& t = outcome(run);
  const NamedHistory& x = t.history("x");
  double worst = 0;
  for (std::size_t i = 0; i < x.values.size(); ++i)
    worst = std::max(worst, std::abs(x.values[i] - exact(t.result.times[i])));
  return worst;
}

constexpr double kW = 20;  // rad/s

}  // namespace

TEST_SUITE("deck transient") {
  TEST_CASE("free vibration from the deck's initial state: x0 cos wt + v0/w sin wt, order 2") {
    const std::string text = deck(
        "    dt: dt\n    end: 1\n"
        "    initial: [{at: body, dof: ux, u: 0.01, v: 0.3}]\n");
    const auto exact = [](double t) {
      return 0.01 * std::cos(kW * t) + 0.3 / kW * std::sin(kW * t);
    };
    const double coarse = worstError(solveTransientDeck(text, {"dt=0.002"}), exact);
    const double fine = worstError(solveTransientDeck(text), exact);
    CAPTURE(coarse);
    CAPTURE(fine);
    // Newmark's period error (w dt)^2 / 12 per radian: 20 rad at w dt = 0.02 gives 6.7e-4 rad
    // of phase, 1.2e-5 m on the amplitude 0.0180 m; measured 1.10e-5 m (4.40e-5 at 2 dt).
    CHECK(fine < 1.5e-5);
    CHECK(coarse / fine == doctest::Approx(4).epsilon(0.02));
  }

  TEST_CASE("a step load F in each form of a load in time: F/k (1 - cos wt), same history") {
    // value (an expression of t), pieces, a harmonic series (the k = 0 term is the mean) and
    // a table describe the same step at t = 0; the four runs agree to round-off.
    const std::vector<std::string> forms{
        "value: F", "pieces: [{from: 0, value: F}]",
        "harmonics: {omega: w, mean: F, terms: [{k: 1, amplitude: 0}]}", "table: [[0, F], [1, F]]"};
    std::vector<std::vector<double>> histories;
    for (const std::string& form : forms) {
      CAPTURE(form);
      const RunResult run = solveTransientDeck(
          deck("    dt: dt\n    end: 1\n    loads:\n      - {at: body, dof: ux, " + form + "}\n"));
      histories.push_back(outcome(run).history("x").values);
      // Same phase error as free vibration on the amplitude F/k = 0.05 m: 3.3e-5 m predicted,
      // 3.04e-5 m measured.
      CHECK(worstError(run, [](double t) { return 40.0 / 800 * (1 - std::cos(kW * t)); }) < 4e-5);
    }
    for (std::size_t f = 1; f < histories.size(); ++f)
      for (std::size_t i = 0; i < histories[0].size(); ++i)
        CHECK(std::abs(histories[f][i] - histories[0][i]) < 1e-15);
  }

  TEST_CASE("checks read a history's max, min and value at a time") {
    // The step response F/k (1 - cos wt) peaks at 2F/k = 0.1 m at t = pi/w and starts at 0.
    // w dt = 2e-3: a sample lies within (w dt)^2/8 = 5e-7 (relative) of the peak, where the
    // phase error enters only squared; at t = pi/(2w), between samples, the relative error is
    // the phase error (w dt)^2/12 * pi/2 = 5.2e-7 (the curve is straight there, so linear
    // interpolation adds nothing). Measured 4.1e-8, 0 and 5.24e-7.
    const std::string checks =
        "checks:\n"
        "  - {name: peak, quantity: history x max, reference: 2*F/k, tolerance: 1e-6}\n"
        "  - {name: start, quantity: history x min, reference: 0, tolerance: 1e-15}\n"
        "  - {name: half, quantity: history x at pi/(2*w), reference: F/k, tolerance: 1e-6}\n";
    const RunResult run = solveTransientDeck(
        deck("    dt: dt/10\n    end: 0.2\n    loads: [{at: body, dof: ux, value: F}]\n") + checks);
    REQUIRE(run.checks.size() == 3);
    for (const Check& c : run.checks) {
      CAPTURE(c.name);
      CAPTURE(c.relError());
      CHECK(c.pass());
    }
  }

  TEST_CASE("a periodic expression load at resonance grows as F t/(2 m w) sin wt") {
    // F cos(w t) written as an expression of t inside a period of 2 pi / w (so t is reduced
    // to one period before it is evaluated): the resonant closed form from rest is
    // x = F t sin(w t) / (2 m w).
    const RunResult run = solveTransientDeck(
        deck("    dt: dt/4\n    end: 1\n    loads:\n"
             "      - {at: body, dof: ux, value: F*cos(w*t), period: 2*pi/w}\n"));
    const auto exact = [](double t) { return 40 * t * std::sin(kW * t) / (2 * 2 * kW); };
    // Amplitude at t = 1 s: 0.5 m; phase error (w dt)^2/12 * 20 rad = 4.2e-5 rad -> 2.1e-5 m
    // predicted, 1.03e-5 m measured.
    CHECK(worstError(run, exact) < 2.5e-5);
  }

  TEST_CASE("an end time that is not a whole number of steps ends at the nearest step, warned") {
    const RunResult run = solveTransientDeck(deck("    dt: 0.0003\n    end: 0.5\n"));
    const TransientResult& r = outcome(run).result;
    CHECK(r.steps == 1667);  // round(1666.67)
    REQUIRE(r.warnings.size() == 1);
    CHECK(r.warnings[0].find("0.5001 s") != std::string::npos);
    CHECK(
        outcome(solveTransientDeck(deck("    dt: 0.001\n    end: 0.5\n"))).result.warnings.empty());
  }

  TEST_CASE("Rayleigh mass damping: the decay exp(-alpha t / 2)") {
    // C = alpha M: zeta = alpha / (2 w); x = x0 e^(-zeta w t) (cos wd t + zeta w / wd sin wd t).
    const RunResult run =
        solveTransientDeck(deck("    dt: dt\n    end: 1\n    rayleigh: {alpha: 4}\n"
                                "    initial: [{at: body, dof: ux, u: 0.01}]\n"));
    const double zeta = 4.0 / (2 * kW), wd = kW * std::sqrt(1 - zeta * zeta);
    const auto exact = [&](double t) {
      return 0.01 * std::exp(-zeta * kW * t) *
             (std::cos(wd * t) + zeta * kW / wd * std::sin(wd * t));
    };
    // The undamped phase error 6.7e-4 t/1 s on an amplitude 0.01 e^(-2t) peaks at t = 0.5 s:
    // 1.2e-6 m predicted, 1.23e-6 m measured.
    CHECK(worstError(run, exact) < 2e-6);
  }

  TEST_CASE("central difference: dt_crit = 2 sqrt(m/k) reported; below it, the closed form") {
    const std::string text = deck(
        "    scheme: central\n    dt: dt\n    end: 1\n"
        "    initial: [{at: body, dof: ux, u: 0.01}]\n");
    const RunResult run = solveTransientDeck(text);
    const TransientResult& r = outcome(run).result;
    CHECK(std::abs(r.stability.dtCritical - 2 * std::sqrt(2.0 / 800)) < 1e-15);
    // Central difference's period error is (w dt)^2 / 24 per radian (Hughes 2000, 9.1): 20 rad
    // give 3.3e-6 m on 0.01 m predicted, 3.04e-6 m measured.
    CHECK(worstError(run, [](double t) { return 0.01 * std::cos(kW * t); }) < 5e-6);
    // Above the limit (0.1 s) the deck is refused at its dt, before any step.
    try {
      solveTransientDeck(text, {"dt=0.11"});
      FAIL("no error");
    } catch (const DeckError& e) {
      CHECK(e.place().field == "analyses[0].dt");
      CHECK(std::string(e.what()).find("0.1 s") != std::string::npos);
    }
  }

  TEST_CASE("HHT with alpha = -0.1 stays second order on a resolved oscillation") {
    const std::string text = deck(
        "    scheme: hht\n    alpha: -0.1\n    dt: dt\n    end: 1\n"
        "    initial: [{at: body, dof: ux, u: 0.01}]\n");
    const auto exact = [](double t) { return 0.01 * std::cos(kW * t); };
    const double coarse = worstError(solveTransientDeck(text, {"dt=0.002"}), exact);
    const double fine = worstError(solveTransientDeck(text), exact);
    CAPTURE(coarse);
    CAPTURE(fine);
    CHECK(coarse / fine == doctest::Approx(4).epsilon(0.05));  // measured 3.99
  }

  TEST_CASE("a stop with restitution: the body never passes it and rebounds at -e v") {
    // Free flight into the stop (no spring force yet matters for the first approach: the body
    // starts at x = 0 moving at -2 m/s toward x = -0.005 m, reached after 2.5 ms, well before
    // the spring slows it by more than k x / m dt ~ 1e-3 of v). Rebound e = 0.5.
    const std::string contacts = "contacts:\n  - {name: collar, at: body, dof: ux, min: -0.005}\n";
    const RunResult run =
        solveTransientDeck(deck("    dt: dt/10\n    end: 0.2\n    restitution: 0.5\n"
                                "    initial: [{at: body, dof: ux, v: -2}]\n",
                                contacts));
    const TransientOutcome& t = outcome(run);
    CHECK(t.history("x").min() >= -0.005);
    REQUIRE(!t.result.impacts.empty());
    const Impact& first = t.result.impacts.front();
    CHECK(first.stop == "collar");
    CHECK(first.velocityAfter == doctest::Approx(-0.5 * first.velocityBefore).epsilon(1e-12));
    // Approach speed from energy: v^2 = v0^2 - k x^2 / m at x = -0.005: 1.99998 m/s.
    CHECK(std::abs(first.velocityBefore + std::sqrt(4 - 800 * 0.005 * 0.005 / 2)) < 1e-6);
  }

  TEST_CASE("the files: history CSV and chart, frames as vertex cells in a .pvd, results.json") {
    const fs::path dir = test::scratchDir("transient-files");
    const fs::path file = dir / "spring.yaml";
    std::ofstream(file) << deck(
        "    dt: dt\n    end: 0.5\n    frames: 11\n"
        "    initial: [{at: body, dof: ux, u: 0.01}]\n");
    const fs::path out = dir / "out";
    const auto r = test::runBeamrotor({"solve", file.string(), "--out", out.string()});
    REQUIRE(r.exitCode == 0);
    CHECK(r.out.find("transient analysis 'run' (newmark") != std::string::npos);
    std::ifstream in(out / "results.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    const auto& a = doc.at("analyses").at(0);
    CHECK(a.at("type") == "transient");
    CHECK(a.at("steps") == 500);
    // Energy is conserved by the average acceleration rule to round-off.
    CHECK(a.at("energy_balance_error").get<double>() < 1e-12);
    CHECK(std::abs(a.at("maxima").at("x_max").get<double>() - 0.01) < 1e-9);
    CHECK(a.at("files").at("vtu").size() == 11);
    for (const char* name : {"run_history.csv", "run_history.png", "run.pvd", "run_frame_0011.vtu"})
      CHECK(fs::exists(out / name));
    // The last frame read back by VTK: one vertex at the body, displaced as the history ends
    // (x = 0.01 cos(20 t) at t = 0.5 s, to Newmark's phase error 1.2e-5 m).
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((out / "run_frame_0011.vtu").c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    REQUIRE(grid->GetNumberOfCells() == 1);
    CHECK(grid->GetCellType(0) == VTK_VERTEX);
    const double x = grid->GetPointData()->GetArray("displacement")->GetComponent(0, 0);
    CHECK(x == a.at("histories").at("x").at("final").get<double>());
    CHECK(std::abs(x - 0.01 * std::cos(10.0)) < 1.5e-5);
    CHECK(grid->GetFieldData()->GetArray("time")->GetTuple1(0) == doctest::Approx(0.5));
    std::ifstream csv(out / "run_history.csv");
    int rows = 0;
    for (std::string line; std::getline(csv, line);) ++rows;
    CHECK(rows == 2 + 501);  // names, units, t = 0 and every step
    fs::remove_all(dir);
  }

  TEST_CASE("a beam in time: tip mass on a massless cantilever, omega^2 = 3 E I / (M L^3)") {
    // Hermite beams condense exactly to the tip stiffness 3 E I / L^3, and the beam's dofs
    // carry no mass (rho = 0): the tip mass M started at v0 moves as v0/omega sin(omega t).
    // Newmark's phase error (omega dt)^2 / 12 per radian over 4 pi rad: 2.6e-4 of the
    // amplitude at dt = T/400 (measured 2.58e-4, 1.86e-7 m); halving dt divides it by 4.
    const std::string text =
        "parameters: {L: 1, D: 0.05, E: 210e9, M: 10, v0: 0.1, n: 400}\n"
        "derived: {w: sqrt(3*E*(pi*D^4/64)/(M*L^3)), T: 2*pi/w}\n"
        "materials: [{name: steel, E: E, nu: 0.3}]\n"
        "sections: [{name: rod, shape: circle, D: D}]\n"
        "segments: [{length: L, section: rod, elements: 4}]\n"
        "supports: [{at: start, fix: clamped}]\n"
        "masses: [{at: end, m: M}]\n"
        "analyses:\n  - type: transient\n    dt: T/n\n    cycles: 2\n    period: T\n"
        "    initial: [{at: end, dof: uy, v: v0}]\n"
        "    record: [{name: x, at: end, dof: uy}]\n";
    const double E = 210e9, I = std::numbers::pi * std::pow(0.05, 4) / 64;
    const double w = std::sqrt(3 * E * I / 10);
    const auto exact = [&](double t) { return 0.1 / w * std::sin(w * t); };
    const double coarse = worstError(solveTransientDeck(text, {"n=200"}), exact);
    const double fine = worstError(solveTransientDeck(text), exact);
    CAPTURE(coarse);
    CAPTURE(fine);
    CHECK(fine < 3e-4 * 0.1 / w);
    CHECK(coarse / fine == doctest::Approx(4).epsilon(0.02));
  }
}
