#!/usr/bin/env bash
# Installs what lvfusion needs on Debian 12 (only the packages that are
# missing; apt needs root), then configures and builds it (Release) in ./build.
#   LVF_BUILD_DIR=dir   build somewhere else
#   CI=true             warnings become errors
#   LVF_SANITIZE=ON     AddressSanitizer + UndefinedBehaviorSanitizer build
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config file
  libmrpt-dev mrpt-apps mrpt-common
  libopencv-dev libeigen3-dev libyaml-cpp-dev zlib1g-dev libisal-dev
  libgtest-dev libbenchmark-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo=sudo
  echo "bootstrap: installing ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

build_dir=${LVF_BUILD_DIR:-build}
werror=OFF; [ -n "${CI:-}" ] && werror=ON
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DLVF_WARNINGS_AS_ERRORS="$werror" -DLVF_SANITIZE="${LVF_SANITIZE:-OFF}"
cmake --build "$build_dir" -j"$(nproc)"
