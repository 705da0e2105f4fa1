#!/usr/bin/env bash
# The whole benchmark on one Vulkan device (a GPU when there is one; lavapipe otherwise), written
# to bench/GPU.md: every technique per pass at 1920×1080 and 3840×2160, ray-traced ones with
# pipelines and with ray queries where the device has them (refusals listed), and the peers
# (bench/peers/README.md). Extra arguments go to bench/gpu.py, e.g.
#   bash bench/gpu.sh --xegtao-spirv DIR          # include XeGTAO
#   bash bench/gpu.sh --sizes 480x270 --frames 2  # a quick run on lavapipe
# Needs no nightly: the SPIR-V is committed. Budget on one GPU: under 8 minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
# --bin-dir DIR: the release binaries were built elsewhere and copied to DIR (a GPU machine
# without cargo); otherwise build them here.
if [[ " $* " != *" --bin-dir "* ]]; then
  cargo build --release -p aokit --bin aokit
  cargo build --release -p aokit-peers
fi
python3 bench/gpu.py "$@"
