#!/bin/sh
# A sampled pump-rod study run serially and under `mpirun -n 2`: study.csv and summary.json
# must agree byte for byte (ranks share the points; rank 0 restores their order), but for the
# rank count the summary states; `solve`
# under mpirun -n 2 must refuse. Skipped
# (exit 77, with the reason) where mpirun is missing. Arguments: the beamrotor executable and
# the source directory.
exe=$1
src=$2
if ! command -v mpirun >/dev/null 2>&1; then
  echo "SKIPPED: mpirun not found (install openmpi-bin to run the MPI study test)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
set -- study "$src/problems/pump_rod.yaml" --sample 'w0=normal(1e-3,0.2e-3,0,2e-3)' \
  --sample 'eta=uniform(0,0.4)' --samples 200 --seed 9 --output 'stress max <= 60 MPa' \
  --output 'reaction middle uy'
"$exe" "$@" --out "$tmp/serial" >"$tmp/serial.txt" 2>&1 || { cat "$tmp/serial.txt"; exit 1; }
mpirun --allow-run-as-root --oversubscribe -n 2 "$exe" "$@" --out "$tmp/mpi" \
  >"$tmp/mpi.txt" 2>&1 || { echo "mpirun failed:"; cat "$tmp/mpi.txt"; exit 1; }
status=0
# summary.json states the rank count ("ranks": 1 and 2); all else is identical.
for run in serial mpi; do
  grep -v '^  "ranks": ' "$tmp/$run/summary.json" >"$tmp/$run/summary-without-ranks.json"
done
grep -Eqx '  "ranks": 1,?' "$tmp/serial/summary.json" || { echo "serial summary: not 1 rank"; status=1; }
grep -Eqx '  "ranks": 2,?' "$tmp/mpi/summary.json" || { echo "mpirun -n 2 summary: not 2 ranks"; status=1; }
for f in study.csv summary-without-ranks.json; do
  if cmp -s "$tmp/serial/$f" "$tmp/mpi/$f"; then
    echo "$f: identical (serial and mpirun -n 2)"
  else
    echo "$f differs between the serial run and mpirun -n 2:"
    diff "$tmp/serial/$f" "$tmp/mpi/$f" | head -20
    status=1
  fi
done
# Both ranks took part: the table has every point once.
rows=$(($(grep -vc '^#' "$tmp/mpi/study.csv") - 1))  # less the names (and the units line)
[ "$rows" -eq 200 ] || { echo "expected 200 rows, got $rows"; status=1; }
# Any other command under mpirun refuses once (rank 0 says why, naming `study`), exit 2,
# rather than solving the deck once per rank into one results directory.
mpirun --allow-run-as-root --oversubscribe -n 2 "$exe" solve "$src/problems/cantilever.yaml" \
  --out "$tmp/solve" >"$tmp/solve.txt" 2>&1 && { echo "solve under mpirun -n 2 ran"; status=1; }
said=$(grep -c "only \`beamrotor study\` shares its points among MPI ranks" "$tmp/solve.txt")
[ "$said" -eq 1 ] || { echo "expected the refusal once, got $said times:"; cat "$tmp/solve.txt"; status=1; }
[ ! -e "$tmp/solve" ] || { echo "solve under mpirun wrote results"; status=1; }
exit $status
