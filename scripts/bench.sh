#!/bin/sh
# The benchmark suite in one command: builds step_bench and neighbor_bench in double and float
# (Release) and memory_report in double, runs them into bench/results/*.json and writes
# docs/performance.md from those files.
#
#   scripts/bench.sh             build, run everything (about an hour on 2 cores), write the page
#   scripts/bench.sh --report    only rewrite docs/performance.md from bench/results/*.json
#
# Environment: TIDE_ARCH (-march of the builds, default native: the vectorised pair loops need
# AVX2 or wider), TIDE_BENCH_BUILD (build folder prefix, default build-bench), TIDE_BENCH_REPETITIONS
# (default 3), TIDE_BENCH_HUGE=1 (adds the 3D 10^7-particle rows: ~12 GB, run on a quiet machine).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
results="$root/bench/results"
# The first Python that has matplotlib (a pyenv shim may shadow the system's).
report() {
  for python in ${PYTHON:-} python3 /usr/bin/python3; do
    if "$python" -c 'import matplotlib' 2>/dev/null; then
      "$python" "$root/scripts/performance_report.py" "$results" "$root/docs/performance.md"
      return
    fi
  done
  echo "bench.sh: no python3 with matplotlib (set PYTHON)" >&2
  return 1
}
if [ "${1:-}" = "--report" ]; then
  report
  exit 0
fi

prefix=${TIDE_BENCH_BUILD:-$root/build-bench}
repetitions=${TIDE_BENCH_REPETITIONS:-3}
for real in double float; do
  cmake -S "$root" -B "$prefix-$real" -DCMAKE_BUILD_TYPE=Release -DTIDE_REAL=$real -DTIDE_BUILD_TESTS=OFF \
    -DTIDE_BUILD_APPS=OFF -DTIDE_ARCH="${TIDE_ARCH:-native}" >/dev/null
  cmake --build "$prefix-$real" -j2 --target step_bench neighbor_bench
done
cmake --build "$prefix-double" -j2 --target memory_report

run() {  # binary, output name, extra arguments
  binary=$1
  name=$2
  shift 2
  "$binary" --benchmark_repetitions="$repetitions" --benchmark_out="$results/$name.json" \
    --benchmark_out_format=json "$@"
}
mkdir -p "$results"
run "$prefix-double/bench/step_bench" step_bench_double
# Float: the rows the targets quote (the reference scene and the 3D WCSPH steps).
run "$prefix-float/bench/step_bench" step_bench_float --benchmark_filter='BM_Reference3D|BM_Step/wcsph/3D'
run "$prefix-double/bench/neighbor_bench" neighbor_bench_double
# Target 4's bytes per particle, with the default skin and with lists rebuilt every step.
"$prefix-double/bench/memory_report" --particles 1000000 --json "$results/memory_report.json"
"$prefix-double/bench/memory_report" --particles 1000000 --skin 0 --json "$results/memory_report_skin0.json"
report
