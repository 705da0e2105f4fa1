#!/usr/bin/env bash
# Ray-tracing pipelines vs ray queries (--rt-mode) on the Vulkan back-end: `aokit bench` of the
# ray-traced techniques in both modes, alternating, on Sponza at 1080p; prints the median time of
# each technique's ray-traced pass. Usage: benches/rt_mode.sh [OUT_DIR] (needs a release build).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-target/rt-mode-bench}"
mkdir -p "$out"
aokit=target/release/aokit
cargo build --release -q
# technique, timed frames, the pass that traces, extra flags
runs=("raysd 4 sd_map" "hybrid 4 hybrid_rays" "raysvao 2 ao_pass2_rays" "groundtruth 2 groundtruth --spp 4")
for run in "${runs[@]}"; do
  read -r technique frames pass extra <<<"$run"
  for mode in pipeline query; do
    # shellcheck disable=SC2086
    "$aokit" bench --scene sponza --backend vulkan --rt-mode "$mode" --technique "$technique" $extra \
      --frames "$frames" --warmup 1 --json "$out/$technique-$mode.json" >/dev/null
  done
  python3 - "$out" "$technique" "$pass" <<'PY'
import json, sys
out, technique, label = sys.argv[1:]
ms = {m: next(p["median_ms"] for p in json.load(open(f"{out}/{technique}-{m}.json"))["passes"] if p["name"] == label)
      for m in ("pipeline", "query")}
print(f"{technique:12} {label:14} pipeline {ms['pipeline']:9.1f} ms   query {ms['query']:9.1f} ms   query/pipeline {ms['query'] / ms['pipeline']:.2f}")
PY
done
