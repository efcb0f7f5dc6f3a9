#!/usr/bin/env python3
"""Benchmarks of the Python package (not a test): prints a Markdown section for docs/benchmarks.md.

- baize.simulate on random single shots against the same shots in C++ alone, in this process on
  one core, run after run interleaved: the binding's cost;
- baize.simulate_many on 1 and 2 threads: shots per second and their ratio (two cores), and
  `baize batch --threads 1` on the same shots on the same one core;
- baize.dask on a LocalCluster of two worker processes: throughput, and the overhead per chunk
  (Dask's wall time less simulate_many's on two threads, per chunk).

Usage: PYTHONPATH=build/python /usr/bin/python3 tools/bench_python.py [--quick] [--baize PATH]
  --baize PATH  the baize program timed for the batch comparison (default build/baize; none there:
                that line says it was not measured)
"""
import contextlib
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import baize
from baize import _baize


@contextlib.contextmanager
def one_core():
    """This process (and the programs it starts) on one core, the first it may use."""
    allowed = os.sched_getaffinity(0)
    os.sched_setaffinity(0, {min(allowed)})
    try:
        yield
    finally:
        os.sched_setaffinity(0, allowed)


def clock_costs_ns(count):
    """The median empty interval of Python's clock and of the C++ clock, each read as the timings
    below read it: what reading the clock adds to every time, taken off it."""
    clock, empty = time.perf_counter_ns, []
    for _ in range(count):
        start = clock()
        empty.append(clock() - start)
    return statistics.median(empty), statistics.median(_baize._native_clock_ns(count))


def single_shot_figures(shots, repeats):
    """Per shot, the median over `repeats` runs of: baize.simulate; and in C++, engine::runScene as
    simulate runs it and `baize bench shots` times it (no trajectories), its result freed. The two
    run in turn, so that they see the same load, and each clock's own cost is taken off its times.
    Returns the medians over shots of those times (ns) and of the per-shot ratios simulate / C++."""
    clock, simulate, native = time.perf_counter_ns, baize.simulate, _baize._native_run_times_ns
    per_shot = []
    with one_core():
        for scene in shots:  # untimed warm-up: the cushion model's tables, the caches
            simulate(scene)
        python_clock_ns, native_clock_ns = clock_costs_ns(len(shots) * repeats)
        for scene in shots:
            python_ns, native_ns = [], []
            for _ in range(repeats):
                start = clock()
                simulate(scene)
                python_ns.append(clock() - start - python_clock_ns)
                native_ns.append(native(scene, 1, False)[0] - native_clock_ns)
            per_shot.append([statistics.median(t) for t in (python_ns, native_ns)])
    python_ns, native_ns = zip(*per_shot)
    return {"python_us": statistics.median(python_ns) / 1e3,
            "native_us": statistics.median(native_ns) / 1e3,
            "ratio": statistics.median(p / q for p, q in per_shot),
            "python_clock_ns": python_clock_ns, "native_clock_ns": native_clock_ns}


def timed_s(work):
    start = time.perf_counter()
    work()
    return time.perf_counter() - start


def batch_file(scenes, folder, copies):
    """The scenes as `baize batch` input, one scene file's JSON per line, `copies` times over."""
    path = os.path.join(folder, f"shots-x{copies}.jsonl")
    with open(path, "w") as out:
        for _ in range(copies):
            for scene in scenes:
                out.write(scene.to_json() + "\n")
    return path


def run_batch(program, path):
    done = subprocess.run([program, "batch", path, "--threads", "1", "--quiet"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        sys.exit(f"bench_python.py: {program} batch exited {done.returncode}: {done.stderr.strip()}")
    return done.stdout


def check_same_shots(scenes, batch_output):
    """The batch ran the same shots: its final positions are simulate's, to the bit."""
    lines = batch_output.splitlines()
    if len(lines) != len(scenes):
        sys.exit(f"bench_python.py: baize batch wrote {len(lines)} lines for {len(scenes)} shots")
    for k in range(0, len(scenes), max(1, len(scenes) // 20)):
        result, line = baize.simulate(scenes[k]), json.loads(lines[k])
        for ball, (x, y) in zip(result.ball_ids, result.final_positions.tolist()):
            at = line["final_positions_m"][ball]
            if at is not None and at != [x, y]:
                sys.exit(f"bench_python.py: shot {k}: baize batch put ball {ball} at {at}, "
                         f"baize.simulate at {[x, y]}: not the same shots")


def batch_figures(scenes, repeats, program):
    """Shots per second of simulate_many on 1 thread and of `baize batch --threads 1`, both on one
    core, and of simulate_many on 2 threads, run in turn `repeats` times: their medians, and the
    median of the 2-thread / 1-thread ratios of each turn (side by side, so a slow spell of the
    machine does not fall on one side alone). Both run warm: simulate_many after an untimed pass;
    the batch as the time of two more passes over the shots in one process less that of one pass
    (its start and the cushion table's first build taken away)."""
    one, batch, two = [], [], []
    with tempfile.TemporaryDirectory() as folder:
        if program:
            once, thrice = batch_file(scenes, folder, 1), batch_file(scenes, folder, 3)
            check_same_shots(scenes, run_batch(program, once))
        baize.simulate_many(scenes, threads=1)  # untimed: the cushion model's tables
        for _ in range(repeats):
            with one_core():
                one.append(len(scenes) / timed_s(lambda: baize.simulate_many(scenes, threads=1)))
            two.append(len(scenes) / timed_s(lambda: baize.simulate_many(scenes, threads=2)))
            if program:
                with one_core():
                    extra_s = timed_s(lambda: run_batch(program, thrice)) - timed_s(
                        lambda: run_batch(program, once))
                batch.append(2 * len(scenes) / extra_s)
    return (statistics.median(one), statistics.median(batch) if batch else None,
            statistics.median(two), statistics.median(t / o for t, o in zip(two, one)))


def dask_figures(scenes, chunk):
    import baize.dask
    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                      host="127.0.0.1") as cluster, Client(cluster) as client:
        baize.dask.simulate_on(client, scenes[:chunk], chunk=chunk, threads=1)  # warm the workers
        start = time.perf_counter()
        baize.dask.simulate_on(client, scenes, chunk=chunk, threads=1)
        dask_s = time.perf_counter() - start
    start = time.perf_counter()
    baize.simulate_many(scenes, threads=2)
    local_s = time.perf_counter() - start
    chunks = -(-len(scenes) // chunk)
    return len(scenes) / dask_s, (dask_s - local_s) / chunks * 1e3, chunks


def arguments(argv):
    quick, program, k = False, "build/baize", 0
    while k < len(argv):
        if argv[k] == "--quick":
            quick, k = True, k + 1
        elif argv[k] == "--baize" and k + 1 < len(argv) and argv[k + 1]:
            program, k = argv[k + 1], k + 2
        else:
            sys.exit(f"bench_python.py: unknown or incomplete argument '{argv[k]}' "
                     "(allowed: --quick, --baize PATH)")
    return quick, (program if os.access(program, os.X_OK) else None)


def main():
    quick, program = arguments(sys.argv[1:])
    single, repeats = (20, 3) if quick else (300, 21)
    batch, batch_repeats = (200, 1) if quick else (5000, 9)
    dask_shots, chunk = (200, 50) if quick else (10000, 500)
    s = single_shot_figures(baize.random_shots(single, seed=1), repeats)
    scenes = baize.random_shots(batch, seed=2)
    one, batch_rate, two, scaling = batch_figures(scenes, batch_repeats, program)
    lines = [
        "## Python (`tools/bench_python.py`)",
        "",
        f"- `baize.simulate`, one random single shot ({single} shots x {repeats} runs on one core, "
        f"interleaved with the same shot in C++ in the same process): median {s['python_us']:.2f} "
        f"us against {s['native_us']:.2f} us for `engine::runScene` (what `baize bench shots` "
        f"times), ratio {s['ratio']:.3f} (ratios: median "
        "over shots of each shot's median times; each clock's own cost, measured empty, taken off: "
        f"{s['python_clock_ns']:.0f} ns in Python, {s['native_clock_ns']:.0f} ns in C++).",
        f"- `baize.simulate_many` on {batch} random shots: {one:.0f} shots/s on 1 thread (one core), "
        f"{two:.0f} shots/s on 2 threads (two cores): ratio {scaling:.2f} (median of "
        f"the ratios of {batch_repeats} pairs of runs side by side).",
    ]
    if batch_rate is None:
        lines.append("- `baize batch`: not measured (no baize program: built with "
                     "BAIZE_WITH_RENDER=OFF, or --baize not given).")
    else:
        lines.append(f"- `baize batch --threads 1` on the same {batch} shots as JSON lines, on the "
                     f"same core, in turn with `simulate_many`, warm (two more passes over the "
                     f"shots in one process less one pass): {batch_rate:.0f} shots/s; "
                     f"`simulate_many` per core / `baize batch` per core: {one / batch_rate:.2f}.")
    try:
        rate, overhead_ms, chunks = dask_figures(baize.random_shots(dask_shots, seed=3), chunk)
        lines.append(f"- `baize.dask`, LocalCluster of two worker processes, {dask_shots} shots in "
                     f"{chunks} chunks of {chunk}: {rate:.0f} shots/s; overhead per chunk "
                     f"{overhead_ms:.1f} ms (Dask's wall time less `simulate_many` on 2 threads).")
    except ImportError:
        lines.append("- `baize.dask`: not measured (python3-distributed is not installed).")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
