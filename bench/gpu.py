#!/usr/bin/env python3
"""The whole benchmark on one Vulkan device, written to bench/GPU.md (run through bench/gpu.sh).

    python3 bench/gpu.py [--sizes 1920x1080,3840x2160] [--frames 5] [--warmup 2] [--scene sponza]
                         [--xegtao-spirv DIR] [--no-bevy] [--bevy-src DIR] [--timeout-s 90]
                         [--bin-dir target/release] [--out bench/GPU.md]

Every technique of `aokit techniques` at every size, per pass (`aokit bench`, GPU timestamps); the
ray-traced ones with ray-tracing pipelines and with ray queries, each where the device has the
extensions and otherwise listed with the one-line refusal aokit gave; then the peers
(bench/peers/README.md): XeGTAO when --xegtao-spirv is given, Bevy unless --no-bevy. Each command
gets --timeout-s seconds; one that runs longer is listed as timed out and the run goes on. Expects
release builds of `aokit` and `aokit-peers` in --bin-dir (bench/gpu.sh makes them; a machine
without cargo gets them copied). Standard library only.
"""

import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def attempt(cmd, timeout_s):
    """(True, None) when `cmd` succeeded, else (False, its last error line)."""
    try:
        done = subprocess.run(cmd, cwd=ROOT, text=True, capture_output=True, timeout=timeout_s)
    except subprocess.TimeoutExpired:
        return False, f"timed out after {timeout_s:.0f} s (--timeout-s)"
    if done.returncode != 0:
        lines = [l for l in (done.stderr or done.stdout).strip().splitlines() if l.strip()]
        return False, (lines[-1] if lines else f"exit status {done.returncode}")
    return True, None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", default="1920x1080,3840x2160")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=2)
    parser.add_argument("--scene", default="sponza")
    parser.add_argument("--xegtao-spirv", help="folder with XeGTAO's SPIR-V (bench/peers/README.md)")
    parser.add_argument("--no-bevy", action="store_true")
    parser.add_argument("--bevy-src", help="folder holding bevy_pbr-0.20.* and bevy_render-0.20.* (default: cargo's registry)")
    parser.add_argument("--timeout-s", type=float, default=90.0, help="limit of each command, seconds")
    parser.add_argument("--bin-dir", default=os.path.join(ROOT, "target", "release"),
                        help="folder holding the release binaries aokit and aokit-peers")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "GPU.md"))
    args = parser.parse_args()
    aokit = os.path.join(os.path.abspath(args.bin_dir), "aokit")
    peers = os.path.join(os.path.abspath(args.bin_dir), "aokit-peers")
    try:
        sizes = [tuple(int(v) for v in s.split("x")) for s in args.sizes.split(",")]
    except ValueError:
        sys.exit(f"gpu: --sizes takes WxH[,WxH…], not '{args.sizes}'")
    for binary in (aokit, peers):
        if not os.access(binary, os.X_OK):
            sys.exit(f"gpu: {binary} is missing: run bench/gpu.sh (it builds the release binaries)")
    start = time.time()
    info = subprocess.run([aokit, "info"], text=True, capture_output=True).stdout.splitlines()
    device = json.loads(info[0]) if info and info[0].startswith("{") else {"name": "?"}
    techniques = [l.split()[0] for l in subprocess.run([aokit, "techniques"], text=True, capture_output=True)
                  .stdout.splitlines() if l and not l[0].isspace()]
    rows, refusals = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for (w, h) in sizes:
            for t in techniques:
                modes = [None]
                for mode in modes:
                    path = os.path.join(tmp, "bench.json")
                    cmd = [aokit, "bench", "--backend", "vulkan", "--scene", args.scene, "--technique", t,
                           "--width", str(w), "--height", str(h), "--frames", str(args.frames),
                           "--warmup", str(args.warmup), "--json", path]
                    if mode:
                        cmd += ["--rt-mode", mode]
                    label = f"{t} {w}×{h}" + (f" ({mode})" if mode else "")
                    print(f"gpu: {label}", file=sys.stderr)
                    ok, error = attempt(cmd, args.timeout_s)
                    if not ok:
                        refusals.append((label, error))
                        if mode is None:
                            # The default (pipelines) refused: ray queries may still run.
                            modes.append("query")
                        continue
                    with open(path) as f:
                        r = json.load(f)
                    if mode is None and r.get("traces_rays"):
                        modes.append("query")
                    rows.append((t, w, h, mode or ("pipeline" if r.get("traces_rays") else "—"), r))
        peer_sections = []
        for peer, extra in (("xegtao", ["--spirv", args.xegtao_spirv] if args.xegtao_spirv else None),
                            ("bevy", None if args.no_bevy else
                             (["--bevy-src", args.bevy_src] if args.bevy_src else []))):
            if extra is None:
                why = "no --xegtao-spirv given" if peer == "xegtao" else "--no-bevy"
                peer_sections.append(f"- {peer}: not run ({why}).")
                continue
            for (w, h) in sizes:
                path = os.path.join(tmp, f"{peer}.json")
                cmd = [peers, peer, "--scene", args.scene, "--width", str(w), "--height", str(h),
                       "--iterations", str(args.frames), "--warmup", str(args.warmup), "--json", path] + extra
                print(f"gpu: peers {peer} {w}×{h}", file=sys.stderr)
                ok, error = attempt(cmd, args.timeout_s)
                if not ok:
                    peer_sections.append(f"- {peer} {w}×{h}: failed: {error}")
                    continue
                with open(path) as f:
                    r = json.load(f)
                cells = ", ".join(f"{p['pass']} {p['aokit_ms']:.2f} / {p['peer_ms']:.2f} ms (**{p['ratio']:.3f}**)"
                                  for p in r["passes"])
                peer_sections.append(f"- {peer} {w}×{h}: aokit / peer: {cells}")
    minutes = (time.time() - start) / 60
    out = [f"# aokit on {device.get('name', '?')}", "",
           f"Generated by `bash bench/gpu.sh` on {datetime.date.today()} in {minutes:.1f} min: scene {args.scene}, "
           f"{args.frames} timed frames after {args.warmup} warm-ups, medians of GPU timestamps per pass "
           "(`aokit bench --backend vulkan`; the frame's G-buffer raster passes included, the acceleration "
           "structure's build not). Device: " + json.dumps(device) + ".", "",
           "| technique | size | rays | GPU ms (Σ passes) | frame ms | passes (ms) |", "|---|---|---|---:|---:|---|"]
    for (t, w, h, mode, r) in rows:
        passes = ", ".join(f"{p['name']} {p['median_ms']:.2f}" for p in r["passes"] if "median_ms" in p)
        gpu = r.get("gpu_ms")
        frame = r.get("frame_ms")
        out.append(f"| {t} | {w}×{h} | {mode} | {gpu:.2f} | {frame:.2f} | {passes} |" if gpu and frame else
                   f"| {t} | {w}×{h} | {mode} | – | – | {passes} |")
    out += ["", "## Refused or failed", ""]
    out += [f"- {label}: {error}" for (label, error) in refusals] or ["- none"]
    out += ["", "## Peers (same device, alternating iterations; bench/peers/README.md)", ""] + peer_sections + [""]
    with open(args.out, "w") as f:
        f.write("\n".join(out))
    print(f"gpu: wrote {args.out} in {minutes:.1f} min", file=sys.stderr)


if __name__ == "__main__":
    main()
