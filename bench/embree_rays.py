"""Traces the rays of an `aokit rays --dump DIR` folder with Embree 4 (the `embreex` package) and
compares with cpu-sim's answers in the same folder (for bench/rays_vs_embree.sh).

    python3 bench/embree_rays.py DIR [--procs 2] [--repeat 3] [--robust] [--json OUT]

What is timed, on both sides: only the traversal of already-built acceleration structures.

- AO rays: `EmbreeScene.run(origins, directions, dists=t_max, query='OCCLUDED')`, i.e.
  `rtcOccluded1` per ray over t ∈ [0, t_max] (embreex sets tnear = 0); cpu-sim traces the same
  rays over t ∈ (0, t_max).
- Primary rays: `run(..., query='INTERSECT')`, `rtcIntersect1` per ray, t ∈ [0, 1e37].

embreex's `run` loops over the rays in compiled Cython holding the GIL (two Python threads
measured no faster than one), and Embree's single-ray queries run on the calling thread (TBB
threads only build). So `--procs P` (default 2, the machine's cores) forks P worker processes
before any Embree device exists; each builds its own scene, then in every repeat all wait on a
barrier and trace interleaved chunks of the rays; a repeat's time is the last worker's end minus
the first worker's start (one monotonic clock). The build is timed once, alone, in the parent
(`TriangleMesh` + the commit that embreex does on the first query): Embree's default (medium)
build quality, non-robust unless `--robust`, on all cores through TBB.

The per-ray cost of the binding itself (copying a ray into an RTCRay, the call) is measured on a
scene of one far-away triangle with the same AO rays, one process: the `binding floor`.
"""

import argparse
import json
import multiprocessing as mp
import os
import sys
import time

import numpy as np

CHUNK = 1 << 16


def load(folder):
    with open(os.path.join(folder, "rays.json")) as f:
        meta = json.load(f)
    arr = {
        name: np.load(os.path.join(folder, name + ".npy"))
        for name in [
            "triangles",
            "ao_origins",
            "ao_directions",
            "ao_tmax",
            "ao_occluded",
            "primary_directions",
            "primary_hits",
            "primary_t",
        ]
    }
    p = arr["primary_directions"].shape[0]
    arr["primary_origins"] = np.ascontiguousarray(
        np.broadcast_to(np.array(meta["primary"]["eye"], dtype=np.float32), (p, 3))
    )
    return meta, arr


def make_scene(triangles, robust):
    from embreex import rtcore_scene
    from embreex.mesh_construction import TriangleMesh

    scene = rtcore_scene.EmbreeScene(robust=robust)
    TriangleMesh(scene, triangles)
    # embreex commits the scene (builds the BVH) on the first query.
    scene.run(np.zeros((1, 3), np.float32), np.ones((1, 3), np.float32), dists=np.zeros(1, np.float32), query="OCCLUDED")
    return scene


def chunks(n, worker, procs):
    for c in range(worker, (n + CHUNK - 1) // CHUNK, procs):
        yield c * CHUNK, min(n, (c + 1) * CHUNK)


def trace(scene, arr, kind, lo, hi):
    if kind == "ao":
        return scene.run(
            arr["ao_origins"][lo:hi],
            arr["ao_directions"][lo:hi],
            dists=arr["ao_tmax"][lo:hi].copy(),
            query="OCCLUDED",
        )
    return scene.run(arr["primary_origins"][lo:hi], arr["primary_directions"][lo:hi], query="INTERSECT")


def worker(index, procs, arr, robust, jobs, barrier, results):
    scene = make_scene(arr["triangles"], robust)
    for kind, repeat in jobs:
        n = arr["ao_origins" if kind == "ao" else "primary_origins"].shape[0]
        trace(scene, arr, kind, 0, min(n, 1024))  # warm-up
        for r in range(repeat):
            out = {}
            barrier.wait()
            c0, t0 = time.process_time(), time.perf_counter()
            for lo, hi in chunks(n, index, procs):
                out[lo] = trace(scene, arr, kind, lo, hi)
            t1, c1 = time.perf_counter(), time.process_time()
            results.put((kind, r, index, t0, t1, c1 - c0, out if r == repeat - 1 else None))


def run_parallel(arr, procs, repeat, robust):
    ctx = mp.get_context("fork")
    barrier = ctx.Barrier(procs)
    results = ctx.Queue()
    jobs = [("ao", repeat), ("primary", repeat)]
    workers = [ctx.Process(target=worker, args=(i, procs, arr, robust, jobs, barrier, results)) for i in range(procs)]
    for w in workers:
        w.start()
    spans, cpu, answers = {}, {}, {"ao": {}, "primary": {}}
    for _ in range(procs * 2 * repeat):
        kind, r, _, t0, t1, c, out = results.get()
        a, b = spans.get((kind, r), (t0, t1))
        spans[(kind, r)] = (min(a, t0), max(b, t1))
        cpu[(kind, r)] = cpu.get((kind, r), 0.0) + c
        if out is not None:
            answers[kind].update(out)
    for w in workers:
        w.join()
        if w.exitcode != 0:
            sys.exit(f"an Embree worker failed (exit code {w.exitcode})")
    times = {
        k: ([spans[(k, r)][1] - spans[(k, r)][0] for r in range(repeat)], [cpu[(k, r)] for r in range(repeat)])
        for k in ("ao", "primary")
    }
    joined = {k: np.concatenate([answers[k][lo] for lo in sorted(answers[k])]) for k in answers}
    return times, joined


def throughput(n, times):
    """As `aokit::rays::throughput_json`: best and median wall-clock run, and per CPU second."""
    wall, cpu = times
    best, median = min(wall), float(np.median(wall))
    return {
        "runs_s": wall,
        "min_s": best,
        "median_s": median,
        "mrays_per_s_best": n / best / 1e6,
        "mrays_per_s_median": n / median / 1e6,
        "cpu_s": cpu,
        "mrays_per_cpu_s": n * len(cpu) / sum(cpu) / 1e6,
    }


def binding_floor(arr, count):
    """Seconds per ray of embreex's `run` on a scene whose only triangle no ray reaches."""
    far = np.array([[[1e6, 1e6, 1e6], [1e6 + 1, 1e6, 1e6], [1e6, 1e6 + 1, 1e6]]], np.float32)
    scene = make_scene(far, False)
    n = min(count, arr["ao_origins"].shape[0])
    t = time.perf_counter()
    for lo in range(0, n, CHUNK):
        hi = min(n, lo + CHUNK)
        trace(scene, arr, "ao", lo, hi)
    return (time.perf_counter() - t) / n


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folder")
    ap.add_argument("--procs", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--robust", action="store_true", help="RTC_SCENE_FLAG_ROBUST (Embree's watertight mode)")
    ap.add_argument("--json", help="write the results here")
    args = ap.parse_args()
    if args.procs < 1 or args.repeat < 1:
        sys.exit("--procs and --repeat must be at least 1")
    meta, arr = load(args.folder)
    n_ao, n_primary = arr["ao_origins"].shape[0], arr["primary_origins"].shape[0]

    times, answers = run_parallel(arr, args.procs, args.repeat, args.robust)

    # The build, alone (TBB on every core), once the workers are gone.
    t = time.perf_counter()
    scene = make_scene(arr["triangles"], args.robust)
    build_ms = (time.perf_counter() - t) * 1e3
    del scene
    floor = binding_floor(arr, 4 * CHUNK * 8)

    import embreex

    ours_ao = arr["ao_occluded"].astype(bool)
    theirs_ao = answers["ao"] != -1  # embreex returns the geometry id (0) when occluded, -1 otherwise
    ours_hit, theirs_hit = arr["primary_hits"], answers["primary"]
    both = (ours_hit >= 0) & (theirs_hit >= 0)
    result = {
        "embree": f"Embree {embreex.__version__} via embreex (rtcOccluded1 / rtcIntersect1, "
        f"{'robust' if args.robust else 'default'} scene flags, default build quality)",
        "procs": args.procs,
        "cpu_count": os.cpu_count(),
        "build_ms": build_ms,
        "binding_floor_ns_per_ray": floor * 1e9,
        "ao": {
            "rays": n_ao,
            "occluded": int(theirs_ao.sum()),
            "occluded_fraction": float(theirs_ao.mean()) if n_ao else 0.0,
            "cpu_sim_occluded_fraction": float(ours_ao.mean()) if n_ao else 0.0,
            "disagree": int((ours_ao != theirs_ao).sum()),
            "embree": throughput(n_ao, times["ao"]),
        },
        "primary": {
            "rays": n_primary,
            "hit_fraction": float((theirs_hit >= 0).mean()),
            "cpu_sim_hit_fraction": float((ours_hit >= 0).mean()),
            "hit_disagree": int(((ours_hit >= 0) != (theirs_hit >= 0)).sum()),
            "other_triangle": int((both & (ours_hit != theirs_hit)).sum()),
            "embree": throughput(n_primary, times["primary"]),
        },
    }
    if meta.get("masked_materials", 0) and meta.get("alpha") == "on":
        result["warning"] = "the scene has alpha-masked materials that cpu-sim tested and Embree did not (--alpha off)"
    a, p = result["ao"], result["primary"]
    c_ao, c_p = meta["ao"]["cpu_sim"], meta["primary"]["cpu_sim"]
    print(
        f"{meta['scene']}: {meta['triangles']} triangles; build: cpu-sim {meta['bvh_build_ms']:.0f} ms, Embree {build_ms:.0f} ms\n"
        f"AO rays ({n_ao}): cpu-sim {c_ao['mrays_per_s_best']:.2f} M rays/s (median {c_ao['mrays_per_s_median']:.2f}, "
        f"{c_ao.get('mrays_per_cpu_s', 0):.2f} per CPU s), "
        f"Embree {a['embree']['mrays_per_s_best']:.2f} (median {a['embree']['mrays_per_s_median']:.2f}, "
        f"{a['embree']['mrays_per_cpu_s']:.2f} per CPU s); "
        f"occluded {a['cpu_sim_occluded_fraction']:.6f} vs {a['occluded_fraction']:.6f}, {a['disagree']} rays disagree\n"
        f"primary rays ({n_primary}): cpu-sim {c_p['mrays_per_s_best']:.2f} M rays/s ({c_p.get('mrays_per_cpu_s', 0):.2f} per CPU s), "
        f"Embree {p['embree']['mrays_per_s_best']:.2f} ({p['embree']['mrays_per_cpu_s']:.2f} per CPU s); hit {p['cpu_sim_hit_fraction']:.6f} vs {p['hit_fraction']:.6f}, "
        f"{p['hit_disagree']} disagree on hit/miss, {p['other_triangle']} on the triangle\n"
        f"binding floor {result['binding_floor_ns_per_ray']:.0f} ns/ray",
        file=sys.stderr,
    )
    if "warning" in result:
        print("warning: " + result["warning"], file=sys.stderr)
    text = json.dumps(result, indent=1)
    if args.json:
        with open(args.json, "w") as f:
            f.write(text + "\n")
    print(json.dumps(result))


if __name__ == "__main__":
    main()
