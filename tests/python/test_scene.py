"""baize.Scene and baize.load_scene: the scene file's checks and messages, from Python values."""
import pickle

import numpy as np
import pytest

import baize

SHOT = {"aim_at": "1", "speed_mps": 2.0}
BALLS = {"cue": (-0.6, 0.0), "1": (0.4, 0.0)}


def test_the_package_is_the_installed_one(prefix):
    assert str(prefix) in baize.__file__


def test_scene_from_values_matches_the_same_file(tmp_path):
    scene = baize.Scene(table="pool-9ft", ball_set="pool", balls=BALLS, shot=SHOT)
    assert sorted(scene.ball_ids) == ["1", "cue"]
    at = dict(zip(scene.ball_ids, scene.positions.tolist()))
    assert at == {"cue": [-0.6, 0.0], "1": [0.4, 0.0]}
    path = tmp_path / "s.json"
    path.write_text(scene.to_json())
    loaded = baize.load_scene(str(path))
    a, b = baize.simulate(scene), baize.simulate(loaded)
    assert a.events == b.events
    assert a.final_positions.tobytes() == b.final_positions.tobytes()


def test_numpy_values_are_accepted():
    scene = baize.Scene(table="pool-9ft", ball_set="pool",
                        balls={"cue": np.array([-0.6, 0.0]), "1": (np.float64(0.4), np.int64(0))},
                        shot={"aim_at": "1", "speed_mps": np.float32(2.0)})
    assert scene.positions[scene.ball_ids.index("1"), 0] == 0.4


def test_a_rack_by_name():
    scene = baize.Scene(table="pool-9ft", ball_set="pool", rack={"name": "9-ball"},
                        shot={"aim_at": "1", "speed_mps": 8})
    assert len(scene.ball_ids) == 10 and "cue" in scene.ball_ids and scene.cue_ball == "cue"


def file_message(tmp_path, document):
    """The message the scene reader gives for the same document as a file."""
    import json
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(document))
    with pytest.raises(ValueError) as refused:
        baize.load_scene(str(path))
    return str(refused.value).replace(str(path), "Scene")


@pytest.mark.parametrize("key, bad, named", [
    ("table", "pool-10ft", "pool-10ft"),
    ("shot", {"aim_at": "1", "speed_mps": 99.0}, "99"),
    ("shot", {"aim_at": "7", "speed_mps": 2.0}, "7"),
    ("balls", {"cue": (-0.6, 0.0), "1": (-0.6, 0.01)}, "overlap"),
])
def test_bad_values_are_refused_as_a_file_would_be(tmp_path, key, bad, named):
    values = {"table": "pool-9ft", "ball_set": "pool", "balls": BALLS, "shot": SHOT}
    values[key] = bad
    with pytest.raises(ValueError) as refused:
        baize.Scene(**values)
    message = str(refused.value)
    assert named in message
    assert message == file_message(tmp_path, {k: (dict(v) if isinstance(v, dict) else v)
                                              for k, v in values.items()})


def test_values_json_cannot_hold_are_a_type_error():
    with pytest.raises(TypeError, match=r"shot\.speed_mps is a object"):
        baize.Scene(table="pool-9ft", ball_set="pool", balls=BALLS,
                    shot={"aim_at": "1", "speed_mps": object()})
    with pytest.raises(TypeError, match="keys must be str"):
        baize.Scene(table="pool-9ft", ball_set="pool", balls={1: (0, 0)}, shot=SHOT)


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises((ValueError, RuntimeError, OSError), match="nowhere.json"):
        baize.load_scene(str(tmp_path / "nowhere.json"))


def test_scenes_pickle_to_the_same_scene(scenes_dir):
    scene = baize.load_scene(str(scenes_dir / "9-ball-break.json"))
    copy = pickle.loads(pickle.dumps(scene))
    assert copy.to_json() == scene.to_json()
    assert baize.simulate(copy).events == baize.simulate(scene).events


def test_random_shots_are_seeded():
    a, b = baize.random_shots(20, seed=3), baize.random_shots(30, seed=3)
    assert [s.to_json() for s in a] == [s.to_json() for s in b[:20]]
    assert a[0].to_json() != baize.random_shots(1, seed=4)[0].to_json()
    with pytest.raises(ValueError, match="count = -1"):
        baize.random_shots(-1)
