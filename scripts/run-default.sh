#!/usr/bin/env bash
# The main job (the README's first command): installs the Debian packages, builds the tide
# command only (Release, double) in build/, runs the default scene, the 2D dam break
# (scenes/dam_break_2d.json), with a progress bar, and renders its frames as PNG pictures (and
# an MP4 where ffmpeg is installed). Arguments go to `tide run`.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
jobs="${JOBS:-$(nproc)}"

echo "==== Dependencies"
bash scripts/install-deps.sh

echo "==== Configure and build the tide command (build/)"
cmake -S . -B build
cmake --build build -j "$jobs" --target tide_app

echo "==== tide run --render (default scene: 2D dam break; frames in runs/dam_break_2d/)"
./build/apps/tide run --render "$@"
echo "==== Done: pictures in runs/dam_break_2d/render/ (movie.mp4 where ffmpeg is installed); open"
echo "     runs/dam_break_2d/frames.xdmf in ParaView for the fields"
