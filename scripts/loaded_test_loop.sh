#!/usr/bin/env bash
# make test N times in a row on a fresh clone, with a CPU-heavy process beside it (docs/benchmarks.md,
# "Set-up and test times"). Usage: scripts/loaded_test_loop.sh [REPO] [N] [WORKDIR]
# Each run's log is WORKDIR/run_K.log; one line per run (exit status, seconds, load, pytest's summary)
# goes to WORKDIR/summary.txt.
set -u
repo=${1:-$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)}
n=${2:-10}
work=${3:-$(mktemp -d)}
git clone -q "$repo" "$work/clone" || exit 2
cd "$work/clone" || exit 2
python3 -c "while True: pass" &
burner=$!
trap 'kill $burner 2>/dev/null' EXIT
echo "start $(date -u) commit $(git rev-parse --short HEAD)" >> "$work/summary.txt"
for i in $(seq 1 "$n"); do
  start=$(date +%s)
  make test > "$work/run_$i.log" 2>&1
  rc=$?
  echo "run $i rc=$rc $(( $(date +%s) - start ))s load=$(cut -d' ' -f1-3 /proc/loadavg) $(tail -1 "$work/run_$i.log")" \
    >> "$work/summary.txt"
done
echo "end $(date -u)" >> "$work/summary.txt"
cat "$work/summary.txt"
