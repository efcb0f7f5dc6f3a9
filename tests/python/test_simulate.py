"""baize.simulate and its Result: events, final positions, pocketed balls, samples."""
import pickle
import threading

import numpy as np
import pytest

import baize


@pytest.fixture
def stun(scenes_dir):
    return baize.simulate(baize.load_scene(str(scenes_dir / "stun-shot.json")))


def test_the_stun_shot_pots_the_one_ball(stun):
    assert stun.first_ball_hit == "1"
    assert [ball for ball, _ in stun.pocketed] == ["1"]
    assert stun.foul == "none"
    kinds = [e.kind for e in stun.events]
    assert kinds.count("ball-ball") == 1 and kinds.count("pocket") == 1
    pocket = next(e for e in stun.events if e.kind == "pocket")
    assert pocket.balls == ["1"] and pocket.pocket == stun.pocketed[0][1] and pocket.cushion is None


def test_events_are_in_time_order_and_end_at_rest(stun):
    times = [e.time for e in stun.events]
    assert times == sorted(times) and times[-1] <= stun.end_time


def test_final_positions_are_n_by_2_and_agree_with_samples(stun):
    final = stun.final_positions
    assert final.shape == (2, 2) and final.dtype == np.float64
    samples = stun.sample([0.0, stun.end_time, stun.end_time + 5.0])
    assert samples.shape == (2, 3, 2)
    cue = stun.ball_ids.index("cue")
    np.testing.assert_array_equal(samples[cue, 1], final[cue])  # the cue ball where it stopped
    np.testing.assert_array_equal(samples[cue, 2], final[cue])  # and stays there


def test_samples_start_where_the_scene_put_the_balls(scenes_dir):
    scene = baize.load_scene(str(scenes_dir / "draw-shot.json"))
    result = baize.simulate(scene)
    np.testing.assert_array_equal(result.sample([0.0])[:, 0, :], scene.positions)
    path = result.sample(np.linspace(0, result.end_time, 50))[result.ball_ids.index("cue")]
    assert np.all(np.abs(path[:, 0]) < 1.3) and np.all(np.abs(path[:, 1]) < 0.65)  # on the table


@pytest.mark.parametrize("bad", [[-1.0], [float("nan")], [[0.0, 1.0]]])
def test_bad_sample_times_are_a_value_error(stun, bad):
    with pytest.raises(ValueError, match="time|dimension"):
        stun.sample(bad)


def test_results_pickle_to_the_same_bits(stun):
    copy = pickle.loads(pickle.dumps(stun))
    assert copy.events == stun.events and copy.pocketed == stun.pocketed
    assert copy.final_positions.tobytes() == stun.final_positions.tobytes()
    times = np.linspace(0, stun.end_time, 17)
    assert copy.sample(times).tobytes() == stun.sample(times).tobytes()


def test_a_break_lists_its_impacts_beyond_the_cushion_models_range(scenes_dir):
    scene = baize.load_scene(str(scenes_dir / "8-ball-break.json"))
    result = baize.simulate(scene)
    beyond = result.beyond_model_range
    assert beyond and beyond == sorted(beyond), beyond
    assert all(result.events[i].kind in ("cushion", "jaw") for i in beyond)
    assert pickle.loads(pickle.dumps(result)).beyond_model_range == beyond


def test_the_scenes_limit_changes_the_count():
    def beyond(physics):
        return baize.simulate(baize.Scene(table="pool-9ft", ball_set="pool", rack={"name": "9-ball"},
                                          shot={"aim_at": "1", "speed_mps": 8},
                                          physics=physics)).beyond_model_range
    assert beyond({}), "an 8 m/s break hits a cushion above 2.5 m/s"
    assert beyond({"cushion": {"valid_normal_speed_mps": 100}}) == []


def test_a_soft_shot_has_none_beyond_the_models_range(stun):
    assert stun.beyond_model_range == []


def test_a_shot_that_cannot_finish_raises(scenes_dir):
    scene = baize.Scene(table="pool-9ft", ball_set="pool", rack={"name": "9-ball"},
                        shot={"aim_at": "1", "speed_mps": 8}, physics={"max_events": 3})
    with pytest.raises(RuntimeError, match="3"):
        baize.simulate(scene)


def test_simulate_wants_a_scene():
    with pytest.raises(TypeError, match="scene is of type str, not a baize.Scene"):
        baize.simulate("9-ball-break.json")
    with pytest.raises(TypeError, match="holding no scene"):
        baize.simulate(baize.Scene.__new__(baize.Scene))
    scene = baize.random_shots(1, seed=1)[0]
    assert baize.simulate(scene=scene).events == baize.simulate(scene).events

    class MyScene(baize.Scene):  # a subclass goes the general way, with the same result
        pass

    mine = MyScene(table="pool-9ft", ball_set="pool", balls={"cue": (-0.6, 0.0), "1": (0.4, 0.02)},
                   shot={"aim_at": "1", "speed_mps": 2.5})
    same = baize.Scene(table="pool-9ft", ball_set="pool", balls={"cue": (-0.6, 0.0), "1": (0.4, 0.02)},
                       shot={"aim_at": "1", "speed_mps": 2.5})
    assert baize.simulate(mine).events == baize.simulate(same).events
    with pytest.raises(TypeError, match="one argument, scene; got 0 by position"):
        baize.simulate()
    with pytest.raises(TypeError, match="got 2 by position"):
        baize.simulate(scene, scene)
    with pytest.raises(TypeError, match="no argument 'scenes'"):
        baize.simulate(scenes=scene)


def test_a_result_pickled_before_it_is_read_answers_as_one_read_first(scenes_dir):
    # pocketed, foul, beyond_model_range and sample's cloth are derived on first use.
    scene = baize.load_scene(str(scenes_dir / "8-ball-break.json"))
    read, unread = baize.simulate(scene), baize.simulate(scene)
    answers = (read.pocketed, read.first_ball_hit, read.foul, read.beyond_model_range)
    copy = pickle.loads(pickle.dumps(unread))
    assert (copy.pocketed, copy.first_ball_hit, copy.foul, copy.beyond_model_range) == answers
    assert answers[3], "the break has impacts beyond the model's range, so the check means something"
    times = np.linspace(0, read.end_time, 9)
    assert copy.sample(times).tobytes() == read.sample(times).tobytes()


def test_sampling_records_the_same_run_as_the_one_simulated(scenes_dir):
    # The trajectories are recorded when first sampled, by running the shot again: what the result
    # showed before must not change, and the samples must end where the balls stopped.
    result = baize.simulate(baize.load_scene(str(scenes_dir / "9-ball-break.json")))
    before = ([(e.time, e.kind, e.balls) for e in result.events], result.final_positions.tobytes())
    samples = result.sample([result.end_time])
    after = ([(e.time, e.kind, e.balls) for e in result.events], result.final_positions.tobytes())
    assert before == after and len(before[0]) > 50
    down = [i for i, b in enumerate(result.ball_ids) if b not in dict(result.pocketed)]
    np.testing.assert_array_equal(samples[down, 0, :], result.final_positions[down])


def test_shots_simulated_on_python_threads_are_the_same_as_in_turn():
    scenes = baize.random_shots(40, seed=5)
    alone = [baize.simulate(s).events for s in scenes]
    together = [None] * len(scenes)

    def work(first):
        for k in range(first, len(scenes), 2):
            together[k] = baize.simulate(scenes[k]).events

    threads = [threading.Thread(target=work, args=(first,)) for first in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert together == alone


def test_cushion_impact_head_on_rolling():
    out = baize.cushion_impact()
    assert out["velocity"].shape == (3,)
    assert 0 < out["rebound_speed"] < 1.0  # slower than it came in
    assert abs(out["rebound_angle_deg"] - 90) < 1e-9  # straight back, no sidespin
    paper = baize.cushion_impact(solver="paper", steps=20000)
    assert abs(paper["rebound_speed"] - out["rebound_speed"]) < 1e-3
    with pytest.raises(ValueError, match="solver"):
        baize.cushion_impact(solver="magic")
    with pytest.raises(ValueError):
        baize.cushion_impact(restitution=2.0)
    with pytest.raises(ValueError, match="speed"):
        baize.cushion_impact(speed=float("inf"))


def test_cushion_impact_takes_the_shipped_speed_dependence(prefix):
    """The snooker fit, read from the shipped file: no change at or below the knee; above it the
    rebound ratio falls while the rebound speed still rises."""
    import json
    shipped = json.loads((prefix / "share" / "baize" / "measurements" /
                          "snooker-speed-dependence.json").read_text())
    law = shipped["cushion"]["restitution_speed_dependence"]
    knee = law["knee_speed_mps"]
    slow = baize.cushion_impact(speed=0.5 * knee, restitution_speed_dependence=law)
    assert slow["rebound_speed"] == baize.cushion_impact(speed=0.5 * knee)["rebound_speed"]
    fast, faster = (baize.cushion_impact(speed=s * knee, restitution_speed_dependence=law)
                    for s in (2, 3))
    constant = baize.cushion_impact(speed=2 * knee)
    assert fast["rebound_speed"] < constant["rebound_speed"]
    assert faster["rebound_speed"] > fast["rebound_speed"]
    assert faster["rebound_speed"] / (3 * knee) < fast["rebound_speed"] / (2 * knee)
    with pytest.raises(ValueError, match="falloff_exponent = 2"):
        baize.cushion_impact(restitution_speed_dependence={"knee_speed_mps": 2, "falloff_exponent": 2})
    with pytest.raises(ValueError, match="knee_speed"):
        baize.cushion_impact(restitution_speed_dependence={"falloff_exponent": 0.3})
    with pytest.raises(ValueError, match="'knee' is not allowed"):
        baize.cushion_impact(restitution_speed_dependence={"knee": 2, "falloff_exponent": 0.3})


@pytest.mark.skipif(not baize.with_render, reason="built without rendering")
def test_render_png_writes_a_picture(tmp_path, scenes_dir):
    scene = baize.load_scene(str(scenes_dir / "stun-shot.json"))
    path = tmp_path / "stun.png"
    baize.render_png(scene, str(path), width=320, height=160)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="width"):
        baize.render_png(scene, str(path), width=1)


def test_a_speed_dependent_restitution_passes_through_and_slows_a_fast_rebound():
    def scene(cushion):
        return baize.Scene(table="pool-9ft", ball_set="pool", balls={"cue": [0.0, 0.0]},
                           shot={"heading_deg": 0, "speed_mps": 4, "height": 0.4},
                           physics={"cushion": cushion})

    def way_back(cushion):  # how far the cue ball is from the foot cushion 0.4 s after hitting it
        result = baize.simulate(scene(cushion))
        hit = next(e.time for e in result.events if e.kind == "cushion")
        return 1.27 - result.sample([hit + 0.4])[result.ball_ids.index("cue"), 0, 0]
    law = {"knee_speed_mps": 1.0, "falloff_exponent": 0.5}
    assert 0 < way_back({"restitution_speed_dependence": law}) < 0.8 * way_back({})
    with pytest.raises(ValueError, match="falloff_exponent"):
        scene({"restitution_speed_dependence": {"knee_speed_mps": 1.0, "falloff_exponent": 3}})
