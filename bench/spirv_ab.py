#!/usr/bin/env python3
"""A/B timing of two aokit builds on the same Vulkan device: per pass, the median over rounds of
the ratio B/A, each round running A then B (then B then A in the next round, so neither side
always runs first), each side's pass time the median of its `aokit bench` frames (GPU
timestamps).

    python3 bench/spirv_ab.py A_BIN B_BIN [--technique gtao] [--width 640] [--height 360]
                              [--rounds 5] [--frames 3] [--scene sponza]

A_BIN and B_BIN are two `aokit` binaries (each embeds the SPIR-V it was built with: build one,
copy it away, change the kernels, rebuild the SPIR-V and the binary). Prints a Markdown table.
Standard library only.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def bench(binary, args, path):
    cmd = [
        binary, "bench", "--scene", args.scene, "--width", str(args.width), "--height", str(args.height),
        "--technique", args.technique, "--backend", "vulkan", "--frames", str(args.frames),
        "--warmup", "1", "--json", path,
    ]
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"spirv_ab: {' '.join(cmd)} failed: {done.stderr.strip().splitlines()[-1:]}")
    with open(path) as f:
        report = json.load(f)
    return {p["name"]: p["median_ms"] for p in report["passes"] if "median_ms" in p}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--technique", default="gtao")
    parser.add_argument("--scene", default="sponza")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--frames", type=int, default=3)
    args = parser.parse_args()
    for binary in (args.a, args.b):
        if not os.access(binary, os.X_OK):
            sys.exit(f"spirv_ab: {binary} is not an executable aokit binary")
    times = {"a": [], "b": []}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(args.rounds):
            order = ("a", "b") if r % 2 == 0 else ("b", "a")
            for side in order:
                binary = args.a if side == "a" else args.b
                times[side].append(bench(binary, args, os.path.join(tmp, f"{side}{r}.json")))
            print(f"round {r + 1}/{args.rounds} done", file=sys.stderr)
    passes = [p for p in times["a"][0] if p != "gbuffer"]
    print(f"{args.technique} on {args.scene} {args.width}×{args.height}, {args.rounds} rounds × {args.frames} frames\n")
    print("| pass | A median ms | B median ms | B/A (median of per-round ratios) |")
    print("|---|---:|---:|---:|")
    for p in passes:
        a = [t[p] for t in times["a"]]
        b = [t[p] for t in times["b"]]
        ratios = [y / x for x, y in zip(a, b) if x > 0]
        print(f"| {p} | {statistics.median(a):.2f} | {statistics.median(b):.2f} | {statistics.median(ratios):.3f} |")


if __name__ == "__main__":
    main()
