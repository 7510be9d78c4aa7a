# Thin wrapper: install missing Debian packages, build with CMake, run.
# VTK comes from one of two Debian packages that cannot be installed together on Debian 12:
# libvtk9-dev, or paraview-dev (ParaView's own VTK; libvtk9-dev depends on python3-vtk9, which
# ParaView's python3-paraview conflicts with). The one already installed is kept; a machine
# with ParaView (paraview or python3-paraview) gets paraview-dev, so nothing is removed; any
# other machine gets libvtk9-dev. `make VTK_PACKAGE=paraview-dev ...` chooses by hand.
installed = $(shell dpkg-query -W -f='$${Status}' $(1) 2>/dev/null | grep -q 'ok installed$$' && echo $(1))
ifeq ($(origin VTK_PACKAGE),undefined)
  VTK_PACKAGE := $(or $(call installed,libvtk9-dev),\
                      $(if $(or $(call installed,paraview-dev),$(call installed,python3-paraview),$(call installed,paraview)),paraview-dev),\
                      libvtk9-dev)
endif
# With ParaView's VTK come pvpython, the ParaView test (tests/paraview) and, for its pictures
# on a machine without a display, a virtual X server.
VTK_EXTRAS := $(if $(filter paraview-dev,$(VTK_PACKAGE)),xvfb xauth)
PACKAGES := cmake g++ make libopenmpi-dev openmpi-bin libeigen3-dev libsuitesparse-dev libarpack2-dev $(VTK_PACKAGE) $(VTK_EXTRAS) \
            doctest-dev libyaml-cpp-dev libcli11-dev libmuparser-dev nlohmann-json3-dev \
            gnuplot-nox python3-meshio pybind11-dev python3-dev python3-numpy python3-pytest \
            dpkg-dev file libpng-dev libopenblas0-pthread help2man
BUILD    := build
JOBS     ?= $(shell nproc)
DECK     ?= problems/pump_rod.yaml
SUDO     := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: deps configure build run test bench clean package

# Warnings as errors (-Werror), as CI builds: `make test WERROR=1`. Given to CMake at every
# configure, so a build directory configured earlier keeps no stale value.
WERROR ?= 0
CMAKE_WERROR := -DBEAMROTOR_WERROR=$(if $(filter 1 ON On on YES yes TRUE true,$(WERROR)),ON,OFF)
# Each target builds only what it runs: the executable (run, bench, report, ...), what the
# package ships (package: the executable, the Python module and the manual page); the test
# suite only for test and hostile.
BUILD_EXE := cmake --build $(BUILD) -j $(JOBS) --target beamrotor

# Installs what is missing (without Debian's recommended extras: the project names all it needs,
# and the extras are a sixth of the download) and never removes anything: when Debian can install a package only by
# removing one the machine has (libvtk9-dev beside ParaView's python3-paraview, for one), or
# cannot install it at all beside them, it stops, changes nothing, names the packages that stand
# in each other's way and the way out.
# Prints "  PACKAGE Conflicts: ..." (or Breaks) for each stanza of apt-cache show whose
# Conflicts or Breaks names a package matching the regular expression rx.
export CONFLICTS_AWK := /^Package: /{p=$$2} /^(Conflicts|Breaks): /{n=split($$0,w,/[ ,:|()]+/); for(i=2;i<=n;i++) if(w[i]~rx){print "  " p " " $$0; break}}
deps:
	@missing=$$(for p in $(PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed' || echo $$p; done); missing=$$(echo $$missing); \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:" $$missing; \
	  $(SUDO) apt-get update -qq || exit 1; \
	  plan=$$(LC_ALL=C apt-get install -s $$missing 2>&1) || { \
	    echo "beamrotor: Debian cannot install $$missing beside the packages this machine has; nothing was installed or removed. apt says:" >&2; \
	    echo "$$plan" | sed -n '/unmet dependencies/,$$p' >&2; \
	    case " $$missing " in *" libvtk9-dev "*) echo "beamrotor: build against ParaView's VTK instead of libvtk9-dev: make VTK_PACKAGE=paraview-dev $(MAKECMDGOALS)" >&2;; esac; \
	    case " $$missing " in *" paraview-dev "*) echo "beamrotor: build against Debian's VTK instead of paraview-dev: make VTK_PACKAGE=libvtk9-dev $(MAKECMDGOALS)" >&2;; esac; \
	    exit 1; }; \
	  removed=$$(echo "$$plan" | sed -n 's/^Remv \([^ ]*\).*/\1/p' | tr '\n' ' '); removed=$$(echo $$removed); \
	  if [ -n "$$removed" ]; then \
	    echo "beamrotor: Debian can install $$missing only by removing $$removed, which this machine has." >&2; \
	    echo "beamrotor: nothing was installed or removed. The packages stand in each other's way:" >&2; \
	    installs=$$(echo "$$plan" | sed -n 's/^Inst \([^ ]*\).*/\1/p'); \
	    gone=$$(echo $$removed | sed 's/[.+]/\\&/g; s/ /|/g'); coming=$$(echo $$installs | sed 's/[.+]/\\&/g; s/ /|/g'); \
	    { apt-cache show --no-all-versions $$installs 2>/dev/null | awk -v rx="^($$gone)$$" "$$CONFLICTS_AWK"; \
	      apt-cache show --no-all-versions $$removed 2>/dev/null | awk -v rx="^($$coming)$$" "$$CONFLICTS_AWK"; } >&2; \
	    echo "beamrotor: install the listed packages on a machine (or container) without $$removed, or remove $$removed yourself if you choose to." >&2; \
	    case " $$missing " in *" libvtk9-dev "*) echo "beamrotor: or build against ParaView's VTK instead of libvtk9-dev: make VTK_PACKAGE=paraview-dev $(MAKECMDGOALS)" >&2;; esac; \
	    case " $$missing " in *" paraview-dev "*) echo "beamrotor: or build against Debian's VTK instead of paraview-dev: make VTK_PACKAGE=libvtk9-dev $(MAKECMDGOALS)" >&2;; esac; \
	    exit 1; \
	  fi; \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-remove --no-install-recommends $$missing; \
	fi

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DBEAMROTOR_VTK=$(if $(filter paraview-dev,$(VTK_PACKAGE)),paraview,system) $(CMAKE_WERROR) >/dev/null

# Everything: library, executable, Python module and tests.
build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: configure
	$(BUILD_EXE)
	./$(BUILD)/beamrotor solve $(DECK)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The Debian package (CPack, dependencies from dpkg-shlibdeps): $(BUILD)/beamrotor_<version>_<arch>.deb,
# built from what it ships only (beamrotor_installed; CPack's install step builds nothing more).
package: configure
	cmake --build $(BUILD) -j $(JOBS) --target beamrotor_installed
	cd $(BUILD) && cpack

# Speed figures (never part of `make test`; about 25-30 minutes on a quiet 2-core machine), medians of
# BENCH_REPEAT runs, every ratio measured side by side in one run, JSON in out/bench/ and
# everything gathered in out/bench/summary.json (tests/bench/compare.py, last):
# - the planar line against SciPy: statics at 10^3 .. 10^6 elements, 10 modes at 10^4 and
#   10^6 (the latter against its own statics), warm (repeats inside one process) and cold
#   (tests/bench/cold.py: fresh processes, start-up and page faults included); grid3d at 10^6
#   dofs (statics and 10 modes);
# - rotors: Campbell diagrams of 200 and 800 elements (50 speeds x 12 modes);
# - 3D frames against CalculiX (tests/bench/frames_ccx.py: buildings of about 10^3 and 10^4
#   members and a lattice tower, `beamrotor solve` against `ccx`, solve alone, answers
#   compared, peak memory); load combinations 1, 20 and 200 on a 10^4-member frame
#   (`bench --kind frame3d`);
# - every shipped deck end to end, with and without charts, each analysis's solve (the
#   compressor's unbalance sweep, the Jeffcott rotor's instability onset), and per-point files
#   (tests/bench/output_bench.py);
# - design studies: points per second serially, with --threads 2 and under mpirun -n 2
#   (tests/bench/study_bench.py).
# The frames of 10^5 elements and 10^5 members are in `make bench-large`.
BENCH_PACKAGES := python3-scipy calculix-ccx
BENCH_REPEAT   ?= 3
PY             := /usr/bin/python3
COLD           := $(PY) tests/bench/cold.py --repeat 3 --json
bench: configure
	$(BUILD_EXE)
	@$(MAKE) --no-print-directory deps PACKAGES="$(BENCH_PACKAGES)"
	mkdir -p out/bench
	for n in 1000 10000 100000 1000000; do \
	  ./$(BUILD)/beamrotor bench --kind planar --elements $$n --modes 0 --repeat 3 \
	    --json out/bench/planar_static_$$n.json || exit 1; \
	  $(PY) tests/bench/planar_scipy.py --elements $$n --repeat 3 \
	    --json out/bench/scipy_static_$$n.json || exit 1; \
	  $(COLD) out/bench/cold_planar_static_$$n.json -- ./$(BUILD)/beamrotor bench --kind planar \
	    --elements $$n --modes 0 --repeat 1 --cold || exit 1; \
	  $(COLD) out/bench/cold_scipy_static_$$n.json -- $(PY) tests/bench/planar_scipy.py \
	    --elements $$n --json out/bench/cold_scipy_run.json || exit 1; \
	done
	./$(BUILD)/beamrotor bench --kind planar --elements 10000 --modes 10 --repeat 3 \
	  --json out/bench/planar_modal_10000.json
	$(PY) tests/bench/planar_scipy.py --elements 10000 --modes 10 \
	  --json out/bench/scipy_modal_10000.json
	$(COLD) out/bench/cold_planar_modal_10000.json -- ./$(BUILD)/beamrotor bench --kind planar \
	  --elements 10000 --modes 10 --repeat 1 --cold
	$(COLD) out/bench/cold_scipy_modal_10000.json -- $(PY) tests/bench/planar_scipy.py \
	  --elements 10000 --modes 10 --json out/bench/cold_scipy_run.json
	./$(BUILD)/beamrotor bench --kind planar --elements 1000000 --modes 10 --repeat 3 \
	  --json out/bench/planar_modal_1000000.json
	./$(BUILD)/beamrotor bench --kind grid3d --dofs 1000000 --modes 10 --repeat 1 \
	  --json out/bench/grid3d_1000000.json
	for n in 200 800; do \
	  ./$(BUILD)/beamrotor bench --kind rotor --elements $$n --repeat $(BENCH_REPEAT) \
	    --json out/bench/rotor_$$n.json || exit 1; \
	done
	$(COLD) out/bench/cold_rotor_200.json -- ./$(BUILD)/beamrotor bench --kind rotor \
	  --elements 200 --repeat 1 --cold
	$(PY) tests/bench/frames_ccx.py --exe ./$(BUILD)/beamrotor --repeat $(BENCH_REPEAT) \
	  --json out/bench/frames_ccx.json
	for c in 1 20 200; do \
	  ./$(BUILD)/beamrotor bench --kind frame3d --members 10000 --modes 0 --combinations $$c \
	    --repeat $(BENCH_REPEAT) --json out/bench/frame3d_combinations_$$c.json || exit 1; \
	done
	$(PY) tests/bench/output_bench.py --exe ./$(BUILD)/beamrotor --json out/bench/output.json
	$(PY) tests/bench/study_bench.py --exe ./$(BUILD)/beamrotor --repeat $(BENCH_REPEAT) \
	  --json out/bench/study.json
	$(PY) tests/bench/compare.py out/bench

# The large frames (never part of `make test` or `make bench`; about 10 minutes and 6 GB):
# the building of 16 x 16 bays and 24 storeys (19,992 members, 99,960 elements, about 6x10^5
# dofs) against CalculiX once, and the one of 30 x 30 bays and 36 storeys (101,556 members,
# 5x10^5 elements, 3x10^6 dofs) by beamrotor alone (ccx would need about 25 GB); then the
# frame3d bench of 10^5 members (solve and write timed apart).
.PHONY: bench-large
bench-large: configure
	$(BUILD_EXE)
	@$(MAKE) --no-print-directory deps PACKAGES="$(BENCH_PACKAGES)"
	mkdir -p out/bench
	$(PY) tests/bench/frames_ccx.py --exe ./$(BUILD)/beamrotor --large \
	  --only building_16x16x24,building_30x30x36 --json out/bench/frames_ccx_large.json
	./$(BUILD)/beamrotor bench --kind frame3d --members 100000 --modes 0 --repeat 1 \
	  --json out/bench/frame3d_100000.json
	$(PY) tests/bench/compare.py out/bench

# What writing costs beside the solve, per shipped deck (also the end of `make bench`; about a
# minute): medians of 5 runs of `solve` per deck (solve and write seconds from the summary's
# cost line, CPU seconds of the run and its gnuplot processes), and per-point files of a
# 200-value sweep and a 1000-point study in points per second; out/bench/output.json.
.PHONY: bench-output
bench-output: configure
	$(BUILD_EXE)
	$(PY) tests/bench/output_bench.py --exe ./$(BUILD)/beamrotor --json out/bench/output.json

# Design-study throughput (never part of `make test`; a few minutes): the pump rod's
# stroke-and-wear grid of 10^5 points (all reactions and the largest stress per point, the
# closed-form checks at every point) serially, with --threads 2 and under mpirun -n 2; medians
# of 3 runs, parallel efficiency, memory per point, tables compared; out/bench/study.json.
.PHONY: bench-study
bench-study: configure
	$(BUILD_EXE)
	$(PY) tests/bench/study_bench.py --exe ./$(BUILD)/beamrotor --json out/bench/study.json

clean:
	rm -rf $(BUILD) out

# The verification report (never part of `make test`; a few minutes): out/report/index.html,
# one self-contained page with every shipped deck's checks, the convergence charts and the
# failure-case studies. Each deck's convergence study (`beamrotor converge`, its default
# quantity: the first that changes with the mesh or time step) runs first into
# out/report/convergence/<deck>/ (`report --converge`); a deck with nothing to converge (a
# mechanism given by closed forms) is skipped and named on the page; a study that fails stops
# the report. tests/verify/test_report.cpp runs the same command on two decks.
REPORT_DIR := out/report
.PHONY: report
report: configure
	$(BUILD_EXE)
	rm -rf $(REPORT_DIR) && mkdir -p $(REPORT_DIR)
	./$(BUILD)/beamrotor report --converge --out $(REPORT_DIR)

# Frames against a second method (never part of `make test`; about 15 seconds): the two-bay
# portal frame and the 3d base frame of tests/verify/frames/ written both as beamrotor decks and
# as CalculiX inputs (B31 beams, 32, 64 and 128 per member), solved by both, and their joint
# displacements, reactions and member end forces compared (after a self-test of the ccx file
# reader). Table on the terminal, JSON in out/verify/frames/; fails when a difference exceeds
# the tolerance that README.md there justifies.
VERIFY_FRAMES_PACKAGES := calculix-ccx
.PHONY: verify-frames
verify-frames: configure
	$(BUILD_EXE)
	@$(MAKE) --no-print-directory deps PACKAGES="$(VERIFY_FRAMES_PACKAGES)"
	$(PY) tests/verify/frames/test_ccx_results.py
	$(PY) tests/verify/frames/compare_frames.py --beamrotor ./$(BUILD)/beamrotor \
	  --out out/verify/frames tests/verify/frames/two_bay_frame.json \
	  tests/verify/frames/base_frame_3d.json

# Fuzz the deck reader and the command-line values (clang-14 + libFuzzer, ASan, UBSan),
# FUZZ_SECONDS each (default 10 minutes; never part of `make test`): fuzz_deck reads each input
# as a deck, builds its model when small and reads its design study; fuzz_options tries --set,
# --sweep (with units), expressions, --formulation, check quantities and the study options
# --sample, --sweep and --output (limits from either side). Seeds are the shipped decks, the
# malformed fixtures and tests/problems/fuzz_inputs/ (frames with releases, load cases and
# combinations, rotors on bearings, sampled and grid studies, option lines); new inputs collect
# in $(FUZZ_BUILD)/corpus-*, crashes in $(FUZZ_BUILD)/; each run ends with its statistics
# (executions, peak memory). Keep each finding, once fixed, as a fixture
# tests/problems/fuzz_inputs/finding_* (`make test` replays every file there).
FUZZ_BUILD   := build-fuzz
FUZZ_SECONDS ?= 600
FUZZ_FLAGS   := -max_len=8192 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
.PHONY: fuzz
fuzz:
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 \
	      -DBEAMROTOR_FUZZ=ON >/dev/null
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_deck fuzz_options
	mkdir -p $(FUZZ_BUILD)/corpus-deck $(FUZZ_BUILD)/seeds-deck $(FUZZ_BUILD)/corpus-options \
	         $(FUZZ_BUILD)/seeds-options
	cp problems/*.yaml tests/problems/malformed/*.yaml tests/problems/fuzz_inputs/*.deck \
	   $(FUZZ_BUILD)/seeds-deck/
	cp tests/problems/fuzz_inputs/*.options $(FUZZ_BUILD)/seeds-options/
	cd $(FUZZ_BUILD) && ./fuzz_deck corpus-deck seeds-deck -dict=../tests/problems/fuzz_deck.dict \
	      -max_total_time=$(FUZZ_SECONDS) $(FUZZ_FLAGS)
	cd $(FUZZ_BUILD) && ./fuzz_options corpus-options seeds-options \
	      -dict=../tests/problems/fuzz_options.dict -max_total_time=$(FUZZ_SECONDS) $(FUZZ_FLAGS)

# The slow hostile cases (never part of `make test`; a few minutes): a full device (a small
# tmpfs, mounted when run as root, else skipped with a note), signals while results are
# written, address-space limits (ulimit -v). The fast ones run in `make test`.
.PHONY: hostile
hostile: configure
	cmake --build $(BUILD) -j $(JOBS) --target beamrotor_tests
	./$(BUILD)/beamrotor_tests --test-suite='slow hostile*' --no-intro

# Mutation testing (never part of `make test`; about a minute per mutant on two cores): plants
# each single-line bug of tests/mutants/mutants.txt in turn in the source tree, rebuilds the
# one-object-per-source build $(MUTANT_BUILD) incrementally, runs the suite and puts the file
# back (also on Ctrl-C); prints killed/survived per mutant and the kill rate, writes
# out/mutants/summary.json, and fails when a mutant survives. MUTANTS=id1,id2 runs only those.
MUTANT_BUILD := build-mutants
MUTANTS      ?=
.PHONY: mutants
mutants: deps
	cmake -S . -B $(MUTANT_BUILD) -DCMAKE_BUILD_TYPE=Release -DBEAMROTOR_UNITY=OFF >/dev/null
	$(PY) tests/mutants/run_mutants.py --build $(MUTANT_BUILD) --out out/mutants --jobs $(JOBS) \
	  $(if $(MUTANTS),--only $(MUTANTS))
