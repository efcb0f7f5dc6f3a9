"""Spreading a batch of shots over a Dask cluster (docs/python.md, "Many machines").

    from dask.distributed import Client
    import baize, baize.dask
    client = Client("tcp://scheduler:8786")       # or Client(LocalCluster(...))
    results = baize.dask.simulate_on(client, baize.random_shots(100_000, seed=7))

The scenes travel to the workers pickled (as their self-contained scene documents), each worker
runs its chunk with baize.simulate_many on its own threads, and the chunks come back in order:
the list is the input's order and the same as baize.simulate_many on one machine gives.
"""
import baize

# Shots per chunk: enough that a chunk's work (tens of milliseconds) outweighs Dask's per-task
# overhead (a millisecond or so), few enough that two workers share a batch of thousands evenly.
DEFAULT_CHUNK = 500


def _run_chunk(scenes, threads):
    return baize.simulate_many(scenes, threads=threads, on_error="return")


def chunks_of(scenes, chunk):
    """The scenes in consecutive chunks of at most `chunk` (a positive int)."""
    if not isinstance(chunk, int) or isinstance(chunk, bool) or chunk < 1:
        raise ValueError(f"chunk = {chunk!r} is not allowed: it must be an int >= 1")
    scenes = list(scenes)
    return [scenes[i:i + chunk] for i in range(0, len(scenes), chunk)]


def simulate_on(client, scenes, chunk=DEFAULT_CHUNK, threads=0, on_error="raise"):
    """Simulates the scenes on the client's workers, chunk by chunk, and gathers them in order.

    threads: per worker, as in simulate_many (0: every core of its machine). Failed shots are
    reported as simulate_many reports them (a ShotError at their index in the whole list; with
    on_error='raise' a BatchError after all have run).
    """
    if on_error not in ("raise", "return"):
        raise ValueError(f"on_error = {on_error!r} is not allowed: it must be 'raise' or 'return'")
    parts = chunks_of(scenes, chunk)
    futures = client.map(_run_chunk, parts, threads=threads, pure=False)
    results = []
    errors = []
    for part in client.gather(futures):
        for entry in part:
            if isinstance(entry, baize.ShotError):  # its index is the chunk's: make it the list's
                entry = baize.ShotError(len(results), entry.kind, entry.message)
                errors.append(entry)
            results.append(entry)
    if errors and on_error == "raise":
        raise baize.BatchError(f"{len(errors)} of {len(results)} shots failed; the first, shot "
                               f"{errors[0].index}: {errors[0].message}", results, errors)
    return results
