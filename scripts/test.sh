#!/usr/bin/env bash
# Every test: the Release build of build/ with all suites (C++ core/occt/openscad/cli/reliability, Python,
# FreeCAD headless and GUI, the OpenSCAD binary), then the C++ suites again in build-asan under
# AddressSanitizer and UndefinedBehaviorSanitizer (Python and FreeCAD stay out: ASan cannot be preloaded
# into them), then every libFuzzer target for a bounded time (scripts/fuzz.sh).
# Runs unattended (CI=true, no stdin); exits non-zero when anything fails.
# Run as root on Debian 12: bash scripts/test.sh
# (RATBEZ_BUILD_DIR and RATBEZ_ASAN_DIR override build/ and build-asan/, RATBEZ_JOBS the -j 2.)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
exec </dev/null

jobs="${RATBEZ_JOBS:-2}"
build="${RATBEZ_BUILD_DIR:-build}"
asan="${RATBEZ_ASAN_DIR:-build-asan}"
export RATBEZ_BUILD_DIR="$build"
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
export QTWEBENGINE_DISABLE_SANDBOX=1
logs="$build/test-logs"
status=0

bash scripts/setup.sh
mkdir -p "$logs"

echo "== ctest: Release build ($build/)"
ctest --test-dir "$build" --output-on-failure -j "$jobs" 2>&1 | tee "$logs/release.txt" || status=1

echo "== sanitizers: Debug build with ASan + UBSan ($asan/), C++ suites only"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
cmake -S . -B "$asan" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DRATBEZ_SANITIZE=ON \
  -DRATBEZ_WITH_PYTHON=OFF -DRATBEZ_TEST_FREECAD=OFF -DRATBEZ_TEST_OPENSCAD=OFF -DRATBEZ_BUILD_BENCH=OFF >/dev/null
if cmake --build "$asan" -j "$jobs"; then
  ctest --test-dir "$asan" --output-on-failure -j "$jobs" 2>&1 | tee "$logs/asan.txt" || status=1
else
  echo "test.sh: the sanitizer build failed" | tee "$logs/asan.txt"
  status=1
fi

echo "== fuzzing: each libFuzzer target for a bounded time (scripts/fuzz.sh)"
if ! bash scripts/fuzz.sh "${RATBEZ_FUZZ_SECONDS:-20}" 2>&1 | tee "$logs/fuzz.txt"; then
  echo "test.sh: fuzzing found a problem (see $logs/fuzz.txt)"
  status=1
fi

# One closing line for both runs, from ctest's own "N% tests passed, F tests failed out of T" lines.
passed=0 failed=0
for log in "$logs/release.txt" "$logs/asan.txt"; do
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1 || true)
  if [ -z "$line" ]; then
    echo "test.sh: no ctest summary in $log"
    status=1
    continue
  fi
  f=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  t=$(sed -E 's/.* failed out of ([0-9]+).*/\1/' <<<"$line")
  passed=$((passed + t - f))
  failed=$((failed + f))
done
[ "$failed" -eq 0 ] || status=1
[ "$passed" -gt 0 ] || status=1
echo "ratbez: $passed passed, $failed failed"
exit "$status"
