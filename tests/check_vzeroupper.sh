#!/usr/bin/env bash
# check_vzeroupper.sh FILE...: fails if machine code in FILE (objects,
# archives, libraries, programs) calls or returns right after 256-bit AVX
# code without a vzeroupper in between.
#
# Why: AVX2 code that leaves the upper halves of the ymm registers dirty
# makes every legacy-SSE instruction after it, anywhere in the process,
# slower. GCC inserts vzeroupper itself, but GCC 12 once left it out of an
# AVX2 clone that ended in a call to std::find, and the whole fusion ran 25 %
# slower (measurements.md, session 54) with every result unchanged: no other
# test would see it.
#
# Read in address order, per function: ymm code makes the state dirty, a
# vzeroupper cleans it, a call or ret while dirty is reported. Address order
# is not execution order, but GCC lays a function's vector loop out before
# the code that leaves it, which is what is checked here.
set -euo pipefail
if (($# == 0)); then
  echo "usage: check_vzeroupper.sh FILE..." >&2
  exit 2
fi
found=0
wide=0
for f in "$@"; do
  if ! listing=$(objdump -d --no-show-raw-insn -C "$f" 2>&1); then
    echo "check_vzeroupper: objdump cannot read $f: ${listing##*$'\n'}" >&2
    exit 2
  fi
  # Prints the offending lines, then the count of functions with 256-bit code.
  report=$(awk -v file="$f" '
    /^[0-9a-f]+ <.*>:$/ { fn = $0; dirty = 0; next }
    /\t/ {
      split($0, parts, "\t"); split(parts[2], words, " "); op = words[1]
      if (op == "vzeroupper") { dirty = 0; next }
      if ((op == "call" || op == "ret") && dirty) { print file ": " fn " " $0; bad++ }
      if ($0 ~ /%ymm/ && !(fn in wide)) { wide[fn] = 1; functions++ }
      if ($0 ~ /%ymm/) dirty = 1
    }
    END { print "BAD " bad + 0 " WIDE " functions + 0 }' <<<"$listing")
  summary=${report##*$'\n'}
  read -r _ bad _ functions <<<"$summary"
  if ((bad)); then
    echo "${report%$'\n'*}"
    found=1
  fi
  wide=$((wide + functions))
done
if ((found)); then
  echo "check_vzeroupper: 256-bit code reaches a call or ret above without vzeroupper" >&2
  exit 1
fi
echo "check_vzeroupper: $wide functions with 256-bit code in $# files; each clears the upper halves before a call or ret"
