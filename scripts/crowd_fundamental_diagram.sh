#!/usr/bin/env bash
# Case (a) of the crowd validation (docs/crowds.md, "Fundamental diagram"): runs the corridor test
# of a built tree and plots its mean speed against density beside Weidmann 1993.
# Usage: bash scripts/crowd_fundamental_diagram.sh [BUILD_DIR] [OUT.png]
set -euo pipefail
build="${1:-build}"
out="${2:-docs/crowds/fundamental_diagram.png}"
data="$(mktemp)"
trap 'rm -f "$data"' EXIT
"$build/tests/crowd_corridor_test" |
  sed -n 's/^density \([0-9.]*\) persons\/m^2: mean speed \([0-9.]*\) m\/s.*/\1 \2/p' >"$data"
[[ -s "$data" ]] || { echo "no densities in the test's output" >&2; exit 1; }
gnuplot <<PLOT
set terminal pngcairo size 800,500 font "DejaVu Sans,11"
set output "$out"
set xlabel "density (persons/m^2)"
set ylabel "mean speed (m/s)"
set xrange [0:5.5]
set yrange [0:1.5]
set grid
weidmann(r) = 1.34*(1-exp(-1.913*(1/r-1/5.4)))
plot weidmann(x) title "Weidmann 1993 (v0 = 1.34 m/s)" lw 2 lc rgb "black", \
     "$data" using 1:2 with linespoints pt 7 ps 1.3 lc rgb "#1f77b4" title "TideSPH crowd, periodic corridor"
PLOT
echo "wrote $out"
