#!/usr/bin/env bash
# Compares two lvf-fuse binaries on the same inputs, as the fusion's changes
# in share/doc/lvfusion/measurements.md were judged: whether their fused
# rawlogs are the same byte for byte, and if not, each one's recall and
# phantom bearings summed per set (NAME_frames.csv's in_view, hidden, recall,
# phantom_rate columns; seen_hidden and seen_recall where the inputs have
# seen truth scans), plus its mean search time per frame.
#   usage: scripts/fusion-ab.sh OLD_LVF_FUSE NEW_LVF_FUSE [WORKDIR]
#   LVF_AB_ROOMS="201 202 ..."   seeded rooms (default 201-230, never tuned on)
#   LVF_AB_CONFIG=FILE.ini       --config for both binaries
#   LVF_BUILD_DIR=dir            where this checkout was built (default build)
# Inputs: the seeded rooms (made once with this checkout's lvf-simulate), the
# three shipped samples, and Middlebury Motorcycle and Recycle when
# ../shared/data is there. One thread each (the outputs are the same on any
# number), so a time compares like with like.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,14p' "$0" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(realpath "$1"); new=$(realpath "$2"); work=${3:-lvf-ab}
for b in "$old" "$new"; do [ -x "$b" ] || { echo "fusion-ab: $b: not an executable" >&2; exit 2; }; done
bin=$root/${LVF_BUILD_DIR:-build}/bin  # lvf-simulate, lvf-import-middlebury (as bootstrap.sh builds them)
rm -rf "$work/old" "$work/new"  # the inputs are kept: made once, reused
mkdir -p "$work/inputs"
inputs=()
for s in ${LVF_AB_ROOMS:-$(seq 201 230)}; do
  [ -f "$work/inputs/random_$s.rawlog" ] || "$bin/lvf-simulate" -q --random-world "$s" --outdir "$work/inputs"
  inputs+=("$work/inputs/random_$s.rawlog")
done
for n in two_cubes box_room corridor_desk; do inputs+=("$root/rawlog_samples/$n.rawlog"); done
mb=$root/../shared/data/middlebury
for scene in Motorcycle Recycle; do
  if [ -d "$mb/$scene" ]; then
    [ -f "$work/inputs/$scene.rawlog" ] || "$bin/lvf-import-middlebury" -q -s "$mb/$scene" -o "$work/inputs"
    inputs+=("$work/inputs/$scene.rawlog")
  fi
done

config=(); [ -n "${LVF_AB_CONFIG:-}" ] && config=(--config "$LVF_AB_CONFIG")
differ=0
for side in old new; do
  b=$old; [ $side = new ] && b=$new
  for in in "${inputs[@]}"; do
    name=$(basename "$in" .rawlog)
    "$b" -q --threads 1 "${config[@]}" -i "$in" -o "$work/$side/$name" --output "$work/$side/$name.rawlog" >/dev/null
  done
done
for in in "${inputs[@]}"; do
  name=$(basename "$in" .rawlog)
  cmp -s "$work/old/$name.rawlog" "$work/new/$name.rawlog" || { differ=$((differ + 1)); echo "differs: $name"; }
done
echo "fusion-ab: ${#inputs[@]} inputs, $differ with different fused rawlogs"
# Per side and set (the seeded rooms together, every other input alone):
# recalled / hidden and phantom / in-view bearings, summed over the frames
# (recall and phantom rate times their counts), and the search's mean time.
for side in old new; do
  awk -F, -v side=$side '
    FNR == 1 {
      n = split(FILENAME, parts, "/"); set = parts[n - 1]; if (set ~ /^random_/) set = "seeded rooms"
      for (i = 1; i <= NF; i++) col[$i] = i  # by name: the CSV may gain columns
      next
    }
    {
      views = $col["in_view"]; hidden = $col["hidden"]
      v[set] += views; h[set] += hidden; t[set] += $col["t_search_ms"]; f[set]++
      r[set] += int($col["recall"] * hidden + 0.5); p[set] += int($col["phantom_rate"] * views + 0.5)
      if ("seen_hidden" in col && $col["seen_hidden"] != "") {  # both cameras see the obstacle (StereoSeenTruth.h)
        sh[set] += $col["seen_hidden"]; sr[set] += int($col["seen_recall"] * $col["seen_hidden"] + 0.5)
      }
    }
    END { for (s in f) printf "%s %-14s recalled %5d of %5d hidden (%5d of %5d seen), %4d phantom of %5d in view, search %.2f ms a frame\n",
          side, s, r[s], h[s], sr[s], sh[s], p[s], v[s], t[s] / f[s] }' "$work/$side"/*/*_frames.csv | sort -k2
done
