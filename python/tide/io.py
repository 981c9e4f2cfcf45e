"""tide.io: frames of a World in the formats `tide run` writes (docs/scene-format.md)."""
import os

from . import _tide

FORMATS = _tide.io.FORMATS


def write_frame(world, path, format=None):
    """Write the world's particles to `path` now, atomically: "vtu" (ParaView), "ply", "csv"
    (x,y,z,vx,vy,vz,density,pressure,material) or "obj" (the fluid's surface, one mesh per
    material). format defaults to the path's extension."""
    path = os.fspath(path)
    if format is None:
        format = os.path.splitext(path)[1].lstrip(".").lower()
    return _tide.io._write_frame(world, path, format, list(world.material_names))
