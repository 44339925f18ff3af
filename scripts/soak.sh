#!/usr/bin/env bash
# The readers' mutation campaign (issue 29 item 6): COUNT mutated .brep and STEP files (default 3000) made from
# real files (fuzz/corpus/fuzz_read_brep, fuzz/corpus/fuzz_read_step and tests/corpus/freecad, the findings'
# regression_* files left out) by fuzz/model_file_mutation.hpp, each read in a process of its own by
# build/tests/reliability/reliability_soak_readers (tests/reliability/soak_readers.cpp says what is counted).
# Prints the counts per format; exits non-zero on any crash, hang past the Ctrl-C latency, inconsistent solid or
# stray exception, leaving each such file in build/soak-findings/. Not part of scripts/test.sh (minutes long).
# Then the big randomized round-trip run: ROUND_TRIPS cases per shard of reliability_round_trip_tests (default
# 1000: cases 0 to 9,999 of the same seeds, where the test command runs 0 to 999).
# Usage: bash scripts/soak.sh [COUNT] [FIRST_SEED]   (ROUND_TRIPS=0 skips the round trips)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
exec </dev/null

count="${1:-3000}"
first="${2:-0}"
build="${RATBEZ_BUILD:-build}"
cmake --build "$build" -j "${RATBEZ_JOBS:-2}" --target reliability_soak_readers >/dev/null

seeds="$(mktemp -d)"
trap 'rm -rf "$seeds"' EXIT
for f in fuzz/corpus/fuzz_read_brep/* fuzz/corpus/fuzz_read_step/* tests/corpus/freecad/*.brep tests/corpus/freecad/*.step; do
  case "$(basename "$f")" in regression_*) continue ;; esac
  # Files over 64 KB make each read slow without finding more: the campaign mutates the small ones.
  [ "$(stat -c %s "$f")" -le 65536 ] || continue
  cp "$f" "$seeds/$(basename "$(dirname "$f")")_$(basename "$f")"
done
echo "== soak: $count mutations of $(ls "$seeds" | wc -l) real files (first seed $first)"
start=$(date +%s)
set +e
"$build/tests/reliability/reliability_soak_readers" "$count" "$seeds" "$build/soak-findings" "$first" 2>"$build/soak-stderr.txt"
rc=$?
set -e
echo "== soak: $(( $(date +%s) - start )) s; findings (if any) in $build/soak-findings/"

round_trips="${ROUND_TRIPS:-1000}"
if [ "$round_trips" -gt 0 ]; then
  cmake --build "$build" -j "${RATBEZ_JOBS:-2}" --target reliability_round_trip_tests >/dev/null
  echo "== round trips: 10 shards of $round_trips cases"
  start=$(date +%s)
  if ! RATBEZ_ROUND_TRIP_CASES="$round_trips" ctest --test-dir "$build" -j "${RATBEZ_JOBS:-2}" \
       -R '^Reliability/RoundTrip\.Shard/' --output-on-failure; then
    rc=1
  fi
  echo "== round trips: $(( $(date +%s) - start )) s"
fi
exit "$rc"
