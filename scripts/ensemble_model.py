#!/usr/bin/env python3
"""The makespan of a large ensemble on many ranks, simulated from measured task times.

A study's tasks are the runs that share a mesh (TaskPool). This reads the task times of real
studies from their results.jsonl, builds an ensemble of R realizations per level by drawing
each level's tasks from the measured ones (fixed seed), and simulates the coordinator: it
hands the tasks out largest first, one at a time, each hand-out costing it `c` seconds (the
coordinator cost per task, measured by bench_taskpool), to whichever rank is free first.
The predicted efficiency is the work over (ranks x makespan).

Usage: scripts/ensemble_model.py --coordinator-seconds C --realizations R --ranks 100 1000 10000
           --study NAME=path/results.jsonl [--study ...] [--png out.png] [--json out.json]
"""
import argparse
import heapq
import json
import random
import re
import sys
from collections import defaultdict


def task_times(path):
    """Per level, the measured time of each task (a convergence task: every run on one
    (mesh, level, realization), their stage seconds added; a dynamics run: its seconds)."""
    tasks = defaultdict(float)
    for line in open(path):
        try:
            r = json.loads(line)
        except ValueError:
            continue  # a line cut short by a stop
        s = r.get("seconds")
        seconds = sum(s.values()) if isinstance(s, dict) else float(s or 0.0)
        rid = r["id"]
        m = re.match(r"(.+)/L(\d+)/R(\d+)/", rid) or re.match(r"(.+)-L(\d+)-R(\d+)$", rid)
        if not m:
            sys.exit(f"ensemble_model: {path}: run id '{rid}' has no level and realization")
        tasks[(m.group(1), int(m.group(2)), int(m.group(3)))] += seconds
    levels = defaultdict(list)
    for (mesh, level, _), t in sorted(tasks.items()):
        levels[(mesh, level)].append(t)
    return levels


def ensemble(levels, realizations, seed=1):
    """R tasks per level, each drawn from that level's measured tasks."""
    rng = random.Random(seed)
    return [rng.choice(times) for times in levels.values() for _ in range(realizations)]


def makespan(tasks, ranks, c):
    """Largest first to the first free rank; the coordinator hands out one task per c seconds."""
    free = [0.0] * ranks  # when each rank is next free
    heapq.heapify(free)
    dispatch = 0.0  # when the coordinator can hand out the next task
    end = 0.0
    for t in sorted(tasks, reverse=True):
        start = max(heapq.heappop(free), dispatch)
        dispatch = start + c
        heapq.heappush(free, start + t)
        end = max(end, start + t)
    return end


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--coordinator-seconds", type=float, required=True)
    p.add_argument("--realizations", type=int, default=10000)
    p.add_argument("--ranks", type=int, nargs="+", default=[100, 1000, 10000])
    p.add_argument("--study", action="append", required=True, metavar="NAME=JSONL")
    p.add_argument("--png")
    p.add_argument("--json")
    a = p.parse_args()
    rows = []
    for spec in a.study:
        name, path = spec.split("=", 1)
        tasks = ensemble(task_times(path), a.realizations)
        work = sum(tasks)
        for ranks in a.ranks:
            span = makespan(tasks, ranks, a.coordinator_seconds)
            rows.append({"study": name, "tasks": len(tasks), "work_seconds": work,
                         "largest_task_seconds": max(tasks), "ranks": ranks,
                         "makespan_seconds": span, "efficiency": work / (ranks * span),
                         "coordinator_share": len(tasks) * a.coordinator_seconds / span})
    print("| study | tasks | work (s) | largest task (s) | ranks | makespan (s) | efficiency |"
          " coordinator busy |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['study']} | {r['tasks']} | {r['work_seconds']:.3g} | "
              f"{r['largest_task_seconds']:.3g} | {r['ranks']} | {r['makespan_seconds']:.3g} | "
              f"{r['efficiency']:.2f} | {r['coordinator_share']:.2f} |")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for name in dict.fromkeys(r["study"] for r in rows):
            mine = [r for r in rows if r["study"] == name]
            ax.semilogx([r["ranks"] for r in mine], [r["efficiency"] for r in mine], "o-",
                        label=name)
        ax.set_xlabel("ranks")
        ax.set_ylabel("predicted efficiency (work / ranks x makespan)")
        ax.set_ylim(0, 1.05)
        ax.grid(True, alpha=0.3)
        ax.legend()
        ax.set_title(f"{a.realizations} realizations per level, c = {a.coordinator_seconds:g} s")
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
