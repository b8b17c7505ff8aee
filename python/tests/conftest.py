"""Where the tests find the build's tools and the repository's scenes: REVOLVE_BIN_DIR and
REVOLVE_SOURCE_DIR (CTest sets both), else build/bin and the checkout this file lies in."""

import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("REVOLVE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BIN_DIR = pathlib.Path(os.environ.get("REVOLVE_BIN_DIR", SOURCE_DIR / "build" / "bin"))


def tool_env():
    """The environment the build's tools run in: this one without LD_PRELOAD, which the sanitizer
    suite sets for the interpreter (so that the module finds its sanitizer runtime) and which would
    load a second runtime into the tools, whose own runtime is linked in."""
    return {key: value for key, value in os.environ.items() if key != "LD_PRELOAD"}


def run_tool(name, *args):
    """Runs build/bin/NAME with the arguments; fails the test, with its stderr, unless it exits 0."""
    tool = BIN_DIR / name
    if not tool.exists():
        pytest.fail(f"{tool} is missing: build the tools first (cmake --build build)")
    done = subprocess.run([str(tool), *map(str, args)], capture_output=True, text=True, env=tool_env())
    assert done.returncode == 0, f"{name} exited {done.returncode}: {done.stderr}"
    return done


@pytest.fixture
def source_dir():
    return SOURCE_DIR
