#!/usr/bin/env bash
# Builds the libFuzzer targets under fuzz/ with clang (ASan + UBSan + coverage, in build-fuzz/) and runs
# each for a bounded time on a COPY of its seed corpus (fuzz/corpus/<target>/ is never modified).
# Fails on any crash, leak, timeout, out-of-memory or sanitizer report, and prints how many inputs each
# target executed. A crashing input is left in build-fuzz/findings/<target>/ (crash-*, leak-*, ...):
# turn it into a regression test in tests/reliability (see fuzz/README.md).
# Usage: bash scripts/fuzz.sh [SECONDS_PER_TARGET (default 20)] [TARGET ...]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
exec </dev/null

seconds="${1:-20}"
shift || true
targets=("$@")
[ "${#targets[@]}" -gt 0 ] || targets=(fuzz_spec fuzz_geometry fuzz_mesh fuzz_output fuzz_read_brep fuzz_read_step)
jobs="${RATBEZ_JOBS:-2}"
build=build-fuzz
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1

CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRATBEZ_BUILD_FUZZERS=ON -DRATBEZ_BUILD_TESTS=OFF -DRATBEZ_BUILD_BENCH=OFF \
  -DRATBEZ_WITH_PYTHON=OFF -DRATBEZ_TEST_FREECAD=OFF -DRATBEZ_TEST_OPENSCAD=OFF >/dev/null
cmake --build "$build" -j "$jobs" --target "${targets[@]}"

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:allocator_may_return_null=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
summary=()
for target in "${targets[@]}"; do
  work="$build/fuzz-run/$target"
  findings="$build/findings/$target"
  rm -rf "$work" "$findings"
  mkdir -p "$work/corpus" "$findings"
  cp fuzz/corpus/"$target"/* "$work/corpus/"
  dict=()
  [ -f "fuzz/$target.dict" ] && dict=(-dict="fuzz/$target.dict")
  echo "== $target: ${seconds}s on a copy of fuzz/corpus/$target ($(ls "$work/corpus" | wc -l) seeds)"
  # The readers' inputs are whole model files (their seeds up to ~9 KB, mutated longer); the others' 4 KB.
  max_len=4096
  case "$target" in fuzz_read_*) max_len=65536 ;; esac
  set +e
  "$build/fuzz/$target" "$work/corpus" "${dict[@]}" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
    -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$findings/" >"$work/log.txt" 2>&1
  rc=$?
  set -e
  runs=$(grep -E '^stat::number_of_executed_units:' "$work/log.txt" | awk '{print $2}' | tail -n 1)
  runs="${runs:-?}"
  if [ "$rc" -ne 0 ] || ls "$findings" | grep -q .; then
    echo "fuzz.sh: $target FAILED (exit $rc) after $runs inputs; findings in $findings:"
    ls "$findings" | sed 's/^/  /'
    grep -E 'ERROR|SUMMARY|runtime error|invariant broken|terminate|deadly' "$work/log.txt" | head -n 20 | sed 's/^/  /'
    echo "  full log: $work/log.txt"
    summary+=("$target: FAILED after $runs inputs")
    status=1
  else
    echo "$target: $runs inputs, no crash"
    summary+=("$target: $runs inputs, ok")
  fi
done

echo "== fuzz summary"
printf '  %s\n' "${summary[@]}"
exit "$status"
