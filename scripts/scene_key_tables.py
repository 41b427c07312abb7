#!/usr/bin/python3
"""Rewrites the key tables of docs/scenes.md from `vorodg run --keys KIND`, so the doc says word
for word what the program reads (test: EveryKeyOfEveryKindIsInTheScenesDoc).

Each kind's table is the first Markdown table after its section heading. Usage:
    scripts/scene_key_tables.py BUILD/bin/vorodg [docs/scenes.md]
"""
import subprocess
import sys

# The section heading of each kind's table in docs/scenes.md.
SECTIONS = {
    "fracture": "## Fracture studies",
    "dynamics": "## Dynamics and fragmentation studies",
}


def replace_table(text, heading, table):
    start = text.index(heading)
    first = text.index("\n| key |", start) + 1
    end = first
    while end < len(text) and text.startswith("|", end):
        end = text.index("\n", end) + 1
    return text[:first] + table + text[end:]


def main():
    binary = sys.argv[1]
    path = sys.argv[2] if len(sys.argv) > 2 else "docs/scenes.md"
    text = open(path).read()
    for kind, heading in SECTIONS.items():
        table = subprocess.run([binary, "run", "--keys", kind], check=True, capture_output=True,
                               text=True).stdout
        text = replace_table(text, heading, table if table.endswith("\n") else table + "\n")
    open(path, "w").write(text)


if __name__ == "__main__":
    main()
