#!/usr/bin/env bash
# Regenerates bench/HALF_RESOLUTION.md: per screen-space technique, what half resolution
# (docs/algorithms/half-resolution.md) saves and costs — the AO passes' median time at full and at
# half resolution on lavapipe and on cpu-sim (1920×1080 + guard, `aokit bench`), and the MSE and
# FLIP of both against the 512-spp ground truth (`aokit compare` on the CPU, 640×360, exponent 1).
#
#   bench/half_resolution.sh
#   SCENE=kitchen FRAMES=5 bench/half_resolution.sh
#
# Environment: SCENE, WIDTH, HEIGHT (timing), QWIDTH, QHEIGHT (quality), FRAMES, WARMUP,
# TECHNIQUES (space-separated), AOKIT (the binary; default: build target/release/aokit), OUT.
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE=${SCENE:-sponza}
WIDTH=${WIDTH:-1920}
HEIGHT=${HEIGHT:-1080}
QWIDTH=${QWIDTH:-640}
QHEIGHT=${QHEIGHT:-360}
FRAMES=${FRAMES:-3}
WARMUP=${WARMUP:-1}
TECHNIQUES=${TECHNIQUES:-vao hbao gtao vbao raymarch}
OUT=${OUT:-bench/HALF_RESOLUTION.md}
if [ -z "${AOKIT:-}" ]; then
  cargo build --release --bin aokit >&2
  AOKIT=target/release/aokit
fi
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
SPECS=""
for t in $TECHNIQUES; do
  for r in full half; do
    SPECS="$SPECS,$t:resolution=$r"
    for b in vulkan cpu; do
      echo "bench $t at $r resolution on $b ($SCENE ${WIDTH}x${HEIGHT}, $FRAMES frames after $WARMUP)" >&2
      "$AOKIT" bench --scene "$SCENE" --width "$WIDTH" --height "$HEIGHT" --technique "$t:resolution=$r" \
        --backend "$b" --frames "$FRAMES" --warmup "$WARMUP" --json "$DIR/$t-$r-$b.json" >/dev/null
    done
  done
done
echo "compare on the CPU ($SCENE ${QWIDTH}x${QHEIGHT}) against the ground truth" >&2
"$AOKIT" compare --scene "$SCENE" --width "$QWIDTH" --height "$QHEIGHT" --exponent 1 --reference groundtruth \
  --techniques "${SPECS#,}" --json "$DIR/quality.json" --images "$DIR/images" >/dev/null
python3 bench/half_resolution.py "$DIR" "$TECHNIQUES" > "$OUT.tmp"
mv "$OUT.tmp" "$OUT"
cat "$OUT"
