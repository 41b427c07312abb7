#!/usr/bin/python3
"""The folders are the architecture (docs/design.md, "Pipeline and folders"): every #include of a
library's sources may name only the folders below it, and the generic parts of verification/
(harness, model, report) name no formulation, physics library or study kind, the static kinds'
shared code (solve, static) names no study kind; python/ includes nothing of verification/cli or
verification/kinds. Prints each breach (file, line, the folder
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
# The parts of verification/ that every static kind shares (the one solve, the static ensemble):
# they name no study kind and know nothing of the program around them.
SHARED = ("verification/solve", "verification/static")
SHARED_FORBIDDEN = ("verification/kinds", "verification/cli", "verification/api")
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


def includes(root, part):
    """Every #include of a repository header in the sources under `part`, as (path, line, header),
    the path relative to the root."""
    for folder, _, files in os.walk(os.path.join(root, part)):
        for name in sorted(f for f in files if f.endswith((".cpp", ".hpp"))):
            path = os.path.join(folder, name)
            for number, line in enumerate(open(path, encoding="utf-8"), 1):
                match = INCLUDE.match(line)
                if match and match.group(1).split("/")[0] in FOLDERS:
                    yield os.path.relpath(path, root), number, match.group(1)


def forbidden_breaches(part, found, forbidden):
    """Prints and counts the includes in `found` that start with one of `forbidden`."""
    breaches = 0
    for rel, number, target in found:
        if target.startswith(forbidden):
            print(f"{rel}:{number}: {part} includes {target}")
            breaches += 1
    return breaches


def generic_breaches(root):
    """The harness, the model and the report layer include no formulation, no physics library
    and no study kind: only core and the generic parts of verification/ they are allowed."""
    breaches = 0
    for part, allowed in GENERIC.items():
        for rel, number, target in includes(root, part):
            if not any(target == a or target.startswith(a + "/") for a in allowed):
                print(f"{rel}:{number}: {part} includes {target}")
                breaches += 1
    return breaches


def shared_breaches(root):
    """The static kinds' shared code includes no study kind, command line or program operation."""
    return sum(forbidden_breaches(p, includes(root, p), SHARED_FORBIDDEN) for p in SHARED)


def python_breaches(root):
    """python/ (its own sources, not its tests) includes nothing of cli/ or kinds/."""
    found = (i for i in includes(root, "python") if os.path.dirname(i[0]) == "python")
    return forbidden_breaches("python", found, PYTHON_FORBIDDEN)


def main(root):
    breaches = 0
    for lib in ALLOWED:
        for rel, number, header in includes(root, lib):
            if library_of(rel) != lib:
                continue  # a sub-library's file, checked under its own name
            target = library_of(header) or header.split("/")[0]
            if target != lib and target not in ALLOWED[lib]:
                print(f"{rel}:{number}: {lib} includes {header} ({target})")
                breaches += 1
    breaches += generic_breaches(root) + shared_breaches(root) + python_breaches(root)
    print(f"folder rules: {breaches} breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
