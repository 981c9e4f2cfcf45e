#!/usr/bin/python3
"""tide-view under Xvfb, as the acceptance asks: started on a small scene, it draws a picture
(the screen is not blank, 3 s after start or as soon after as a loaded machine draws), the
picture moves (two screenshots a second apart differ, also outside the panel, where the
fluid is), and SIGTERM ends it cleanly (exit 0, promptly).
A second run leaves by itself (--exit-after), also with exit 0.

usage: viewer_xvfb_test.py TIDE_VIEW
"""
import os
import signal
import struct
import subprocess
import sys
import tempfile
import time

SCENE = """{
  "name": "viewer test", "domain": {"min": [0, 0, 0], "max": [0.3, 0.3, 0.3]},
  "particle_spacing": 0.02, "end_time": 10,
  "materials": [{"name": "water", "density": 1000}],
  "blocks": [{"min": [0.02, 0.12, 0.02], "max": [0.22, 0.28, 0.22]}]
}"""
WIDTH, HEIGHT = 640, 480
PANEL_RIGHT = 330  # the ImGui panel sits at the top left, 300 px wide


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def free_display():
    for n in range(91, 160):
        if not os.path.exists(f"/tmp/.X11-unix/X{n}") and not os.path.exists(f"/tmp/.X{n}-lock"):
            return n
    fail("no free X display number")


def screenshot(display):
    """The root window as rows of 4-byte pixels, via xwd (x11-apps); XWD's header is big-endian."""
    data = subprocess.run(["xwd", "-root", "-silent", "-display", display], check=True,
                          capture_output=True, timeout=30).stdout
    fields = struct.unpack(">25I", data[:100])
    header_size, width, height = fields[0], fields[4], fields[5]
    bits_per_pixel, bytes_per_line, ncolors = fields[11], fields[12], fields[19]
    if bits_per_pixel not in (24, 32):
        fail(f"expected a 24- or 32-bit screen, got {bits_per_pixel} bits per pixel")
    size = bits_per_pixel // 8
    pixels = data[header_size + 12 * ncolors:]
    # Every pixel widened to 4 bytes, so the helpers below index one way.
    return [b"".join(pixels[y * bytes_per_line + size * x:y * bytes_per_line + size * (x + 1)].ljust(4, b"\0")
                     for x in range(width)) for y in range(height)]


def region(shot, x0, x1, y0, y1):
    return [shot[y][4 * x0:4 * x1] for y in range(y0, y1)]


def distinct_colours(rows):
    return len({row[i:i + 4] for row in rows for i in range(0, len(row), 4)})


def changed_fraction(a, b):
    changed = total = 0
    for ra, rb in zip(a, b):
        for i in range(0, len(ra), 4):
            total += 1
            changed += ra[i:i + 4] != rb[i:i + 4]
    return changed / max(total, 1)


def main():
    viewer = sys.argv[1]
    number = free_display()
    display = f":{number}"
    xvfb = subprocess.Popen(["Xvfb", display, "-screen", "0", "800x600x24", "-nolisten", "tcp"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(100):
            if os.path.exists(f"/tmp/.X11-unix/X{number}"):
                break
            time.sleep(0.1)
        else:
            fail("Xvfb did not start")
        env = dict(os.environ, DISPLAY=display, OMP_WAIT_POLICY="PASSIVE")
        with tempfile.TemporaryDirectory() as tmp:
            scene = os.path.join(tmp, "scene.json")
            with open(scene, "w") as f:
                f.write(SCENE)
            command = [viewer, scene, "--width", str(WIDTH), "--height", str(HEIGHT), "--threads", "1"]
            view = subprocess.Popen(command, env=env, cwd=tmp, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
            time.sleep(3)
            if view.poll() is not None:
                fail(f"tide-view exited early with {view.returncode}: {view.stdout.read().decode()}")
            # On a loaded machine the first frame (shader compiles in software GL) can take
            # longer than 3 s: wait for a picture, up to a deadline, before judging it.
            deadline = time.monotonic() + 60
            first = region(screenshot(display), 0, WIDTH, 0, HEIGHT)
            while distinct_colours(first) < 100 and time.monotonic() < deadline:
                time.sleep(0.5)
                first = region(screenshot(display), 0, WIDTH, 0, HEIGHT)
            # Later the fluid has moved: wait for the change itself (frames come slowly on a
            # loaded machine), with a deadline only against a hang.
            scene_part = lambda shot: [row[4 * PANEL_RIGHT:] for row in shot]
            deadline = time.monotonic() + 60
            while True:
                time.sleep(1)
                second = region(screenshot(display), 0, WIDTH, 0, HEIGHT)
                if changed_fraction(scene_part(first), scene_part(second)) >= 0.001 or time.monotonic() > deadline:
                    break
            sent = time.monotonic()
            view.send_signal(signal.SIGTERM)
            try:
                code = view.wait(timeout=20)
            except subprocess.TimeoutExpired:
                view.kill()
                fail("tide-view did not exit within 20 s of SIGTERM")
            took = time.monotonic() - sent
            output = view.stdout.read().decode()

            colours = distinct_colours(first)
            whole = changed_fraction(first, second)
            fluid = changed_fraction(scene_part(first), scene_part(second))
            print(f"distinct colours {colours}; changed pixels: {whole:.2%} of the window, {fluid:.2%} outside the "
                  f"panel; exit {code} {took:.1f} s after SIGTERM")
            if code != 0:
                fail(f"exit code {code} after SIGTERM; output: {output}")
            if colours < 100:
                fail(f"the window looks blank: {colours} distinct colours")
            if whole <= 0.0 or fluid < 0.001:
                fail("the picture did not change in 60 s")

            started = time.monotonic()
            quick = subprocess.run(command + ["--exit-after", "2"], env=env, cwd=tmp, capture_output=True, timeout=60)
            if quick.returncode != 0:
                fail(f"--exit-after 2 ended with {quick.returncode}: {quick.stdout.decode()} {quick.stderr.decode()}")
            print(f"--exit-after 2: exit 0 after {time.monotonic() - started:.1f} s")
            if os.listdir(tmp) != ["scene.json"]:
                fail(f"the viewer left files behind: {os.listdir(tmp)}")
    finally:
        xvfb.terminate()
        xvfb.wait(timeout=10)
    print("PASS")


if __name__ == "__main__":
    main()
