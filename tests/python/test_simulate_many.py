"""baize.simulate_many: every core, input order, the same bits as one by one, failures kept."""
import pytest

import baize


def same(a, b):
    return (a.events == b.events and a.pocketed == b.pocketed and
            a.final_positions.tobytes() == b.final_positions.tobytes())


def test_many_equal_one_by_one_in_order():
    scenes = baize.random_shots(200, seed=11)
    one_by_one = [baize.simulate(s) for s in scenes]
    for threads in (0, 1, 2, 3):
        many = baize.simulate_many(scenes, threads=threads)
        assert len(many) == len(scenes)
        assert all(same(a, b) for a, b in zip(one_by_one, many))


def test_a_failed_shot_keeps_the_others():
    good = baize.random_shots(5, seed=2)
    bad = baize.Scene(table="pool-9ft", ball_set="pool", rack={"name": "9-ball"},
                      shot={"aim_at": "1", "speed_mps": 8}, physics={"max_events": 3})
    scenes = good[:2] + [bad] + good[2:]
    with pytest.raises(baize.BatchError) as failed:
        baize.simulate_many(scenes, threads=2)
    error = failed.value
    assert "shot 2" in str(error) and len(error.results) == 6
    assert [e.index for e in error.errors] == [2] and error.errors[0].kind == "RuntimeError"
    assert isinstance(error.results[2], baize.ShotError)
    kept = [r for i, r in enumerate(error.results) if i != 2]
    assert all(same(a, baize.simulate(s)) for a, s in zip(kept, good))
    returned = baize.simulate_many(scenes, on_error="return")
    assert isinstance(returned[2], baize.ShotError) and same(returned[3], kept[2])


def test_bad_arguments_are_named():
    with pytest.raises(TypeError, match=r"scenes\[1\] is of type str"):
        baize.simulate_many([baize.random_shots(1)[0], "x"])
    with pytest.raises(ValueError, match="threads = -1"):
        baize.simulate_many([], threads=-1)
    with pytest.raises(ValueError, match="on_error"):
        baize.simulate_many([], on_error="ignore")
    assert baize.simulate_many([]) == []
