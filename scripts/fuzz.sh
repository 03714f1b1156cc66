#!/usr/bin/env bash
# Fuzzes the readers of user input with libFuzzer (tests/fuzz): world files,
# INI files, the text files beside a rawlog, rawlogs, and whole fusion frames.
# Builds everything with Clang, ASan and UBSan in ./build-fuzz (installs
# clang on Debian if missing), makes seed inputs from the shipped files, then
# runs each target for the given time. A finding stops its target and is
# written to build-fuzz/findings/TARGET/; rerun it with
# build-fuzz/bin/TARGET FILE.
#   usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 60)] [TARGET ...]
#   LVF_FUZZ_DIR=dir   build somewhere else
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}; shift || true
targets=("$@")
((${#targets[@]})) || targets=(fuzz_world_file fuzz_ini_options fuzz_text_files fuzz_rawlog fuzz_fusion_frame)
dir=${LVF_FUZZ_DIR:-build-fuzz}

if ! command -v clang++ >/dev/null; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends clang
fi
bash scripts/bootstrap.sh >/dev/null  # the libraries lvfusion needs, and build/ for the seeds
cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLVF_FUZZ=ON -DLVF_BUILD_TESTS=OFF >/dev/null
cmake --build "$dir" -j"$(nproc)" --target "${targets[@]}"

# Seeds: the shipped worlds and configurations, the samples' truth and pose
# files, Middlebury calibrations, and one-frame rawlogs from small rigs.
seeds=$dir/seeds; mkdir -p "$seeds"/{world,ini,text,rawlog}
cp share/lvfusion/worlds/*.yaml "$seeds/world/"
cp share/lvfusion/config/*.ini "$seeds/ini/"
# fuzz_text_files reads its first byte as the reader to use (0 truth scans,
# 1 poses, 2 calib.txt, 3 PFM).
with_selector() { { printf "\\x$(printf %02x "$1")"; head -c 3000 "$2"; } > "$3"; }
with_selector 0 rawlog_samples/two_cubes_truth_scans.csv "$seeds/text/truth"
with_selector 1 rawlog_samples/box_room_gt_poses.txt "$seeds/text/poses"
for calib in ../shared/data/middlebury/*/calib.txt; do
  [ -f "$calib" ] && with_selector 2 "$calib" "$seeds/text/calib_$(basename "$(dirname "$calib")")"
done
printf '\x03Pf\n2 2\n-1.0\n' > "$seeds/text/pfm" && head -c 16 /dev/zero >> "$seeds/text/pfm"
for rig in "24 16 17" "64 48 45"; do
  read -r cols rows f <<< "$rig"
  sed -e "s/^ncols .*/ncols = $cols/" -e "s/^nrows .*/nrows = $rows/" -e "s/^fx .*/fx = $f/" -e "s/^fy .*/fy = $f/" \
    -e "s/^cx .*/cx = $((cols / 2)).5/" -e "s/^cy .*/cy = $((rows / 2)).5/" share/lvfusion/config/sensors.ini > "$seeds/rig.ini"
  for format in sf obs; do
    build/bin/lvf-simulate -q --config "$seeds/rig.ini" --frames 1 --format $format --outdir "$seeds/tmp" --name rig
    # Uncompressed, so that mutations reach the objects, not the gzip
    # checks; and as written, so that they reach the gzip reader too
    # (GzipInputFile.h).
    gzip -dc "$seeds/tmp/rig.rawlog" > "$seeds/rawlog/${cols}x${rows}_$format.rawlog"
    cp "$seeds/tmp/rig.rawlog" "$seeds/rawlog/${cols}x${rows}_$format.gz.rawlog"
  done
done
rm -rf "$seeds/tmp" "$seeds/rig.ini"

seeds_of() { case $1 in fuzz_world_file) echo world;; fuzz_ini_options) echo ini;; fuzz_text_files) echo text;; *) echo rawlog;; esac; }
# Each fuzzing process's input file goes here, not into /tmp.
export TMPDIR; TMPDIR=$(realpath -m "$dir/scratch")
for t in "${targets[@]}"; do
  mkdir -p "$dir/corpus/$t" "$dir/findings/$t" "$TMPDIR"
  echo "fuzz: $t for $seconds s"
  # -ignore_ooms: MRPT's own deserialisers trust a record's element counts
  # (README, "Fuzzing"); the rest of a run still looks for crashes. With
  # allocator_may_return_null an impossible allocation fails as it does
  # without ASan (OpenCV then throws, and the reader names the record)
  # instead of ASan aborting.
  ASAN_OPTIONS=allocator_may_return_null=1 "$dir/bin/$t" "$dir/corpus/$t" "$seeds/$(seeds_of "$t")" -fork=1 -ignore_ooms=1 -malloc_limit_mb=512 \
    -max_total_time="$seconds" -max_len=16384 -artifact_prefix="$dir/findings/$t/" 2>"$dir/$t.log" || true
  grep -E '^#[0-9]+: cov|INFO: exiting|crash|ERROR' "$dir/$t.log" | tail -2
  rm -rf "$TMPDIR"
done
echo "fuzz: findings (none is good):"; find "$dir/findings" -type f -not -name 'oom-*' | sed 's/^/  /'
