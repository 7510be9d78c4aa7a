#!/bin/sh
# A study under `mpirun -n 2` that loses a rank (kill -9 of rank 1) or is stopped (SIGTERM to
# mpirun, which sends SIGCONT to every rank, SIGTERM some seconds later and SIGKILL as long
# after that): rank 0 keeps the rows done, writes a summary marked partial that states the
# rank count (and names the lost rank, as the console does), and `--resume` under mpirun
# writes the serial run's table byte for byte; a `--resume` that rank 0 refuses ends (exit 2)
# instead of leaving rank 1 waiting. Skipped (exit 77, with the reason) where mpirun is
# missing. Arguments: the beamrotor executable and the source directory. No speed is asserted,
# but every wait has a deadline: one that passes says what it waited for, shows the processes
# (state, where each sleeps in the kernel) and the run's console, ends them and fails.
exe=$1
src=$2
if ! command -v mpirun >/dev/null 2>&1; then
  echo "SKIPPED: mpirun not found (install openmpi-bin to run the MPI signal test)"
  exit 77
fi
tmp=$(mktemp -d)
runner=""  # the run going on in the background (mpirun, or the serial study)
trap 'end_run; rm -rf "$tmp"' EXIT
trap 'exit 1' HUP INT TERM
mpi="mpirun --allow-run-as-root --oversubscribe -n 2"
# mpirun's pause between SIGCONT, SIGTERM and SIGKILL (1 s by default): rank 0 writes its
# partial results and console between SIGTERM and SIGKILL, and on a machine loaded by a whole
# test run one second was measured too short (1 run in 5 beside busy loops lost the console).
# Open MPI 4.1 reads the first name; the second is for PRRTE (Open MPI 5), assuming it kept
# the parameter's name; a launcher that knows neither ignores them.
export OMPI_MCA_odls_base_sigkill_timeout=3 PRTE_MCA_odls_base_sigkill_timeout=3
status=0
fail() { echo "$1"; status=1; }
now() { date +%s; }

# The state of process $1 (R running, S sleeping, T stopped, Z ended but not reaped, ...);
# empty once it is gone.
state() { sed -n 's/^.*) \(.\).*$/\1/p' "/proc/$1/stat" 2>/dev/null; }
running() { case $(state "$1") in "" | Z) return 1 ;; esac; }

# The run $runner and its children (mpirun's ranks), by pid.
run_pids() { [ -n "$runner" ] && echo "$runner" $(pgrep -P "$runner"); }

show_run() {
  for p in $(run_pids); do
    wchan=$(cat "/proc/$p/wchan" 2>/dev/null)
    [ "$wchan" != 0 ] || wchan="(on a CPU)"
    echo "  pid $p state $(state "$p") waiting in $wchan:" \
      "$(tr '\0' ' ' <"/proc/$p/cmdline" 2>/dev/null | cut -c1-160)"
    sed 's/^/    /' "/proc/$p/stack" 2>/dev/null | head -8
  done
}

# Ends the run in the background, if any (its ranks first, then mpirun), by pid.
end_run() {
  [ -n "$runner" ] || return 0
  for p in $(pgrep -P "$runner") "$runner"; do kill -KILL "$p" 2>/dev/null; done
  wait "$runner" 2>/dev/null
  runner=""
}

# A wait that ran out ($1 says for what): the processes, the run's console ($2), then failure.
timed_out() {
  echo "FAILED: $1"
  echo "the run's processes:"
  show_run
  echo "its console ($2):"
  cat "$2"
  exit 1
}

# Starts "$@" in the background as the run, its console (stdout and stderr) into $console.
start() {
  "$@" >"$console" 2>&1 &
  runner=$!
}

# Waits at most $1 s for the run to end ($2 names it); its exit status in $code.
await_end() {
  until=$(($(now) + $1))
  while running "$runner"; do
    [ "$(now)" -lt "$until" ] || timed_out "$2 did not end within $1 s" "$console"
    sleep 0.05
  done
  wait "$runner"
  code=$?
  runner=""
}

# The rows a study writing $1 has written into its temporary directory (or its results).
rows_of() { cat "$1".tmp-*/study.csv 2>/dev/null | grep -vc '^#'; }

# Waits at most 60 s until the study writing $1 has 20 rows; fails when it ends first.
await_rows() {
  until=$(($(now) + 60))
  while [ "$(rows_of "$1")" -le 20 ]; do
    running "$runner" || { echo "FAILED: the study writing $1 ended before it had 20 rows:";
                           cat "$console"; exit 1; }
    [ "$(now)" -lt "$until" ] || timed_out "no 20 rows in $1.tmp-*/study.csv within 60 s" "$console"
    sleep 0.01
  done
}

# Waits at most 60 s until the table of the study writing $1 stays the same for 2 s (rank 0
# waits for the rows of the chunk a stopped rank holds) or has every row (one per point of
# $points, and the names); its rows in $rows.
await_still() {
  until=$(($(now) + 60))
  before=-1
  rows=$(rows_of "$1")
  while [ "$rows" -le "$points" ] && [ "$rows" -ne "$before" ]; do
    [ "$(now)" -lt "$until" ] ||
      timed_out "the table of $1 still grew 60 s after rank 1 was stopped" "$console"
    before=$rows
    sleep 2
    rows=$(rows_of "$1")
  done
}

# The pid of rank $1 among the children of the run (mpirun).
rank_pid() {
  for p in $(pgrep -P "$runner"); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1"; then
      echo "$p"
      return
    fi
  done
}

# A JSON key of a summary, with python3.
key() {
  python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get(sys.argv[2]))" "$1" "$2"
}

# Checks the partial results in $2 of the run described by $1 (its console in $2.txt):
# summary.json marked partial, stopped by SIGTERM, stating 2 ranks; false when there is none.
partial_results() {
  summary="$2/summary.json"
  if [ ! -f "$summary" ]; then
    fail "$1: no summary.json; the run said:"
    cat "$2.txt"
    return 1
  fi
  [ "$(key "$summary" partial)" = "True" ] || fail "$1: summary not partial"
  [ "$(key "$summary" stopped_by)" = "SIGTERM" ] || fail "$1: not stopped by SIGTERM"
  [ "$(key "$summary" ranks)" = "2" ] || fail "$1: summary does not say 2 ranks"
  grep -q "ranks: 2" "$2.txt" ||
    { fail "$1: console does not state the rank count:"; cat "$2.txt"; }
  echo "$1: $(($(grep -vc '^#' "$2/study.csv") - 1)) rows kept"
}

set -- study "$src/problems/pump_rod.yaml" --sweep eta=0:0.4:39 --sweep w0=0.5e-3:1.5e-3:200
points=8040
console="$tmp/serial.txt"
start "$exe" "$@" --out "$tmp/serial"
await_end 120 "the serial study"
[ "$code" -eq 0 ] || { echo "the serial study failed (exit $code):"; cat "$console"; exit 1; }

# 1. kill -9 of rank 1, while it holds points: stopped (SIGSTOP) first, rank 1 keeps the
# chunk it was given, so rank 0's in-order table stops short of it. Rank 1 may not have asked
# for points yet (rank 0 is then alone and writes every row): it is let go and the study run
# again, at most three times.
for attempt in 1 2 3; do
  rm -rf "$tmp/killed" "$tmp"/killed.tmp-*
  console="$tmp/killed.txt"
  start $mpi "$exe" "$@" --out "$tmp/killed"
  await_rows "$tmp/killed"
  victim=$(rank_pid 1)
  [ -n "$victim" ] || timed_out "rank 1 not found among mpirun's children" "$console"
  kill -STOP "$victim"
  await_still "$tmp/killed"
  [ "$rows" -le "$points" ] && break
  echo "attempt $attempt: rank 1 had no points yet when stopped; rank 0 wrote every row alone"
  kill -CONT "$victim"
  await_end 60 "the study whose rank 1 was let go"
  [ "$attempt" -lt 3 ] || { echo "FAILED: rank 1 never held points in three attempts"; exit 1; }
done
kill -9 "$victim"
await_end 60 "mpirun after the kill -9 of rank 1"
if partial_results "kill -9 of rank 1" "$tmp/killed"; then
  key "$summary" lost_ranks | grep -q "rank 1 (pid $victim" ||
    fail "kill -9 of rank 1: summary does not name it: $(key "$summary" lost_ranks)"
  grep -q "lost rank 1 (pid $victim" "$tmp/killed.txt" ||
    { fail "kill -9 of rank 1: console does not name it:"; cat "$tmp/killed.txt"; }
  console="$tmp/resumed.txt"
  start $mpi "$exe" "$@" --resume "$tmp/killed"
  await_end 120 "--resume under mpirun"
  [ "$code" -eq 0 ] || { fail "--resume failed (exit $code):"; cat "$console"; }
  if cmp -s "$tmp/serial/study.csv" "$tmp/killed/study.csv"; then
    echo "study.csv after --resume under mpirun -n 2: identical to the serial run's"
  else
    fail "study.csv after --resume differs from the serial run's"
  fi
  # Now complete: a second --resume is refused on rank 0 alone, and every rank ends (exit 2).
  console="$tmp/refused.txt"
  start $mpi "$exe" "$@" --resume "$tmp/killed"
  await_end 60 "a --resume that rank 0 refuses, under mpirun"
  [ "$code" -eq 2 ] || { fail "the refused --resume ended with $code, not 2:"; cat "$console"; }
  grep -q "no partial study there" "$console" ||
    { fail "the refused --resume did not say why:"; cat "$console"; }
fi

# 2. SIGTERM to mpirun, on a grid ten times larger: the 8040 points above can all be solved
# (about 2 s on two ranks) while mpirun passes the signal on.
console="$tmp/stopped.txt"
start $mpi "$exe" study "$src/problems/pump_rod.yaml" --sweep eta=0:0.4:399 \
  --sweep w0=0.5e-3:1.5e-3:200 --out "$tmp/stopped"
await_rows "$tmp/stopped"
kill -TERM "$runner"
await_end 60 "mpirun after its SIGTERM"
partial_results "SIGTERM to mpirun" "$tmp/stopped"
exit $status
