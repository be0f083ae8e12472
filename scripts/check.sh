#!/usr/bin/env bash
# The full test job (CI runs it through .ci/run): installs the Debian packages, checks that
# every C++ source is formatted by the repository's .clang-format, then
#   1. builds everything with -Werror in double precision (build/), the tidesph Python module
#      among it, and runs every test, the browser test of tide serve (npm ci installs its
#      playwright-core first) and the module's pytest suite (/usr/bin/python3) among them;
#   2. builds and runs the tests in single precision (build-float/), but for seven long physics
#      studies whose bounds do not depend on the precision;
#   3. installs the double build and builds + runs examples/embed against the installed package;
#   4. builds the unit tests (target tide_unit_tests) with AddressSanitizer +
#      UndefinedBehaviorSanitizer (build-asan/) and runs them;
#   5. builds the scene-parser fuzzer with clang + ASan + UBSan (build-fuzz/) and fuzzes for 60 s
#      (docs/stability.md, "Bad input").
# Stops at the first failure. JOBS (default: nproc) sets the build and test parallelism;
# FUZZ_SECONDS (default: 60) how long the fuzzer runs.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
jobs="${JOBS:-$(nproc)}"

section() {
  printf '\n==== [%dm%02ds] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$*"
}

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

section "Dependencies"
bash scripts/install-deps.sh --browser

section "Browser test: playwright-core (npm ci, package-lock.json)"
# tests/browser/serve_test.mjs drives Debian's chromium with it; ctest runs it with the double build.
npm ci --no-audit --no-fund

section "Formatting (clang-format, .clang-format)"
git ls-files -z '*.cpp' '*.hpp' | xargs -0 clang-format --dry-run --Werror

section "Double precision, -Werror: configure and build (build/)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTIDE_REAL=double -DTIDE_WERROR=ON -DTIDE_SANITIZE= \
  -DTIDE_BUILD_PYTHON=ON
cmake --build build -j "$jobs"

section "Double precision: tests"
ctest --test-dir build --output-on-failure --no-tests=error -j "$jobs"

section "Single precision, -Werror: configure and build the tests (build-float/)"
# Without precompiled headers but for the test executables: the libraries, apps and tools keep
# GCC's -Warray-bounds and -Wstringop-overread, which the others leave out
# (cmake/TidePrecompiledHeaders.cmake), and are checked for including what they use. The tidesph
# Python module is built and tested in the double build only.
cmake -S . -B build-float -DCMAKE_BUILD_TYPE=Release -DTIDE_REAL=float -DTIDE_WERROR=ON -DTIDE_SANITIZE= \
  -DTIDE_BUILD_BENCH=OFF -DTIDE_PRECOMPILE_HEADERS=OFF -DTIDE_PRECOMPILE_TEST_HEADERS=ON -DTIDE_BUILD_PYTHON=OFF
cmake --build build-float -j "$jobs"

section "Single precision: tests"
# Every test but seven physics studies at test resolution that take 10-26 s each and whose bounds
# are the same in both precisions (about 100 s of the stage's 280 on a quiet machine): they run in
# double above. The studies with single-precision bounds of their own (the floating box, the lid-
# driven cavity at Re = 100, Taylor-Green, ...) and the rest of the validation label run here.
double_only='^(ValidationCases\.(SettlingCylinderMeetsFaxensDrag|DamBreak3DWallPressureAtLowResolution|'
double_only+='DamBreakWallPressureFollowsBuchner|LidDrivenCavityRe1000|NeutrallyBuoyantBodiesStayNearWhereTheyAreLetGo)|'
double_only+='CrowdCorridor\.MeanSpeedFallsWithDensity|IncompressibleHydrostatic\.Tank3DHoldsHydrostaticPressureIisph)$'
ctest --test-dir build-float --output-on-failure --no-tests=error -j "$jobs" -E "$double_only"

section "Install the double build and build examples/embed against it"
cmake --install build --prefix "$scratch/prefix"
cmake -S examples/embed -B "$scratch/embed" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror"
cmake --build "$scratch/embed" -j "$jobs"

section "Run examples/embed"
"$scratch/embed/embed"

section "AddressSanitizer + UndefinedBehaviorSanitizer: configure and build the unit tests (build-asan/)"
# Without -Werror: GCC's sanitizer instrumentation raises false -Wmaybe-uninitialized and
# -Wstringop-* warnings; the builds above already hold the code to -Werror. -O1 with line tables
# (and NDEBUG, as the other builds): the optimisation level the sanitizers recommend; the
# profiling build's -O3 -g (RelWithDebInfo) took 3.5x the compile time and 2.7x the memory per
# file (the WCSPH scheme, then one file: 360 s and 4.7 GB against 104 s and 1.8 GB).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1 -DNDEBUG" \
  -DTIDE_SANITIZE=address,undefined -DTIDE_WERROR=OFF -DTIDE_BUILD_BENCH=OFF -DTIDE_BUILD_APPS=OFF \
  -DTIDE_BUILD_PYTHON=OFF
cmake --build build-asan -j "$jobs" --target tide_unit_tests

section "AddressSanitizer + UndefinedBehaviorSanitizer: unit tests"
ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=1:strict_init_order=1}" \
  UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}" \
  ctest --test-dir build-asan --output-on-failure --no-tests=error -j "$jobs" -L unit

section "libFuzzer, clang + AddressSanitizer + UndefinedBehaviorSanitizer: configure and build (build-fuzz/)"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DTIDE_BUILD_FUZZERS=ON -DTIDE_SANITIZE=address,undefined -DTIDE_WERROR=ON \
  -DTIDE_BUILD_TESTS=OFF -DTIDE_BUILD_BENCH=OFF -DTIDE_BUILD_APPS=OFF -DTIDE_BUILD_PYTHON=OFF
cmake --build build-fuzz -j "$jobs" --target scene_parser_fuzzer

fuzz_seconds="${FUZZ_SECONDS:-60}"
section "libFuzzer: the scene parser for ${fuzz_seconds} s"
# The fuzzer adds what it learns to the corpus it is given: give it a copy. A failing input is
# kept in build-fuzz/check-findings/ and printed as Base64, for fuzz/regressions/.
findings=build-fuzz/check-findings
rm -rf "$findings" && mkdir -p "$findings" "$scratch/corpus"
cp scenes/*.json fuzz/corpus/* "$scratch/corpus/"
# Each input must be answered within 5 s and 1 GiB (docs/stability.md, "Bad input"): -timeout
# is the per-input time, -rss_limit_mb the whole process's memory and -malloc_limit_mb the largest
# single allocation; exceeding any is a finding.
if ! build-fuzz/fuzz/scene_parser_fuzzer -max_total_time="$fuzz_seconds" -timeout=5 -rss_limit_mb=1024 \
  -malloc_limit_mb=1024 -max_len=4096 -dict=fuzz/scene.dict -artifact_prefix="$findings/" -print_final_stats=1 \
  "$scratch/corpus" >"$scratch/fuzz.log" 2>&1; then
  tail -n 80 "$scratch/fuzz.log"
  for input in "$findings"/*; do
    [[ -f "$input" ]] && printf '%s, as Base64:\n%s\n' "$input" "$(base64 -w 0 "$input")"
  done
  echo "check: the scene-parser fuzzer found an input that crashes, hangs or trips a sanitizer" >&2
  exit 1
fi
grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)' "$scratch/fuzz.log"

section "All checks passed"
