#!/usr/bin/python3
"""The folders are the architecture (docs/design.md, "Pipeline and folders"): every #include of a
library's sources may name only the folders below it. Prints each breach (file, line, the folder
it reaches) and exits 1 if there is one.

Usage: folder_rules.py SOURCE_DIR
"""
import os
import re
import sys

# What each library may include besides itself (dynamics/contact is a library inside dynamics/).
ALLOWED = {
    "core": set(),
    "fracture": {"core"},
    "interfaces": {"core"},
    "cg": {"core"},
    "dg": {"core", "interfaces", "fracture"},
    "dynamics/contact": {"core"},
    "dynamics": {"core", "fracture", "interfaces", "dynamics/contact"},
}
FOLDERS = ("core", "fracture", "interfaces", "cg", "dg", "dynamics", "verification")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def library_of(path):
    """The library a repository path belongs to ('dynamics/contact' before 'dynamics')."""
    for lib in sorted(ALLOWED, key=len, reverse=True):
        if path == lib or path.startswith(lib + "/"):
            return lib
    return None


def main(root):
    breaches = 0
    for lib in ALLOWED:
        for folder, _, files in os.walk(os.path.join(root, lib)):
            for name in sorted(files):
                if not name.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                if library_of(rel) != lib:
                    continue  # a sub-library's file, checked under its own name
                for number, line in enumerate(open(path, encoding="utf-8"), 1):
                    match = INCLUDE.match(line)
                    if not match or match.group(1).split("/")[0] not in FOLDERS:
                        continue
                    target = library_of(match.group(1)) or match.group(1).split("/")[0]
                    if target != lib and target not in ALLOWED[lib]:
                        print(f"{rel}:{number}: {lib} includes {match.group(1)} ({target})")
                        breaches += 1
    print(f"folder rules: {breaches} breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
