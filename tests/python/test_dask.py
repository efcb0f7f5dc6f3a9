"""baize.dask: a batch spread over a local Dask cluster of two workers gives the same results, in
the same order, as one process."""
import pytest

import baize

distributed = pytest.importorskip("dask.distributed")
import baize.dask  # noqa: E402


@pytest.fixture(scope="module")
def client():
    # Two worker processes on this machine, no network beyond the loopback, no dashboard.
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, host="127.0.0.1") as cluster:
        with distributed.Client(cluster) as c:
            yield c


def test_ten_thousand_seeded_shots_match_one_process(client):
    scenes = baize.random_shots(10_000, seed=2026)
    here = baize.simulate_many(scenes, threads=1)
    spread = baize.dask.simulate_on(client, scenes, chunk=1000, threads=1)
    assert len(spread) == len(here)
    for a, b in zip(here, spread):
        assert a.events == b.events and a.pocketed == b.pocketed
        assert a.final_positions.tobytes() == b.final_positions.tobytes()


def test_a_failed_shot_is_named_by_its_place_in_the_whole_batch(client):
    good = baize.random_shots(7, seed=5)
    bad = baize.Scene(table="pool-9ft", ball_set="pool", rack={"name": "9-ball"},
                      shot={"aim_at": "1", "speed_mps": 8}, physics={"max_events": 3})
    with pytest.raises(baize.BatchError) as failed:
        baize.dask.simulate_on(client, good[:5] + [bad] + good[5:], chunk=3)
    assert [e.index for e in failed.value.errors] == [5]
    assert len(failed.value.results) == 8
    with pytest.raises(ValueError, match="chunk"):
        baize.dask.simulate_on(client, good, chunk=0)
