#!/usr/bin/env python3
"""Stops a study at random moments and checks that resuming it ends exactly as a run that was
never stopped (docs/checkpoints.md).

Usage: restart_check.py VORODG SCENE WORK [--term N] [--kill N] [--seed S] [--threads T]
                        [--set POINTER=VALUE ...]

1. Runs SCENE once without a stop into WORK/reference and times it (T).
2. Into WORK/stopped: N times, starts `vorodg run` and sends SIGTERM at a moment drawn uniformly
   from (0.05, 0.95) x T / (stops + 1), at least 0.3 s, so that every stop meets the study
   still going (the run must exit with 75, "interrupted, resumable", or 0 if it finished
   first); N times the same with SIGKILL, one of them sent as soon as a checkpoint is being
   written (a temporary file beside a .ckpt exists) if the poll catches one before its moment,
   at the moment otherwise.
   The moments are drawn from --seed, so a check can be repeated.
3. Runs it to the end, then compares the two folders with compare_outputs.py (byte for byte,
   times masked) and says which stops resumed from a checkpoint.

--set POINTER=VALUE sets a JSON pointer of the scene to a JSON value (e.g. /checkpoint/steps=50,
/meshes/0/sizes=[0.0254]) into WORK/scene.json. Exits 0 if the folders agree, 1 otherwise.
"""
import argparse
import glob
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
EXIT_INTERRUPTED = 75


def scene_with(scene, overrides, work):
    """The scene file with --set overrides applied (or the scene itself)."""
    if not overrides:
        return scene
    with open(scene) as f:
        data = json.load(f)
    for item in overrides:
        pointer, value = item.split("=", 1)
        keys = [k for k in pointer.split("/") if k]
        node = data
        for k in keys[:-1]:
            node = node[int(k)] if isinstance(node, list) else node.setdefault(k, {})
        last = int(keys[-1]) if isinstance(node, list) else keys[-1]
        node[last] = json.loads(value)
    path = os.path.join(work, "scene.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
    return path


def command(vorodg, scene, out, threads):
    return [vorodg, "run", scene, "-o", out, "--threads", str(threads), "--quiet", "--no-plots"]


def writing_checkpoint(out):
    return bool(glob.glob(os.path.join(out, "checkpoints", "*.ckpt.tmp.*")))


def stop_once(cmd, out, sig, delay, during_write, log):
    """Starts the run, sends `sig` after `delay` s (during_write: at the first sign of a
    checkpoint being written before then); returns (exit code, whether it hit a write)."""
    proc = subprocess.Popen(cmd, stdout=log, stderr=log)
    start, hit = time.monotonic(), False
    while proc.poll() is None:
        if during_write and writing_checkpoint(out):
            hit = True
            break
        if time.monotonic() - start >= delay:  # aimed at a write and none caught: at the moment
            break
        time.sleep(0.0005 if during_write else 0.005)
    if proc.poll() is None:
        proc.send_signal(sig)
    return proc.wait(), hit


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("vorodg")
    p.add_argument("scene")
    p.add_argument("work")
    p.add_argument("--term", type=int, default=5)
    p.add_argument("--kill", type=int, default=5)
    p.add_argument("--seed", type=int, default=2008)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--set", action="append", default=[])
    a = p.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    scene = scene_with(a.scene, a.set, a.work)
    reference, stopped = os.path.join(a.work, "reference"), os.path.join(a.work, "stopped")
    log = open(os.path.join(a.work, "log.txt"), "w")
    t0 = time.monotonic()
    subprocess.run(command(a.vorodg, scene, reference, a.threads), stdout=log, stderr=log,
                   check=True)
    whole = time.monotonic() - t0
    print(f"reference run: {whole:.1f} s")
    rng = random.Random(a.seed)
    plan = [signal.SIGTERM] * a.term + [signal.SIGKILL] * a.kill
    rng.shuffle(plan)
    first_kill = plan.index(signal.SIGKILL) if a.kill else -1
    ok = True
    for i, sig in enumerate(plan):
        # A stop every T / (2 (stops + 1)) on average: every one meets the study still going (a
        # resumed run starts a little later than a fresh one, and a kill loses what followed
        # the last checkpoint), and the run after the last stop finishes about half of it.
        # Never before 0.3 s: a SIGTERM that comes before the program has read its command line
        # and installed its handler (milliseconds; more under the sanitizers) ends it by the
        # signal, rightly, since nothing has started.
        delay = max(0.3, rng.uniform(0.05, 0.95) * whole / (len(plan) + 1))
        during_write = i == first_kill
        log.write(f"--- stop {i}: {sig.name} at {delay:.2f} s{' (during a write)' * during_write}\n")
        log.flush()
        code, hit = stop_once(command(a.vorodg, scene, stopped, a.threads), stopped, sig, delay,
                              during_write, log)
        expected = {EXIT_INTERRUPTED, 0} if sig == signal.SIGTERM else {-signal.SIGKILL, 0}
        where = " during a checkpoint write" if hit else (" (no write caught)" if during_write
                                                          else f" at {delay:.2f} s")
        print(f"stop {i}: {sig.name}{where}: exit {code}")
        if code not in expected:
            print(f"  expected exit {sorted(expected)}")
            ok = False
    subprocess.run(command(a.vorodg, scene, stopped, a.threads), stdout=log, stderr=log,
                   check=True)
    log.close()
    with open(os.path.join(a.work, "log.txt")) as f:
        resumed = sum("resumed at step" in line for line in f)
    print(f"runs resumed from a checkpoint: {resumed}")
    same = subprocess.run([sys.executable, os.path.join(HERE, "compare_outputs.py"), reference,
                           stopped]).returncode == 0
    print("outputs: " + ("the same as the uninterrupted run" if same else "DIFFERENT"))
    return 0 if ok and same else 1


if __name__ == "__main__":
    sys.exit(main())
