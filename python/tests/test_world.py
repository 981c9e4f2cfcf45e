# tide.World from Python: scenes from files and dicts through one parser, numpy views of the
# engine's arrays, stepping, running, adding from dicts, measurements, writers.
import copy
import gc
import json
import os
import signal
import subprocess
import threading

import numpy as np
import pytest

import tide
from conftest import small_tank


def test_a_dict_and_its_file_give_the_same_particles_bit_for_bit_after_10_steps(source_dir):
    path = source_dir / "scenes" / "dam_break.json"
    from_file = tide.World(path)
    with open(path) as f:
        from_dict = tide.World(json.load(f))
    assert from_file.particle_count == from_dict.particle_count == 12000
    for _ in range(10):
        assert from_file.step() == from_dict.step()
    assert from_file.steps == 10 and from_file.time == from_dict.time > 0.0
    for name in ("positions", "velocities", "densities", "pressures", "materials", "ids"):
        a, b = getattr(from_file, name), getattr(from_dict, name)
        assert a.tobytes() == b.tobytes(), name
    assert not np.array_equal(from_file.positions[:, 1].max(), 0.4)  # the water moved


def test_a_bad_dict_raises_scene_error_naming_the_field():
    bad = small_tank()
    bad["blocks"][0]["material"] = "oil"
    bad["solver"]["methd"] = "dfsph"
    bad["particle_spacing"] = -1
    with pytest.raises(tide.SceneError) as e:
        tide.World(bad)
    assert isinstance(e.value, ValueError)
    message = str(e.value)
    assert 'blocks[0].material: no material named "oil"' in message
    assert 'solver.methd: unknown key (did you mean "method"?)' in message
    assert "particle_spacing: must be > 0 and <= 1e+06, got -1" in message
    assert len(e.value.problems) == 3


def test_json_cannot_carry_nan_so_it_is_refused_naming_the_field():
    bad = small_tank()
    bad["domain"]["max"][1] = float("nan")
    with pytest.raises(tide.SceneError, match=r"domain\.max\[1\]: must be finite, got nan"):
        tide.World(bad)


def test_numpy_scalars_and_arrays_are_scene_values():
    scene = small_tank()
    scene["blocks"][0]["max"] = np.array([0.2, 0.2, 0.2])
    scene["particle_spacing"] = np.float32(0.04)
    assert tide.World(scene).particle_count == tide.World(small_tank()).particle_count == 125


def test_a_missing_scene_file_is_a_scene_error(tmp_path):
    with pytest.raises(tide.SceneError, match="cannot open the scene file"):
        tide.World(tmp_path / "none.json")


def test_views_are_the_engines_arrays_no_copy_and_change_with_a_step():
    world = tide.World(small_tank())
    views = {name: getattr(world, name) for name in ("positions", "velocities", "densities", "pressures", "materials", "ids")}
    assert views["positions"].shape == (125, 3) and views["positions"].dtype == np.float32
    assert views["velocities"].shape == (125, 3) and views["densities"].shape == (125,)
    assert views["materials"].dtype == np.uint16 and views["ids"].dtype == np.uint32
    for name, v in views.items():
        assert v.__array_interface__["data"][0] == world._address(name), name
        assert not v.flags.writeable and not v.flags.owndata, name
    before = views["positions"].copy()
    world.step()
    # The array taken before the step shows the step: it is the engine's memory.
    assert not np.array_equal(views["positions"], before)
    assert np.array_equal(views["positions"], world.positions)
    assert world.positions.__array_interface__["data"][0] == world._address("positions")


def test_writing_through_a_view_raises():
    world = tide.World(small_tank())
    for name in ("positions", "velocities", "densities", "pressures", "materials", "ids"):
        with pytest.raises(ValueError, match="read-only"):
            getattr(world, name)[0] = 0


def test_a_view_keeps_its_world_alive():
    positions = tide.World(small_tank()).positions
    gc.collect()
    assert isinstance(positions.base, tide.World)
    assert positions[:, 1].max() < 0.2


def test_set_velocities_checks_shape_and_values_and_the_solver_sees_them():
    world = tide.World(small_tank(), settle=False)
    v = np.zeros((world.particle_count, 3), dtype=np.float32)
    v[:, 0] = 0.5
    world.set_velocities(v)
    assert np.array_equal(world.velocities, v)
    x0 = world.positions[:, 0].mean()
    world.advance(0.02)
    assert world.positions[:, 0].mean() > x0 + 0.005  # moved ~0.01 m in x
    with pytest.raises(ValueError, match=r"velocities: must have shape \(125, 3\), got \(125, 2\)"):
        world.set_velocities(np.zeros((125, 2)))
    v[3, 1] = np.inf
    with pytest.raises(ValueError, match=r"velocities\[3, 1\]: must be finite, got inf"):
        world.set_velocities(v)


def test_emitted_particles_land_in_the_same_arrays():
    scene = small_tank(emitters=[{"min": [0.3, 0.2, 0.16], "max": [0.3, 0.28, 0.24], "velocity": [-1, 0, 0], "material": "water"}])
    world = tide.World(scene)
    view = world.positions
    address = world._address("positions")
    n0 = world.particle_count
    world.advance(0.1)
    assert world.particle_count > n0
    assert world._address("positions") == address == view.__array_interface__["data"][0]
    assert world.particle_count <= world.capacity


def test_add_block_emitter_and_obstacle_from_dicts_through_the_parser():
    world = tide.World(small_tank(blocks=[]), capacity=200)
    assert world.particle_count == 0
    assert world.add_obstacle({"type": "box", "min": [0.3, 0, 0.3], "max": [0.4, 0.1, 0.4]}) == 0
    assert world.obstacle_count == 1
    added = world.add_block({"min": [0, 0, 0], "max": [0.2, 0.2, 0.2], "material": "water"})
    assert added == world.particle_count == 125
    assert world.add_emitter({"min": [0.3, 0.2, 0.2], "max": [0.3, 0.28, 0.28], "velocity": [-1, 0, 0],
                              "material": "water"}) == 0
    with pytest.raises(tide.SceneError, match=r'^block\.material: no material named "oil"'):
        world.add_block({"min": [0, 0, 0], "max": [0.1, 0.1, 0.1], "material": "oil"})
    with pytest.raises(tide.SceneError, match=r"^block\.max: must not be below min"):
        world.add_block({"min": [0.2, 0, 0], "max": [0.1, 0.1, 0.1], "material": "water"})
    with pytest.raises(tide.SceneError, match=r'^obstacle\.type: must be "box"'):
        world.add_obstacle({"type": "cube"})
    with pytest.raises(tide.SceneError, match=r"^emitter\.velocity: must be non-zero"):
        world.add_emitter({"min": [0.3, 0.2, 0.2], "max": [0.3, 0.28, 0.28], "velocity": [0, 0, 0], "material": "water"})
    with pytest.raises(ValueError, match="exceed the world's capacity of 200"):
        world.add_block({"min": [0, 0.2, 0], "max": [0.4, 0.4, 0.4], "material": "water"})
    rotation, translation = world.obstacle_pose(0)
    assert np.array_equal(rotation, np.eye(3, dtype=np.float32)) and np.array_equal(translation, np.zeros(3))


def test_run_calls_back_at_every_frame_as_tide_run_writes_them(capsys):
    world = tide.World(small_tank())
    times = []
    frames = world.run(callback=lambda w: times.append(w.time), progress=False)
    assert frames == 6  # frames 0..5 at 50 fps over end_time 0.1 s
    assert times == pytest.approx([k / 50 for k in range(6)], abs=1e-9)
    assert capsys.readouterr().err == ""
    world.run(0.04, progress=True)  # two more frames, with a bar on stderr
    assert world.time == pytest.approx(0.14, abs=1e-9)
    err = capsys.readouterr().err
    assert "[" in err and "frame 7/7" in err and err.endswith("\n")


def test_a_callback_returning_false_stops_the_run():
    world = tide.World(small_tank())
    assert world.run(callback=lambda w: w.time < 0.03, progress=False) == 3
    assert world.time == pytest.approx(0.04, abs=1e-9)


def test_ctrl_c_stops_between_steps_and_leaves_the_world_usable():
    world = tide.World(small_tank())
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            world.run(1e6, progress=False)  # days of simulated time: only Ctrl-C ends it
    finally:
        timer.cancel()
    t = world.time
    assert 0.0 < t < 1e6
    world.step()
    assert world.time > t and np.isfinite(world.positions).all()


def test_the_gil_is_released_while_stepping():
    world = tide.World(small_tank())
    start = world.time
    seen = []
    ready, done = threading.Event(), threading.Event()

    def watch():  # runs only when the stepping thread lets go of the GIL
        ready.set()
        while not done.is_set():
            t = world.time
            if t > start:
                seen.append(t)
                return

    watcher = threading.Thread(target=watch)
    watcher.start()
    ready.wait()  # spinning before the steps start (it once began only after a short advance ended)
    world.advance(0.5)  # hundreds of steps: the watcher gets the GIL many times over if it is free
    done.set()
    watcher.join()
    end = world.time
    assert seen and start < seen[0] < end  # it read the time in the middle of advance()


def test_gauges_and_probes_read_as_numpy():
    # Still water 0.16 m deep over the whole floor.
    scene = small_tank(blocks=[{"min": [0, 0, 0], "max": [0.4, 0.16, 0.4], "material": "water"}],
                       gauges=[{"name": "g", "x": 0.2, "z": 0.2}, {"name": "corner", "x": 0.06, "z": 0.06}],
                       probes=[{"name": "bed", "position": [0.2, 0.06, 0.2]}])
    world = tide.World(scene)
    world.advance(0.05)  # pressures come from the steps
    heights = world.read_gauges()
    assert world.gauge_names == ["g", "corner"] and heights.shape == (2,) and heights.dtype == np.float32
    assert heights == pytest.approx([0.16, 0.16], abs=0.02)
    assert world.surface_height(0.2, 0.2) == heights[0]
    assert np.array_equal(world.surface_height([0.2, 0.06], [0.2, 0.06]), heights)
    rows = world.read_probes()
    assert world.probe_names == ["bed"] and rows.shape == (1, 4)
    # hydrostatic, ρ g h at 0.1 m under the surface
    assert rows[0, 0] == pytest.approx(1000 * 9.81 * 0.1, rel=0.15)
    assert np.abs(rows[0, 1:]).max() < 0.05
    sample = world.probe([0.2, 0.06, 0.2])
    assert sample["pressure"] == rows[0, 0] and sample["velocity"].shape == (3,)
    assert np.isnan(world.probe([0.2, 0.38, 0.2])["density"])  # no fluid up there


def test_write_frame_in_every_format_the_cli_writes(tmp_path):
    world = tide.World(small_tank())
    world.step()
    tide.io.write_frame(world, tmp_path / "f.csv")
    table = np.loadtxt(tmp_path / "f.csv", delimiter=",", skiprows=1, dtype=np.float32)
    assert np.array_equal(table[:, 0:3], world.positions)  # shortest round-trip decimals
    assert np.array_equal(table[:, 6], world.densities)
    for fmt in ("vtu", "ply", "obj"):
        tide.io.write_frame(world, tmp_path / f"f.{fmt}", fmt)
        assert (tmp_path / f"f.{fmt}").stat().st_size > 1000, fmt
    assert b"o water" in (tmp_path / "f.obj").read_bytes()
    with pytest.raises(ValueError, match=r'format: must be "vtu", "ply", "csv" or "obj", got "xyz"'):
        tide.io.write_frame(world, tmp_path / "f.xyz")


def test_an_oceans_obj_frame_carries_the_far_field(tmp_path):
    ocean = {"depth": 0.15, "waves": {"type": "regular", "height": 0.02, "period": 1.0},
             "zone_width": 0.2, "open_sides": ["-x", "+x", "-z", "+z"]}
    world = tide.World(small_tank(domain={"min": [0, 0, 0], "max": [0.6, 0.3, 0.6]}, blocks=[], ocean=ocean))
    tide.io.write_frame(world, tmp_path / "f.obj", "obj")
    text = (tmp_path / "f.obj").read_text()
    assert "o water" in text and "o far_field" in text
    far = text[text.index("o far_field"):]
    assert far.count("\nf ") > 100


def test_stats_are_a_dict():
    world = tide.World(small_tank())
    world.advance(0.02)
    s = world.stats
    assert s["particles"] == 125 and s["steps"] == world.steps > 0
    assert s["solver"] == "dfsph" and s["particles_lost"] == 0
    assert s["dt_min"] <= s["dt_mean"] <= s["dt_max"]


def test_a_python_run_writes_the_frames_tide_run_writes_bit_for_bit(tmp_path, bin_dir):
    cli = bin_dir / "tide"
    if not cli.exists():
        pytest.skip("the tide command line is not built")
    scene = small_tank(settle={"time": 0.02})
    path = tmp_path / "tank.json"
    path.write_text(json.dumps(scene))
    subprocess.run([str(cli), "run", str(path), "--out", str(tmp_path / "cli"), "--format", "csv", "--quiet"], check=True)
    world = tide.World(scene)
    frames = []
    world.run(callback=lambda w: frames.append(tide.io.write_frame(w, tmp_path / f"py_{len(frames)}.csv") or 1),
              progress=False)
    assert len(frames) == 6
    for k in range(6):
        assert (tmp_path / f"py_{k}.csv").read_bytes() == (tmp_path / "cli" / f"frame_{k:05d}.csv").read_bytes(), k
    assert json.loads((tmp_path / "cli" / "stats.json").read_text())["steps"] == world.steps


def test_the_floor_carries_the_waters_weight():
    # Still water over the whole floor: the fluid's load on the floor is its weight.
    scene = small_tank(blocks=[{"min": [0, 0, 0], "max": [0.4, 0.16, 0.4], "material": "water"}])
    world = tide.World(scene)
    assert "wall_ymin" in world.solid_names
    world.take_mean_loads()
    world.advance(0.1)
    loads = world.take_mean_loads()
    floor = loads["names"].index("wall_ymin")
    assert loads["force"].shape == (len(world.solid_names), 3) and loads["force"].dtype == np.float64
    weight = world.total_mass * 9.81
    assert loads["force"][floor, 1] == pytest.approx(-weight, rel=0.1)  # pushed down (y up)
    assert np.array_equal(world.loads()["names"], loads["names"])


def test_ctrl_c_stops_settle_and_leaves_a_usable_world():
    world = tide.World(small_tank(), settle=False)
    stop = threading.Event()

    def interrupt_once_settling():  # on an event (settle has stepped), not after a delay
        while world.steps == 0 and not stop.is_set():
            stop.wait(0.001)
        if not stop.is_set():
            os.kill(os.getpid(), signal.SIGINT)

    watcher = threading.Thread(target=interrupt_once_settling)
    try:
        with pytest.raises(KeyboardInterrupt):
            watcher.start()
            world.settle(seconds=1e6, speed=0.0)  # never quiet at speed 0: only Ctrl-C ends it
    finally:
        stop.set()
        watcher.join()
    assert world.steps > 0  # it was interrupted while settling
    assert world.time == 0.0  # settling holds the clock
    world.step()
    assert world.time > 0.0 and np.isfinite(world.positions).all()


def test_a_floating_body_falls_freely_until_it_meets_the_water():
    crate = {"type": "box", "name": "crate", "min": [0.26, 0.28, 0.16], "max": [0.34, 0.34, 0.24],
             "dynamic": True, "density": 500}
    world = tide.World(small_tank(obstacles=[crate]), settle=False)
    start = world.bodies()
    assert start["names"] == ["crate"] and list(start["obstacles"]) == [0]
    np.testing.assert_allclose(start["position"][0], [0.30, 0.31, 0.20], atol=1e-6)
    np.testing.assert_allclose(start["orientation"][0], [1, 0, 0, 0], atol=1e-12)
    world.advance(0.05)  # the water, 6 cm away, does not reach it this soon
    now = world.bodies()
    t = world.time
    assert now["position"][0, 1] == pytest.approx(0.31 - 0.5 * 9.81 * t * t, rel=0, abs=2e-4)
    assert now["velocity"][0, 1] == pytest.approx(-9.81 * t, rel=0.01)
    assert abs(now["velocity"][0, 0]) < 1e-6 and abs(now["velocity"][0, 2]) < 1e-6
    assert np.linalg.norm(now["orientation"][0]) == pytest.approx(1.0, abs=1e-9)
    assert np.abs(now["angular_velocity"][0]).max() < 1e-6
    assert np.abs(now["contact_force"][0]).max() == 0.0


def test_a_world_whose_scene_was_refused_still_prints():
    # pytest prints the locals of a failed test, a half-made World among them.
    world = tide.World.__new__(tide.World)
    assert repr(world) == "<tide.World (not built)>"
    assert repr(tide.World(small_tank())).startswith("<tide.World ")
