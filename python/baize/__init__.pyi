# Type stubs for the Python package baize (docs/python.md).
from typing import Any, Iterable, Literal, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str
with_render: bool

class Scene:
    def __init__(self, table: Union[str, Mapping[str, Any]], ball_set: Union[str, Mapping[str, Any]],
                 shot: Mapping[str, Any], balls: Optional[Mapping[str, Sequence[float]]] = ...,
                 rack: Optional[Mapping[str, Any]] = ..., physics: Optional[Mapping[str, Any]] = ...) -> None: ...
    @property
    def ball_ids(self) -> list[str]: ...
    @property
    def positions(self) -> npt.NDArray[np.float64]: ...  # n x 2, m
    @property
    def table(self) -> str: ...
    @property
    def cue_ball(self) -> str: ...
    def to_json(self) -> str: ...

class Event:
    time: float  # s
    kind: str    # 'ball-ball', 'cushion', 'jaw', 'pocket', 'state change'
    balls: list[str]
    cushion: Optional[int]
    pocket: Optional[int]

class Result:
    @property
    def events(self) -> list[Event]: ...
    @property
    def ball_ids(self) -> list[str]: ...
    @property
    def final_positions(self) -> npt.NDArray[np.float64]: ...  # n x 2, m
    @property
    def pocketed(self) -> list[tuple[str, int]]: ...
    @property
    def first_ball_hit(self) -> Optional[str]: ...
    @property
    def foul(self) -> str: ...
    @property
    def end_time(self) -> float: ...
    def sample(self, times: npt.ArrayLike) -> npt.NDArray[np.float64]: ...  # n_balls x n_times x 2

class ShotError:
    index: int
    kind: str
    message: str

class BatchError(RuntimeError):
    results: list[Union[Result, ShotError]]
    errors: list[ShotError]

def load_scene(path: str) -> Scene: ...
def random_shots(count: int, seed: int = ...) -> list[Scene]: ...
def simulate(scene: Scene) -> Result: ...
def simulate_many(scenes: Iterable[Scene], threads: int = 0,
                  on_error: Literal["raise", "return"] = "raise") -> list[Union[Result, ShotError]]: ...
def cushion_impact(*, speed: float = 1.0, angle_deg: float = 90.0, topspin: float = 1.0,
                   sidespin: float = 0.0, solver: Literal["exact", "paper"] = "exact",
                   mass: float = ..., radius: float = ..., contact_height: Optional[float] = None,
                   restitution: float = ..., cushion_friction: float = ..., cloth_friction: float = ...,
                   restitution_speed_dependence: Optional[dict[str, float]] = None, steps: int = 5000, tolerance: Optional[float] = None) -> dict[str, Any]: ...
def render_png(scene: Scene, path: str, *, result: Optional[Result] = None, width: int = 1600,
               height: int = 800, view: Literal["top", "angled"] = "top", legend: bool = False) -> None: ...
