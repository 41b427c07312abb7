#!/usr/bin/env python3
"""Compares two study output folders file by file, for refactors that must not change results.

Usage: compare_outputs.py BEFORE AFTER [--rename OLD=NEW ...]

Every file under BEFORE must exist under AFTER (after --rename of path parts) and the reverse.
Files are compared byte for byte, with three exceptions that carry wall-clock time or where the
run happened, and so differ between any two runs of the same program:
  - pictures (.png) are only checked to exist;
  - run.json (the scene's absolute path) and timings.json (wall-clock seconds per stage)
    are skipped, and so are a shard's own results files (results.shard-K-of-N.jsonl);
  - timing and memory values are masked: JSON keys and CSV columns whose names hold
    "seconds", "memory", "core_hours" or "core-hours"; markdown table columns headed by a run
    time, seconds, wall or core-hours; and in the .md reports a number followed by " s".
Prints one line per difference and exits 1 if there is any, 0 otherwise.
"""
import csv
import io
import json
import os
import re
import sys


def is_timing(name):
    return any(w in name for w in ("seconds", "memory", "core_hours", "core-hours"))


def mask_json(value):
    if isinstance(value, dict):
        return {k: ("<t>" if is_timing(k) else mask_json(v)) for k, v in value.items()}
    if isinstance(value, list):
        return [mask_json(v) for v in value]
    return value


def masked_jsonl(data):
    return [mask_json(json.loads(line)) for line in data.decode().splitlines() if line.strip()]


def masked_csv(data):
    rows = list(csv.reader(io.StringIO(data.decode())))
    if not rows:
        return rows
    timing = {i for i, name in enumerate(rows[0]) if is_timing(name)}
    return [[("<t>" if i in timing else c) for i, c in enumerate(r)] for r in rows]


def masked_markdown(text):
    """A report with its wall-clock numbers masked: "N s" in prose, and the cells of table
    columns whose header names a run time or seconds."""
    out, timing = [], set()
    for line in text.splitlines():
        if line.startswith("|"):
            cells = line.split("|")
            if not set(line) <= set("|-: "):
                if not timing and any(is_timing_header(c) for c in cells):
                    timing = {i for i, c in enumerate(cells) if is_timing_header(c)}
                elif timing:
                    cells = [("<t>" if i in timing else c) for i, c in enumerate(cells)]
            line = "|".join(cells)
        else:
            timing = set()
        out.append(re.sub(r"\b[0-9.]+(e[-+]?[0-9]+)? s\b", "<t> s", line))
    return "\n".join(out)


def is_timing_header(cell):
    cell = cell.lower()
    return "run time" in cell or "seconds" in cell or "wall" in cell or "core-hours" in cell


def comparable(path, data):
    """What of a file must agree: its masked content, or None for files only checked to exist."""
    name = os.path.basename(path)
    if name.endswith(".png") or name in ("run.json", "timings.json"):
        return None
    if name.endswith(".jsonl"):
        return sorted(json.dumps(r, sort_keys=True) for r in masked_jsonl(data))
    if name.endswith(".json"):
        try:
            return mask_json(json.loads(data))
        except ValueError:
            return data
    if name.endswith(".csv"):
        return masked_csv(data)
    if name.endswith(".md"):
        return masked_markdown(data.decode())
    return data


def files(root):
    """Every file under root but a shard's own results (results.shard-K-of-N.jsonl: how the study
    was split, not what it found; merge gathers them into results.jsonl)."""
    out = set()
    for d, _, names in os.walk(root):
        for n in names:
            if not (n.startswith("results.shard-") and n.endswith(".jsonl")):
                out.add(os.path.relpath(os.path.join(d, n), root))
    return out


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    before, after = argv[1], argv[2]
    renames = [tuple(a.split("=", 1)) for a in argv[3:] if "=" in a]

    def renamed(p):
        for old, new in renames:
            p = p.replace(old, new)
        return p

    a = {renamed(p): p for p in files(before)}
    b = files(after)
    differences = 0
    for p in sorted(set(a) - b):
        print(f"only in {before}: {a[p]}")
        differences += 1
    for p in sorted(b - set(a)):
        print(f"only in {after}: {p}")
        differences += 1
    for p in sorted(set(a) & b):
        with open(os.path.join(before, a[p]), "rb") as f:
            x = comparable(p, f.read())
        with open(os.path.join(after, p), "rb") as f:
            y = comparable(p, f.read())
        if x != y:
            print(f"differs: {p}")
            differences += 1
    print(f"{len(set(a) & b)} files compared, {differences} differences")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
