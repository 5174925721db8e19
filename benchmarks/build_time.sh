#!/usr/bin/env bash
# Clean-build time of wetbed under build settings compared one after the other
# (doc/developer_guide.md, "Build time"): for each setting a fresh build folder under
# WORK (default build-time/), configured as scripts/build.sh does plus the setting's
# -D options, the target wetbed alone, then everything else (the test programs); wall
# time and CPU time (user + system of every process the build ran) of each part, and the
# 1-minute load average at its start and end (above 2, other jobs shared the cores: the
# wall time is an upper bound, the CPU time hardly changes). Prints one markdown row per
# setting.
# usage: bash benchmarks/build_time.sh [WORK] [JOBS] [SETTING ...]
#   SETTING: comma-separated CMake options without -D, e.g. WETBED_UNITY_BUILD=OFF;
#   default: the unity build against one source per translation unit
#   (WETBED_UNITY_BUILD=ON WETBED_UNITY_BUILD=OFF); WETBED_PRECOMPILED_HEADERS=OFF and
#   WETBED_DEBUG_INFO=ON are the other two settings that change the build time.
set -euo pipefail
cd "$(dirname "$0")/.."
work=${1:-build-time}
jobs=${2:-$(nproc)}
shift $(( $# < 2 ? $# : 2 ))
settings=("$@")
[ ${#settings[@]} -eq 0 ] && settings=(WETBED_UNITY_BUILD=ON WETBED_UNITY_BUILD=OFF)
load() { cut -d' ' -f1 /proc/loadavg; }
mkdir -p "$work"
echo "| setting | wetbed: wall s | wetbed: CPU s | the rest: wall s | the rest: CPU s | everything: wall s | everything: CPU s | load |"
echo "|---|---|---|---|---|---|---|---|"
for setting in "${settings[@]}"; do
  b=$work/$(echo "$setting" | tr ',=' '__')
  rm -rf "$b"
  options=()
  IFS=',' read -ra parts <<< "$setting"
  for o in "${parts[@]}"; do options+=("-D$o"); done
  cmake -S . -B "$b" -DCMAKE_BUILD_TYPE=Release "${options[@]}" > "$b.configure.log" 2>&1
  l0=$(load)
  /usr/bin/time -f "%e %U %S" -o "$b.wetbed.time" cmake --build "$b" -j "$jobs" --target wetbed > "$b.wetbed.log" 2>&1
  l1=$(load)
  /usr/bin/time -f "%e %U %S" -o "$b.rest.time" cmake --build "$b" -j "$jobs" > "$b.rest.log" 2>&1
  l2=$(load)
  read -r w1 u1 s1 < "$b.wetbed.time"
  read -r w2 u2 s2 < "$b.rest.time"
  awk -v p="$setting" -v w1="$w1" -v u1="$u1" -v s1="$s1" -v w2="$w2" -v u2="$u2" -v s2="$s2" -v l="$l0, $l1, $l2" \
    'BEGIN { printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %s |\n", p, w1, u1 + s1, w2, u2 + s2, w1 + w2, u1 + s1 + u2 + s2, l }'
done
