#!/usr/bin/python3
"""Side-by-side: vorodg's CG on quads against deal.II 9.4 (Q1, step-8 style) on Timoshenko's
cantilever, the same problem, mesh (4n x n squares, h = 1/n) and error definition.

Builds bench/dealii into BUILD/dealii when deal.II is installed (else says so and exits 0),
then for each n runs deal.II with each direct solver and `vorodg solve --family quad
--formulation cg --threads 1`, --repeats times each (interleaved, so a load change on the
machine hits both), and writes a markdown table of the medians.

With --rcp, time to accuracy instead: deal.II (UMFPACK) on 4n x n squares against `vorodg solve
--family rcp --d D --seed S --formulation cg --threads 1` on random meshes, --realizations seeds
per d; each code's time at the --target L2 error, interpolated in log-log, their ratio, and a
plot of L2 error against time (scripts/time_to_accuracy_plot.py makes the tables and the plot).

Usage: side_by_side_dealii.py [--vorodg PATH] [--build DIR] [--sizes N ...] [--repeats R]
                              [--out FILE.md]   (raw runs go to FILE.json beside it)
       side_by_side_dealii.py --rcp [--sizes N ...] [--rcp-d D ...] [--realizations S]
                              [--target L2] [--plot FILE.png] [the options above]
"""
import argparse
import datetime
import hashlib
import json
import math
import os
import platform
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from plotting_common import write_text_atomically

ROOT = Path(__file__).resolve().parent.parent
SOLVERS = ("umfpack", "mumps")
# Both programs single-threaded all the way down: no idle OpenBLAS/OpenMP pools either.
ENV = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", DEAL_II_NUM_THREADS="1")
TIMEOUT = 3600  # seconds per run
QUAD_SIZES = [128, 256]
RCP_SIZES = [64, 90, 128, 181, 256]
# rcp seed distances: h_avg ~ 1.19 d; the mean L2 error (about 6.7e-5 at d = 0.01, 3.2e-5 at
# 0.007, 1.7e-5 at 0.005 with seed 1) brackets the default target, as deal.II's n = 128 and
# 181 do (2.8e-5 and about 1.4e-5).
RCP_D = [0.02, 0.014, 0.01, 0.007, 0.005]
TARGET = 2.3e-5


class Failure(Exception):
    """A one-line reason to stop with a non-zero exit."""


class Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, not argparse's usage block
        raise Failure(f"bad arguments: {message} (see --help)")


def parse_args(argv):
    p = Parser(description=__doc__.split("\n\n")[0])
    p.add_argument("--vorodg", default=str(ROOT / "build/bin/vorodg"), help="vorodg executable")
    p.add_argument("--build", default=str(ROOT / "build"),
                   help="build folder; deal.II's program goes to BUILD/dealii")
    p.add_argument("--sizes", type=int, nargs="+",
                   help=f"n: the beam gets 4n x n cells (default {QUAD_SIZES}; with --rcp "
                        f"{RCP_SIZES})")
    p.add_argument("--repeats", type=int, default=3,
                   help="runs per program and size (median); with --rcp, deal.II's runs per n")
    p.add_argument("--out", help="markdown file (default stdout); raw runs to its .json")
    p.add_argument("--rcp", action="store_true",
                   help="time to accuracy: deal.II on squares against vorodg on rcp meshes")
    p.add_argument("--rcp-d", type=float, nargs="+", metavar="D",
                   help=f"--rcp: vorodg's seed distances d (default {RCP_D})")
    p.add_argument("--realizations", type=int,
                   help="--rcp: seeds 1..S per d, one run each (default 3)")
    p.add_argument("--target", type=float, help=f"--rcp: L2 error to compare at (default {TARGET})")
    p.add_argument("--plot", help="--rcp: PNG of L2 error against time (default: --out's .png)")
    a = p.parse_args(argv)
    rcp_only = [o for o, v in (("--rcp-d", a.rcp_d), ("--realizations", a.realizations),
                               ("--target", a.target), ("--plot", a.plot)) if v is not None]
    if rcp_only and not a.rcp:
        raise Failure(f"{' '.join(rcp_only)}: only with --rcp")
    if a.sizes is None:
        a.sizes = RCP_SIZES if a.rcp else QUAD_SIZES
    if any(n < 1 or n > 4096 for n in a.sizes):
        raise Failure(f"--sizes {a.sizes}: expected integers in [1, 4096]")
    if a.repeats < 1:
        raise Failure(f"--repeats {a.repeats}: expected at least 1")
    if not os.access(a.vorodg, os.X_OK) or not Path(a.vorodg).is_file():
        raise Failure(f"--vorodg {a.vorodg}: not an executable file")
    if a.out and Path(a.out).suffix == ".json":
        raise Failure(f"--out {a.out}: expected a markdown file (the raw runs take .json)")
    if a.out and not Path(a.out).resolve().parent.is_dir():
        raise Failure(f"--out {a.out}: its folder does not exist")
    if a.rcp:
        check_rcp_args(a)
    return a


def check_rcp_args(a):
    a.rcp_d = RCP_D if a.rcp_d is None else a.rcp_d
    a.realizations = 3 if a.realizations is None else a.realizations
    a.target = TARGET if a.target is None else a.target
    for opt, v in (("--sizes", a.sizes), ("--rcp-d", a.rcp_d)):
        if len(set(v)) != len(v):
            raise Failure(f"{opt} {v}: a value given twice")
    if not all(math.isfinite(d) and 0.001 <= d < 1 for d in a.rcp_d):
        raise Failure(f"--rcp-d {a.rcp_d}: expected seed distances in [0.001, 1)")
    if not 1 <= a.realizations <= 1000:
        raise Failure(f"--realizations {a.realizations}: expected an integer in [1, 1000]")
    if not (math.isfinite(a.target) and 0 < a.target < 1):
        raise Failure(f"--target {a.target}: expected a relative L2 error in (0, 1)")
    if a.plot is None and a.out:
        a.plot = str(Path(a.out).with_suffix(".png"))
    if a.plot and Path(a.plot).suffix.lower() != ".png":
        raise Failure(f"--plot {a.plot}: expected a .png file")
    if a.plot and not Path(a.plot).resolve().parent.is_dir():
        raise Failure(f"--plot {a.plot}: its folder does not exist")


def find_dealii():
    """deal.II's CMake package folder, or None."""
    hints = [os.environ.get("DEAL_II_DIR", "")] + [
        "/usr/share/cmake/deal.II", "/usr/lib/cmake/deal.II", "/usr/local/lib/cmake/deal.II",
        "/usr/lib/x86_64-linux-gnu/cmake/deal.II"]
    for h in hints:
        for d in (Path(h), Path(h) / "lib/cmake/deal.II"):
            if h and (d / "deal.IIConfig.cmake").is_file():
                return d
    return None


def run_quiet(cmd, what):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        lines = [l for l in r.stdout.splitlines() if l.strip()]
        raise Failure(f"{what} failed (exit {r.returncode}): {lines[-1] if lines else ''}")


def build_dealii(build):
    folder = Path(build) / "dealii"
    run_quiet(["cmake", "-S", str(ROOT / "bench/dealii"), "-B", str(folder),
               "-DCMAKE_BUILD_TYPE=Release"], "cmake configure of bench/dealii")
    run_quiet(["cmake", "--build", str(folder), "-j", "1"], "cmake build of bench/dealii")
    return folder / "cantilever"


def timed(cmd):
    """(stdout, wall seconds) of a run; Failure with its last stderr line if it fails."""
    t0 = time.perf_counter()
    try:
        r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           env=ENV, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        raise Failure(f"{' '.join(cmd)}: no result after {TIMEOUT} s")
    wall = time.perf_counter() - t0
    if r.returncode != 0:
        err = [l for l in (r.stderr + r.stdout).splitlines() if l.strip()]
        raise Failure(f"{' '.join(cmd)} failed (exit {r.returncode}): {err[-1] if err else ''}")
    return r.stdout, wall


def run_dealii(exe, n, solver):
    out, wall = timed([str(exe), str(n), solver])
    lines = [l for l in out.splitlines() if l.startswith("{")]
    if len(lines) != 1:
        raise Failure(f"deal.II n={n} {solver}: expected one JSON line, got {len(lines)}")
    rec = json.loads(lines[0])
    rec["wall"] = wall
    return rec


def run_vorodg(exe, n):
    cmd = [exe, "solve", "--family", "quad", "--h", f"{1.0 / n:.17g}", "--formulation", "cg",
           "--threads", "1"]
    return dict({"n": n}, **vorodg_result(cmd, f"n={n}"))


def run_vorodg_rcp(exe, d, seed):
    cmd = [exe, "solve", "--family", "rcp", "--d", f"{d:.17g}", "--seed", str(seed),
           "--formulation", "cg", "--threads", "1"]
    return dict({"d": d, "seed": seed}, **vorodg_result(cmd, f"d={d:g} seed={seed}"))


def vorodg_result(cmd, what):
    out, wall = timed(cmd)
    l2 = re.search(r"(\d+) dofs.*L2 error ([-+0-9.eE]+)", out)
    h = re.search(r"h_avg ([-+0-9.eE]+)", out)
    sec = [l for l in out.splitlines() if l.startswith("seconds:")]
    if not l2 or len(sec) != 1:
        raise Failure(f"vorodg {what}: no 'L2 error' or 'seconds:' line in its output")
    words = sec[0].split()[1:]
    seconds = {k: float(v) for k, v in zip(words[::2], words[1::2])}
    return {"dofs": int(l2.group(1)), "l2_error": float(l2.group(2)),
            "h_avg": float(h.group(1)) if h else None,
            "seconds": seconds, "stage_sum": sum(seconds.values()), "wall": wall,
            "command": " ".join(cmd)}


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def vorodg_revision():
    def git(*args):
        r = subprocess.run(["git", "--no-optional-locks", "-C", str(ROOT), *args],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        return r.stdout.strip() if r.returncode == 0 else "?"
    dirty = git("status", "--porcelain", "--untracked-files=no")
    return git("rev-parse", "--short", "HEAD") + (" (uncommitted changes)" if dirty else "")


def median(runs, get):
    return float(np.median([get(r) for r in runs]))


def fmt_s(x):
    return f"{x:.3f}"


def table(sizes, dealii, vorodg, solvers, skipped, header):
    cols = ["n", "DOFs"] + [f"deal.II total ({s}) [s]" for s in solvers] + \
           [f"deal.II solver ({s}) [s]" for s in solvers] + \
           ["deal.II error [s]", "deal.II L2", "vorodg total wall [s]", "vorodg stage sum [s]",
            "vorodg analysis+factorization+solve [s]", "vorodg element [s]", "vorodg error [s]",
            "vorodg cell_matrices [s]", "vorodg L2"]
    out = header + ["| " + " | ".join(cols) + " |", "|" + "---:|" * len(cols)]
    for n in sizes:
        d = {s: dealii[(n, s)] for s in solvers}
        v = vorodg[n]
        first = d[solvers[0]]
        dofs = str(first[0]["dofs"])
        if v[0]["dofs"] != first[0]["dofs"]:
            dofs += f" (vorodg {v[0]['dofs']})"
        st = lambda r, k: r["seconds"].get(k, 0.0)
        row = [str(n), dofs]
        row += [fmt_s(median(d[s], lambda r: st(r, "total"))) for s in solvers]
        row += [fmt_s(median(d[s], lambda r: st(r, "solver"))) for s in solvers]
        row += [fmt_s(median(first, lambda r: st(r, "error"))),
                f"{median(first, lambda r: r['l2_error']):.4e}",
                fmt_s(median(v, lambda r: r["wall"])), fmt_s(median(v, lambda r: r["stage_sum"])),
                fmt_s(median(v, lambda r: st(r, "analysis") + st(r, "factorization") +
                             st(r, "solve"))),
                fmt_s(median(v, lambda r: st(r, "element"))),
                fmt_s(median(v, lambda r: st(r, "error"))),
                fmt_s(median(v, lambda r: st(r, "cell_matrices"))),
                f"{median(v, lambda r: r['l2_error']):.4e}"]
        out.append("| " + " | ".join(row) + " |")
    out.append("")
    walls = ", ".join(f"n={n} {median(dealii[(n, solvers[0])], lambda r: r['wall']):.3f} s"
                      for n in sizes)
    out.append(f"deal.II process wall time ({solvers[0]}, median; includes loading its shared "
               f"libraries): {walls}.")
    for s, why in skipped.items():
        out.append(f"deal.II {s}: skipped: {why}.")
    return "\n".join(out) + "\n"


def main(argv):
    a = parse_args(argv)
    if find_dealii() is None:
        print("deal.II not found (no deal.IIConfig.cmake; set DEAL_II_DIR): no comparison made")
        return 0
    exe = build_dealii(a.build)
    vorodg_sha = sha256(a.vorodg)
    a.revision = vorodg_revision()  # of the sources when the runs start, not when they end
    if a.rcp:
        return main_rcp(a, exe, vorodg_sha)

    # Which solvers this deal.II has: the program says "skipped" for one it was built without.
    # These probes (and one vorodg run) also warm the caches; they are not counted.
    run_vorodg(a.vorodg, a.sizes[0])
    solvers, skipped = [], {}
    for s in SOLVERS:
        probe = run_dealii(exe, a.sizes[0], s)
        if "skipped" in probe:
            skipped[s] = probe["skipped"]
        else:
            solvers.append(s)
    if not solvers:
        raise Failure("deal.II: no direct solver available")

    dealii = {(n, s): [] for n in a.sizes for s in solvers}
    vorodg = {n: [] for n in a.sizes}
    load = os.getloadavg()
    for rep in range(a.repeats):
        for n in a.sizes:
            for s in solvers:
                dealii[(n, s)].append(run_dealii(exe, n, s))
            vorodg[n].append(run_vorodg(a.vorodg, n))
            print(f"repeat {rep + 1}/{a.repeats} n={n}: done", file=sys.stderr)
    when, revision = provenance(a, vorodg_sha)
    header = [
        f"Timoshenko cantilever, L = 4, D = 1, E = 1, nu = 0.3, plane stress, P = 1; 4n x n "
        f"squares. deal.II: Q1, 2x2 Gauss, L2 error with QGauss(4). vorodg {revision}: "
        f"`solve --family quad --formulation cg --threads 1`. One thread each; median of "
        f"{a.repeats} run(s). {when}, {platform.node()}, {os.cpu_count()} CPUs, "
        f"load average {load[0]:.2f} at start.", ""]
    md = table(a.sizes, dealii, vorodg, solvers, skipped, header)
    if a.out:
        raw = {"date": when, "host": platform.node(), "cpus": os.cpu_count(),
               "load_average_at_start": load, "repeats": a.repeats, "sizes": a.sizes,
               "environment": {k: ENV[k] for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS",
                                                   "DEAL_II_NUM_THREADS")},
               "dealii_program": str(exe), "vorodg": a.vorodg, "vorodg_sha256": vorodg_sha,
               "vorodg_revision": revision, "dealii_skipped": skipped,
               "dealii_runs": [r for n in a.sizes for s in solvers for r in dealii[(n, s)]],
               "vorodg_runs": [r for n in a.sizes for r in vorodg[n]]}
        write_outputs(a.out, md, raw)
    else:
        sys.stdout.write(md)
    return 0


def provenance(a, vorodg_sha):
    """When the runs ended and the sources' revision when they started (the binary itself is
    named by its sha256 in the raw file); warns if the binary changed meanwhile."""
    if sha256(a.vorodg) != vorodg_sha:
        print(f"warning: {a.vorodg} changed during the runs (rebuilt?)", file=sys.stderr)
    return datetime.datetime.now().isoformat(timespec="seconds"), a.revision


def write_outputs(out, md, raw):
    """The markdown table at `out` and the raw numbers beside it (.json), each atomically."""
    write_text_atomically(out, md)
    write_text_atomically(Path(out).with_suffix(".json"), json.dumps(raw, indent=1) + "\n")
    print(f"wrote {out} and {Path(out).with_suffix('.json')}", file=sys.stderr)


def main_rcp(a, exe, vorodg_sha):
    """Time to accuracy: deal.II (UMFPACK) on squares, vorodg on rcp meshes, interleaved."""
    import time_to_accuracy_plot as tta  # beside this file

    # Warm-up runs, not counted; the probe also says whether this deal.II has UMFPACK.
    run_vorodg_rcp(a.vorodg, max(a.rcp_d), 1)
    probe = run_dealii(exe, min(a.sizes), "umfpack")
    if "skipped" in probe:
        raise Failure(f"deal.II umfpack: skipped: {probe['skipped']}")
    dealii, vorodg = [], []
    load = os.getloadavg()
    for k in range(max(a.repeats, a.realizations)):  # a load change hits both codes
        if k < a.repeats:
            dealii += [run_dealii(exe, n, "umfpack") for n in sorted(a.sizes)]
        if k < a.realizations:
            vorodg += [run_vorodg_rcp(a.vorodg, d, k + 1) for d in sorted(a.rcp_d, reverse=True)]
        print(f"round {k + 1}/{max(a.repeats, a.realizations)}: done", file=sys.stderr)
    when, revision = provenance(a, vorodg_sha)
    header = [
        f"Timoshenko cantilever, L = 4, D = 1, E = 1, nu = 0.3, plane stress, P = 1; relative "
        f"L2 error of the displacement. deal.II: Q1 on 4n x n squares, UMFPACK, time = its own "
        f"total (setup, assembly, solve, error; median of {a.repeats} run(s)). vorodg {revision}: "
        f"`solve --family rcp --d D --seed S --formulation cg --threads 1`, seeds 1.."
        f"{a.realizations} per d, time = the process's wall time (median over seeds). One thread "
        f"each. {when}, {platform.node()}, {os.cpu_count()} CPUs, load average {load[0]:.2f} "
        f"at start.", ""]
    raw = {"mode": "rcp", "date": when, "host": platform.node(), "cpus": os.cpu_count(),
           "load_average_at_start": load, "repeats": a.repeats, "sizes": a.sizes,
           "rcp_d": a.rcp_d, "realizations": a.realizations, "target": a.target,
           "environment": {k: ENV[k] for k in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS",
                                               "DEAL_II_NUM_THREADS")},
           "dealii_program": str(exe), "vorodg": a.vorodg, "vorodg_sha256": vorodg_sha,
           "vorodg_revision": revision, "header": header,
           "dealii_runs": dealii, "vorodg_runs": vorodg}
    summary = tta.summarize(raw)
    tt = tta.time_to_target(summary, a.target)
    raw["summary"], raw["time_to_target"] = summary, tt
    md = tta.report(raw, summary, tt)
    if a.plot:
        tta.plot(raw, summary, tt, a.plot)
    if a.out:
        write_outputs(a.out, md, raw)
    else:
        sys.stdout.write(md)
    if a.plot:
        print(f"wrote {a.plot}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except Failure as e:
        print(f"side_by_side_dealii: {e}", file=sys.stderr)
        sys.exit(1)
    except KeyboardInterrupt:
        sys.exit(130)
