#!/usr/bin/env bash
# Regenerates bench/CPU_VS_LAVAPIPE.md: per screen-space pass, the CPU simulator's median time
# against lavapipe running the same kernels' SPIR-V, measured in one run on this machine.
# For each technique the two back-ends run back to back with `aokit bench`.
#
#   bench/cpu_vs_lavapipe.sh                      # sponza, 1920×1080 (+ guard), 9 frames after 1 warm-up
#   SCENE=kitchen WIDTH=960 HEIGHT=540 FRAMES=5 bench/cpu_vs_lavapipe.sh
#
# Environment: SCENE, WIDTH, HEIGHT, FRAMES, WARMUP, TECHNIQUES (space-separated), AOKIT (the
# binary; default: build and use target/release/aokit), OUT (the Markdown file).
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE=${SCENE:-sponza}
WIDTH=${WIDTH:-1920}
HEIGHT=${HEIGHT:-1080}
# Nine timed frames: with three, one slow frame of a 4–15 ms pass (the prefilter, the denoiser; a
# 2-core VM's threads are sometimes descheduled) moved its median by up to 70 %.
FRAMES=${FRAMES:-9}
WARMUP=${WARMUP:-1}
TECHNIQUES=${TECHNIQUES:-vao sdsvao gtao vbao raymarch}
OUT=${OUT:-bench/CPU_VS_LAVAPIPE.md}
if [ -z "${AOKIT:-}" ]; then
  cargo build --release --bin aokit >&2
  AOKIT=target/release/aokit
fi
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
for t in $TECHNIQUES; do
  for b in cpu vulkan; do
    echo "bench $t on $b ($SCENE ${WIDTH}x${HEIGHT}, $FRAMES frames after $WARMUP)" >&2
    "$AOKIT" bench --scene "$SCENE" --width "$WIDTH" --height "$HEIGHT" --technique "$t" --backend "$b" \
      --frames "$FRAMES" --warmup "$WARMUP" --json "$DIR/$t-$b.json" >/dev/null
  done
done
python3 bench/cpu_vs_lavapipe.py "$DIR" "$TECHNIQUES" > "$OUT.tmp"
mv "$OUT.tmp" "$OUT"
cat "$OUT"
