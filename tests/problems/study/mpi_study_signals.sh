#!/bin/sh
# A study under `mpirun -n 2` that loses a rank (kill -9 of rank 1) or is stopped (SIGTERM to
# mpirun, which passes it to every rank and kills them a second later): rank 0 keeps the rows
# done, writes a summary marked partial that states the rank count (and names the lost rank,
# as the console does), and `--resume` under mpirun writes the serial run's table byte for
# byte. Skipped (exit 77, with the reason) where mpirun is missing. Arguments: the beamrotor
# executable and the source directory. Waits are generous; no speed is asserted.
exe=$1
src=$2
if ! command -v mpirun >/dev/null 2>&1; then
  echo "SKIPPED: mpirun not found (install openmpi-bin to run the MPI signal test)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpi="mpirun --allow-run-as-root --oversubscribe -n 2"
set -- study "$src/problems/pump_rod.yaml" --sweep eta=0:0.4:39 --sweep w0=0.5e-3:1.5e-3:200
"$exe" "$@" --out "$tmp/serial" >"$tmp/serial.txt" 2>&1 || { cat "$tmp/serial.txt"; exit 1; }
status=0
fail() { echo "$1"; status=1; }

# Waits (at most 60 s) until the study writing $1 has 20 rows; fails otherwise.
await_rows() {
  for _ in $(seq 6000); do
    rows=$(cat "$1".tmp-*/study.csv 2>/dev/null | grep -vc '^#')
    [ "$rows" -gt 20 ] && return 0
    sleep 0.01
  done
  echo "no rows in $1.tmp-*/study.csv within 60 s"
  return 1
}

# The pid of rank $2 among the children of mpirun $1.
rank_pid() {
  for p in $(pgrep -P "$1"); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
      echo "$p"
      return
    fi
  done
}

# A JSON key of a summary, with python3.
key() { python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get(sys.argv[2]))" "$1" "$2"; }

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
  grep -q "ranks: 2" "$2.txt" || fail "$1: console does not state the rank count"
  echo "$1: $(($(grep -vc '^#' "$2/study.csv") - 1)) rows kept"
}

# 1. kill -9 of rank 1.
$mpi "$exe" "$@" --out "$tmp/killed" >"$tmp/killed.txt" 2>&1 &
runner=$!
await_rows "$tmp/killed" || exit 1
victim=$(rank_pid "$runner" 1)
[ -n "$victim" ] || { echo "rank 1 not found among mpirun's children"; exit 1; }
kill -9 "$victim"
wait "$runner"
if partial_results "kill -9 of rank 1" "$tmp/killed"; then
  key "$summary" lost_ranks | grep -q "rank 1 (pid $victim" ||
    fail "kill -9 of rank 1: summary does not name it: $(key "$summary" lost_ranks)"
  grep -q "lost rank 1 (pid $victim" "$tmp/killed.txt" || fail "kill -9 of rank 1: console does not name it"
  $mpi "$exe" "$@" --resume "$tmp/killed" >"$tmp/resumed.txt" 2>&1 || { fail "--resume failed:"; cat "$tmp/resumed.txt"; }
  if cmp -s "$tmp/serial/study.csv" "$tmp/killed/study.csv"; then
    echo "study.csv after --resume under mpirun -n 2: identical to the serial run's"
  else
    fail "study.csv after --resume differs from the serial run's"
  fi
fi

# 2. SIGTERM to mpirun, on a grid ten times larger: the 8040 points above can all be solved
# (about 2 s on two ranks) while mpirun passes the signal on.
$mpi "$exe" study "$src/problems/pump_rod.yaml" --sweep eta=0:0.4:399 --sweep w0=0.5e-3:1.5e-3:200 \
  --out "$tmp/stopped" >"$tmp/stopped.txt" 2>&1 &
runner=$!
await_rows "$tmp/stopped" || exit 1
kill -TERM "$runner"
wait "$runner"
partial_results "SIGTERM to mpirun" "$tmp/stopped"
exit $status
