"""Shared fixtures of the Python layer's tests: the module from the build tree and the program
beside it (the ctest entries set PYTHONPATH and VORODG_EXE; run by hand, the build folder is
found from this file's place)."""
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("VORODG_BUILD", ROOT / "build"))
if str(BUILD) not in sys.path:
    sys.path.insert(0, str(BUILD))

import vorodg  # noqa: E402  (after the path is set)

EXE = os.environ.get("VORODG_EXE", str(BUILD / "bin" / "vorodg"))


def run_program(*args, check=True):
    """Runs the vorodg program; returns the completed process (stdout, stderr as text)."""
    done = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"vorodg {' '.join(map(str, args))} failed:\n{done.stderr}")
    return done


def program_error(*args):
    """The one-line message the program prints for bad input (without its 'vorodg: error: ')."""
    done = run_program(*args, check=False)
    assert done.returncode != 0, "expected the program to refuse the input"
    line = done.stderr.strip().splitlines()[-1]
    prefix = "vorodg: error: "
    assert line.startswith(prefix), line
    return line[len(prefix):]


@pytest.fixture
def program():
    return run_program
