#!/usr/bin/env bash
# Regenerates the shipped sample rawlogs (and their ground truth) from the
# world files, with the default sensors and seed. Deterministic: running it
# again on the same build reproduces the same bytes.
#   usage: rawlog_samples/regenerate.sh [path/to/lvf-simulate]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
sim=${1:-$here/../build/bin/lvf-simulate}
for world in two_cubes box_room corridor_desk; do
  "$sim" --world "$here/../share/lvfusion/worlds/$world.yaml" --outdir "$here"
done
