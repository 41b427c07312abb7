#!/usr/bin/python3
"""Turns Google Benchmark JSON files (--benchmark_out=...json) into Markdown tables for
docs/performance.md: machine and date from the context, then per benchmark the median wall time
(the median aggregate when the run had repetitions, else the single run), items per second and
the user counters.

Usage: bench_table.py FILE.json [FILE.json ...] > table.md
"""
import json
import sys


def rows(data):
    runs = data.get("benchmarks", [])
    # The median where a case was repeated; the single run where it ran once (the 1e6 cases).
    medians = [r for r in runs if r.get("aggregate_name") == "median"]
    repeated = {r["run_name"] for r in medians}
    singles = [r for r in runs if r.get("run_type", "iteration") == "iteration" and
               r.get("run_name", r["name"]) not in repeated]
    order = {r.get("run_name", r["name"]): i for i, r in enumerate(runs)}
    return sorted(medians + singles, key=lambda r: order[r.get("run_name", r["name"])])


SKIP = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations",
        "real_time", "cpu_time", "time_unit", "family_index", "per_family_instance_index",
        "aggregate_name", "aggregate_unit", "items_per_second", "label", "error_occurred",
        "error_message"}


def fmt(x):
    if isinstance(x, float):
        return f"{x:.4g}"
    return str(x)


def table(path):
    with open(path) as f:
        data = json.load(f)
    ctx = data.get("context", {})
    out = [f"### {path}", "",
           f"{ctx.get('date', '?')}, {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
           f"{ctx.get('mhz_per_cpu', '?')} MHz, library built {ctx.get('library_build_type', '?')}", ""]
    rs = rows(data)
    counters = sorted({k for r in rs for k in r if k not in SKIP})
    out.append("| benchmark | wall time | unit | items/s | " + " | ".join(counters) + " |")
    out.append("|---" * (4 + len(counters)) + "|")
    for r in rs:
        ips = r.get("items_per_second")
        cells = [r.get("run_name", r["name"]), fmt(r.get("real_time")), r.get("time_unit", ""),
                 fmt(ips) if ips is not None else "-"] + [fmt(r.get(c, "-")) for c in counters]
        out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def main(argv):
    if len(argv) < 2:
        print("usage: bench_table.py FILE.json [FILE.json ...]", file=sys.stderr)
        return 2
    try:
        for path in argv[1:]:
            print(table(path))
    except (OSError, ValueError, KeyError) as e:
        print(f"bench_table: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
