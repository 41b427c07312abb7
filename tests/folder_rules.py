#!/usr/bin/python3
"""The folders are the architecture (docs/design.md, "Pipeline and folders"): every #include of a
library's sources may name only the folders below it, and the generic parts of verification/
(harness, model, report) name no formulation, physics library or study kind; python/ includes
nothing of verification/cli or verification/kinds. Prints each breach (file, line, the folder
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
# The parts of verification/ that know no physics: what they may include of the repository.
GENERIC = {
    "verification/harness": {"core", "verification/harness", "verification/model",
                             "verification/report"},
    "verification/model": {"core", "verification/model"},
    "verification/report": {"core", "verification/report"},
}
# What the Python module may not include: it binds the library objects and the program's
# operations (verification/api), not the command line or the study kinds' internals.
PYTHON_FORBIDDEN = ("verification/cli", "verification/kinds")
FOLDERS = ("core", "fracture", "interfaces", "cg", "dg", "dynamics", "verification")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def library_of(path):
    """The library a repository path belongs to ('dynamics/contact' before 'dynamics')."""
    for lib in sorted(ALLOWED, key=len, reverse=True):
        if path == lib or path.startswith(lib + "/"):
            return lib
    return None


def generic_breaches(root):
    """The harness, the model and the report layer include no formulation, no physics library
    and no study kind: only core and the generic parts of verification/ they are allowed."""
    breaches = 0
    for part, allowed in GENERIC.items():
        for folder, _, files in os.walk(os.path.join(root, part)):
            for name in sorted(files):
                if not name.endswith((".cpp", ".hpp")):
                    continue
                rel = os.path.relpath(os.path.join(folder, name), root)
                for number, line in enumerate(open(os.path.join(folder, name), encoding="utf-8"), 1):
                    match = INCLUDE.match(line)
                    if not match or match.group(1).split("/")[0] not in FOLDERS:
                        continue
                    target = match.group(1)
                    if not any(target == a or target.startswith(a + "/") for a in allowed):
                        print(f"{rel}:{number}: {part} includes {target}")
                        breaches += 1
    return breaches


def python_breaches(root):
    breaches = 0
    folder = os.path.join(root, "python")
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        if not name.endswith((".cpp", ".hpp")):
            continue
        for number, line in enumerate(open(os.path.join(folder, name), encoding="utf-8"), 1):
            match = INCLUDE.match(line)
            if match and match.group(1).startswith(PYTHON_FORBIDDEN):
                print(f"python/{name}:{number}: python includes {match.group(1)}")
                breaches += 1
    return breaches


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
    breaches += generic_breaches(root) + python_breaches(root)
    print(f"folder rules: {breaches} breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
