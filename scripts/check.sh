#!/usr/bin/env bash
# The full test job (CI runs it through .ci/run): installs the Debian packages, checks that
# every C++ source is formatted by the repository's .clang-format, then
#   1. builds everything with -Werror in double precision (build/) and runs every test;
#   2. builds and runs the tests in single precision (build-float/);
#   3. installs the double build and builds + runs examples/embed against the installed package;
#   4. builds the unit tests with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/)
#      and runs them.
# Stops at the first failure. JOBS (default: nproc) sets the build and test parallelism.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
jobs="${JOBS:-$(nproc)}"

section() {
  printf '\n==== [%dm%02ds] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$*"
}

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

section "Dependencies"
bash scripts/install-deps.sh

section "Formatting (clang-format, .clang-format)"
git ls-files -z '*.cpp' '*.hpp' | xargs -0 clang-format --dry-run --Werror

section "Double precision, -Werror: configure and build (build/)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DTIDE_REAL=double -DTIDE_WERROR=ON -DTIDE_SANITIZE=
cmake --build build -j "$jobs"

section "Double precision: tests"
ctest --test-dir build --output-on-failure --no-tests=error -j "$jobs"

section "Single precision, -Werror: configure and build the tests (build-float/)"
cmake -S . -B build-float -DCMAKE_BUILD_TYPE=Release -DTIDE_REAL=float -DTIDE_WERROR=ON -DTIDE_SANITIZE= \
  -DTIDE_BUILD_BENCH=OFF
cmake --build build-float -j "$jobs"

section "Single precision: tests"
ctest --test-dir build-float --output-on-failure --no-tests=error -j "$jobs"

section "Install the double build and build examples/embed against it"
cmake --install build --prefix "$scratch/prefix"
cmake -S examples/embed -B "$scratch/embed" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$scratch/prefix" \
  -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wpedantic -Werror"
cmake --build "$scratch/embed" -j "$jobs"

section "Run examples/embed"
"$scratch/embed/embed"

section "AddressSanitizer + UndefinedBehaviorSanitizer: configure and build the unit tests (build-asan/)"
# Without -Werror: GCC's sanitizer instrumentation raises false -Wmaybe-uninitialized and
# -Wstringop-* warnings; the builds above already hold the code to -Werror.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTIDE_SANITIZE=address,undefined -DTIDE_WERROR=OFF \
  -DTIDE_BUILD_BENCH=OFF -DTIDE_BUILD_APPS=OFF
cmake --build build-asan -j "$jobs"

section "AddressSanitizer + UndefinedBehaviorSanitizer: unit tests"
ASAN_OPTIONS="${ASAN_OPTIONS:-detect_stack_use_after_return=1:strict_init_order=1}" \
  UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}" \
  ctest --test-dir build-asan --output-on-failure --no-tests=error -j "$jobs" -L unit

section "All checks passed"
