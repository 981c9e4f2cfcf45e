#!/usr/bin/python3
"""Runs the commands of a guide page (its fenced ```sh blocks) as a reader would, but cheaply,
so that a tutorial whose commands no longer work fails `make test` (CTest tests guide_*).

    check_tutorials.py --source REPO --build BUILD docs/guide/PAGE.md

How it keeps them cheap and self-contained, without changing what each command exercises:
- it runs in a fresh temporary folder holding links to the repository's scenes/ and docs/ and
  to BUILD as build/, so every `out/...` a page writes lands there;
- `tide run` and `tide render` simulate at most CAP seconds (--end-time lowered or added);
- a plotting script given a frame the shortened run did not reach gets the run's last frame,
  and its `--from` is lowered to 0;
- `make` (the page's set-up, which is `make test` itself) and `cmake` (installing and building
  against tide: the install_consumer test does that) are listed as skipped, and so are
  commands of programs those would have built.
Exits 1 naming the first command that failed, with its output."""
import argparse
import glob
import os
import re
import shlex
import subprocess
import sys
import tempfile

CAP = 0.1   # simulated seconds per tide run or render


def commands(markdown):
    """The shell commands of a page's ```sh blocks: continuation lines joined, comments dropped."""
    out, block = [], None
    for line in markdown.splitlines():
        fence = re.match(r"^\s*```(\w*)", line)
        if fence:
            if block is None:
                block = [] if fence.group(1) == "sh" else False
            else:
                if block:
                    text = "\n".join(block).replace("\\\n", " ")
                    out += [c for c in text.splitlines() if c.strip()]
                block = None
            continue
        if block is not None and block is not False:
            block.append(line)
    return [shlex.split(c, comments=True) for c in out]


def cheapened(argv, cwd):
    """The command as run in `cwd`, or (None, reason) when it is skipped."""
    prog = argv[0]
    if prog in ("mpirun", "mpiexec"):
        # Under an MPI launcher: as many ranks as asked, on however few cores this machine has.
        at = next((i for i, a in enumerate(argv) if a.endswith("/tide")), None)
        if at is None:
            return None, "an MPI program other than tide"
        inner, reason = cheapened(argv[at:], cwd)
        return ([prog, "--oversubscribe"] + list(argv[1:at]) + inner, None) if inner else (None, reason)
    if prog in ("make", "cmake"):
        return None, "set-up/build step (covered by make test itself and the install_consumer test)"
    if prog.endswith("/tide") and len(argv) > 1 and argv[1] in ("run", "render") and "--help" not in argv:
        argv = list(argv)
        if "--end-time" in argv:
            i = argv.index("--end-time") + 1
            argv[i] = str(min(float(argv[i]), CAP))
        else:
            argv += ["--end-time", str(CAP)]
        return argv + ["--force", "--quiet"], None
    if prog.endswith("python3") and len(argv) > 1 and argv[1].startswith("docs/guide/scripts/"):
        argv = list(argv)
        for i, a in enumerate(argv):
            frame = re.match(r"(.*)/frame_\d+\.(csv|vtu|ply)$", a)
            if frame and not os.path.exists(os.path.join(cwd, a)):
                done = sorted(glob.glob(os.path.join(cwd, f"{frame.group(1)}/frame_*.{frame.group(2)}")))
                if done:
                    argv[i] = os.path.relpath(done[-1], cwd)
            if a == "--from":
                argv[i + 1] = "0"
        return argv, None
    if prog in ("cmp", "diff"):  # comparing what earlier commands wrote
        return list(argv), None
    if not os.path.exists(os.path.join(cwd, prog)):
        return None, "a program an earlier skipped step builds"
    return list(argv), None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("page")
    ap.add_argument("--source", required=True)
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    with open(args.page) as f:
        cmds = commands(f.read())
    if not cmds:
        print(f"{args.page}: no ```sh commands")
        return 1
    ran = 0
    with tempfile.TemporaryDirectory(prefix="guide_") as work:
        os.symlink(os.path.abspath(args.build), os.path.join(work, "build"))
        for d in ("scenes", "docs"):
            os.symlink(os.path.join(os.path.abspath(args.source), d), os.path.join(work, d))
        env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", MPLBACKEND="Agg",
                   OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        for argv in cmds:
            run, reason = cheapened(argv, work)
            shown = " ".join(shlex.quote(a) for a in argv)
            if run is None:
                print(f"skip: {shown}\n      ({reason})")
                continue
            print(f"run:  {' '.join(shlex.quote(a) for a in run)}", flush=True)
            proc = subprocess.run(run, cwd=work, env=env, capture_output=True, text=True)
            if proc.returncode != 0:
                print(f"FAILED ({proc.returncode}): {shown}\n--- stdout\n{proc.stdout[-3000:]}\n--- stderr\n"
                      f"{proc.stderr[-3000:]}")
                return 1
            ran += 1
    print(f"{args.page}: {ran} commands ran, {len(cmds) - ran} skipped")
    return 0 if ran else 1


if __name__ == "__main__":
    sys.exit(main())
