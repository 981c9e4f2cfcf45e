"""tide: SPH fluid simulation from Python (docs/python.md).

    import tide
    world = tide.World("scenes/dam_break.json")      # or a dict with the scene format's keys
    world.run(0.5, callback=lambda w: print(w.time, w.positions[:, 0].max()))

The particle arrays (world.positions, velocities, densities, pressures, materials, ids) are
numpy views of the engine's own memory: no copy, read-only; set velocities with
world.set_velocities().
"""
import json
import math
import os
import sys
import time as _time

import numpy as np

from . import _tide
from ._tide import DivergenceError, Fluid, FluidSettings, Material, SceneError
from . import io, waves

__all__ = ["World", "Fluid", "FluidSettings", "Material", "SceneError", "DivergenceError", "io", "waves"]


def _check_finite(value, path):
    """JSON has no NaN or infinity: refuse them here, naming the field as the parser would."""
    if isinstance(value, float) and not math.isfinite(value):
        raise SceneError(f"{path}: must be finite, got {value}")
    if isinstance(value, dict):
        for key, item in value.items():
            _check_finite(item, f"{path}.{key}" if path else str(key))
    elif isinstance(value, (list, tuple)):
        for i, item in enumerate(value):
            _check_finite(item, f"{path}[{i}]")


def _plain(value):
    """numpy scalars and arrays as the JSON numbers and lists they stand for."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"{type(value).__name__} is not a scene value")


def _json_text(entry, path=""):
    try:
        text = json.dumps(entry, default=_plain)
    except TypeError as e:
        raise SceneError(f"{path or '(scene)'}: {e}") from None
    _check_finite(json.loads(text), path)
    return text


class World(_tide.World):
    """One simulation, from a scene file (a path) or a dict with the scene format's keys.

    Both go through the same scene parser (docs/scene-format.md): a bad scene raises
    tide.SceneError (a ValueError) whose message names each field at fault, e.g.
    ``blocks[0].material: unknown material "oil"``.

    threads: worker threads (0: all cores). capacity: most particles the world may hold
    (default: the scene's estimate, as `tide run`); its arrays are reserved for that many, so
    the numpy views stay valid while emitters and add_block add particles. settle: apply the
    scene's ``settle`` pre-roll now (as `tide run` does before frame 0).
    """

    def __init__(self, scene, *, threads=0, capacity=None, settle=True):
        if isinstance(scene, dict):
            text, source, base = _json_text(scene), "<dict>", os.getcwd()
        elif isinstance(scene, (str, os.PathLike)):
            path = os.fspath(scene)
            try:
                with open(path, "rb") as f:
                    text = f.read().decode("utf-8")
            except OSError as e:
                raise SceneError(f"{path}: cannot open the scene file ({e.strerror})") from None
            source, base = path, os.path.dirname(os.path.abspath(path))
        else:
            raise TypeError(f"scene: must be a path or a dict, got {type(scene).__name__}")
        super().__init__(text, source, base, threads, 0 if capacity is None else int(capacity), settle)
        self._built = True

    def __repr__(self):
        # A world whose scene was refused has no C++ object behind it: pytest's traceback
        # printed one and crashed the interpreter.
        if not getattr(self, "_built", False):
            return "<tide.World (not built)>"
        return (f"<tide.World {self.name!r}: {self.particle_count} particles, t = {self.time:g} s, "
                f"{self.stats['solver']}>")

    # -- adding from dicts (the scene format's entries) ---------------------------------------
    def add_block(self, block):
        """Fill a box with particles: a dict as an entry of the scene's "blocks" (min, max,
        material, velocity, concentration). Returns the number of particles added."""
        return self._add_block(_json_text(block, "block"))

    def add_emitter(self, emitter):
        """Add a continuous source: a dict as an entry of "emitters". Returns its index."""
        return self._add_emitter(_json_text(emitter, "emitter"))

    def add_obstacle(self, obstacle):
        """Add an obstacle: a dict as an entry of "obstacles" (box, sphere, cylinder, plane,
        mesh; with "motion" it moves). Add obstacles before blocks: a block leaves out the
        points inside them, an obstacle added later does not push particles out. Returns its index."""
        return self._add_obstacle(_json_text(obstacle, "obstacle"))

    # -- measurements --------------------------------------------------------------------------
    def surface_height(self, x, z):
        """Free-surface height y (m) at (x, z), scalars or arrays (broadcast); NaN where dry."""
        xs, zs = np.broadcast_arrays(np.asarray(x, dtype=np.float32), np.asarray(z, dtype=np.float32))
        heights = self._surface_heights(xs.ravel(), zs.ravel()).reshape(xs.shape)
        return float(heights) if heights.ndim == 0 else heights

    def probe(self, points):
        """Density (kg/m³), pressure (Pa) and velocity (m/s) interpolated at points ((m, 3) or
        one point); a dict of arrays. NaN where no fluid is near."""
        p = np.asarray(points, dtype=np.float32)
        one = p.ndim == 1
        rows = self._probe(p.reshape(-1, 3))
        out = {"density": rows[:, 0], "pressure": rows[:, 1], "velocity": rows[:, 2:5]}
        return {k: v[0] for k, v in out.items()} if one else out

    def read_gauges(self):
        """The scene's gauges now: (g,) float32 free-surface heights, m (gauges.csv's columns)."""
        g = self.gauge_positions
        return self._surface_heights(g[:, 0].copy(), g[:, 1].copy())

    def read_probes(self):
        """The scene's probes now: (p, 4) float32 rows [pressure, vx, vy, vz] (probes.csv's columns)."""
        return self._probe(self.probe_positions)[:, 1:5].copy()

    # -- running -------------------------------------------------------------------------------
    def run(self, seconds=None, *, callback=None, progress=True, fps=None):
        """Simulate until `seconds` more have passed (default: until the scene's end_time),
        calling callback(world) at every frame, k / fps (default: the scene's output.fps), the
        frame times `tide run` writes at; frame 0 (now) included when the world starts there.

        progress: a bar on stderr (False: none). Ctrl-C stops between two steps with
        KeyboardInterrupt, the world intact. A callback may return False to stop. Returns the
        number of frames the callback was given.
        """
        fps = float(self.fps if fps is None else fps)
        if not fps > 0:
            raise ValueError(f"fps: must be > 0, got {fps}")
        start = self.time
        end = self.end_time if seconds is None else start + float(seconds)
        if not end >= start:
            raise ValueError(f"seconds: the run would end at {end} s, before the world's time {start} s")
        first = math.ceil(start * fps - 1e-9)
        last = math.floor(end * fps + 1e-9)
        bar = _Progress(start, end, enabled=progress)
        frames = 0
        try:
            for frame in range(first, last + 1):
                target = frame / fps
                if target > self.time:
                    self.advance(target - self.time)
                bar.update(self, frame, last)
                if callback is not None:
                    frames += 1
                    if callback(self) is False:
                        return frames
            if end - self.time > 1e-9:  # an end between frames
                self.advance(end - self.time)
                bar.update(self, last, last)
        finally:
            bar.close()
        return frames


class _Progress:
    """A one-line bar like `tide run`'s: redrawn at most 10 times a second, on stderr."""

    def __init__(self, start, end, enabled=True, stream=None):
        self.start, self.end, self.enabled = start, end, enabled
        self.stream = stream if stream is not None else sys.stderr
        self.wall0 = _time.monotonic()
        self.steps0 = None
        self.last_draw = -1.0
        self.drawn = False

    def update(self, world, frame, frames):
        if not self.enabled:
            return
        now = _time.monotonic() - self.wall0
        if self.steps0 is None:
            self.steps0 = world.steps
        if now - self.last_draw < 0.1 and frame < frames:
            return
        self.last_draw = now
        span = max(self.end - self.start, 1e-12)
        fraction = min(max((world.time - self.start) / span, 0.0), 1.0)
        width = 30
        filled = int(fraction * width)
        eta = now * (1 - fraction) / fraction if fraction > 0 else 0.0
        rate = (world.steps - self.steps0) * world.particle_count / max(now, 1e-9) / 1e6
        self.stream.write(f"\r[{'#' * filled}{'-' * (width - filled)}] {world.time:7.3f}/{self.end:.3f} s  "
                          f"frame {frame}/{frames}  {world.particle_count} particles  {rate:.2f} M particle-steps/s  "
                          f"ETA {int(eta) // 3600:02d}:{int(eta) // 60 % 60:02d}:{int(eta) % 60:02d}  ")
        self.stream.flush()
        self.drawn = True

    def close(self):
        if self.drawn:
            self.stream.write("\n")
            self.stream.flush()

# Shown as tide.SceneError in tracebacks (they are defined by the compiled part).
for _error in (SceneError, DivergenceError):
    _error.__module__ = "tide"
del _error
