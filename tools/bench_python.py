#!/usr/bin/env python3
"""Benchmarks of the Python package (not a test): prints a Markdown section for docs/benchmarks.md.

- baize.simulate on random single shots against the same shots run in C++ alone (the binding's
  overhead), median over runs interleaved shot by shot;
- baize.simulate_many on 1 and 2 threads: shots per second and their ratio (two cores);
- baize.dask on a LocalCluster of two worker processes: throughput, and the overhead per chunk
  (Dask's wall time less simulate_many's on two threads, per chunk).

Usage: PYTHONPATH=build/python /usr/bin/python3 tools/bench_python.py [--quick]
"""
import statistics
import sys
import time

import baize
from baize import _baize


def median_ratio_python_to_native(shots, repeats):
    python_ns, native_ns = [], []
    for scene in shots:
        for _ in range(repeats):  # interleaved: both see the same machine load
            start = time.perf_counter_ns()
            baize.simulate(scene)
            python_ns.append(time.perf_counter_ns() - start)
            native_ns.extend(_baize._native_run_times_ns(scene, 1))
    return statistics.median(python_ns), statistics.median(native_ns)


def shots_per_second(scenes, threads, repeats):
    rates = []
    for _ in range(repeats):
        start = time.perf_counter()
        baize.simulate_many(scenes, threads=threads)
        rates.append(len(scenes) / (time.perf_counter() - start))
    return statistics.median(rates)


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


def main():
    quick = "--quick" in sys.argv[1:]
    single, repeats = (20, 3) if quick else (300, 21)
    batch, batch_repeats = (200, 1) if quick else (5000, 5)
    dask_shots, chunk = (200, 50) if quick else (10000, 500)
    python_ns, native_ns = median_ratio_python_to_native(baize.random_shots(single, seed=1), repeats)
    scenes = baize.random_shots(batch, seed=2)
    one = shots_per_second(scenes, 1, batch_repeats)
    two = shots_per_second(scenes, 2, batch_repeats)
    lines = [
        "## Python (`tools/bench_python.py`)",
        "",
        f"- `baize.simulate`, one random single shot: median {python_ns / 1e3:.1f} us against "
        f"{native_ns / 1e3:.1f} us for the same shot in C++ alone: ratio {python_ns / native_ns:.3f} "
        f"({single} shots x {repeats} runs, interleaved).",
        f"- `baize.simulate_many` on {batch} random shots: {one:.0f} shots/s on 1 thread, {two:.0f} "
        f"shots/s on 2 threads (two cores): ratio {two / one:.2f} (median of {batch_repeats}).",
    ]
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
