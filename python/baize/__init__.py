"""Baize: an event-based pool and snooker table simulator, from Python.

    import baize
    scene = baize.load_scene("9-ball-break.json")      # or baize.Scene(table=..., ...)
    result = baize.simulate(scene)
    result.events, result.final_positions, result.pocketed, result.sample([0.5, 1.0])
    results = baize.simulate_many(baize.random_shots(1000, seed=1))

See docs/python.md. baize.dask spreads a batch over a Dask cluster.
"""
from ._baize import (Event, Result, Scene, ShotError, cushion_impact, load_scene,
                     random_shots, simulate, simulate_many, with_render)

if with_render:
    from ._baize import render_png

__version__ = "0.2"


class BatchError(RuntimeError):
    """Some shots of simulate_many failed; every shot ran.

    results: the whole list in the input's order, a ShotError (index, kind, message) in place of
    each failed shot's Result. errors: the ShotErrors alone, in order.
    """

    def __init__(self, message, results, errors):
        super().__init__(message)
        self.results = list(results)
        self.errors = list(errors)


__all__ = ["BatchError", "Event", "Result", "Scene", "ShotError", "cushion_impact", "load_scene",
           "random_shots", "simulate", "simulate_many", "with_render"] + (
               ["render_png"] if with_render else [])
