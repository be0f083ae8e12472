#!/usr/bin/env bash
# The main job (the README's first command): installs the Debian packages, builds TideSPH
# (Release, double) in build/ and runs the default scene, the 2D dam break
# (scenes/dam_break_2d.json), with a progress bar. Arguments go to `tide run`.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
jobs="${JOBS:-$(nproc)}"

echo "==== Dependencies"
bash scripts/install-deps.sh

echo "==== Configure and build (build/)"
cmake -S . -B build
cmake --build build -j "$jobs"

echo "==== tide run (default scene: 2D dam break; frames in runs/dam_break_2d/)"
./build/apps/tide run "$@"
