"""The package as `cmake --install BUILD --component python --prefix P` installs it (docs/python.md):
importable from P alone, by this interpreter, from another folder."""

import os
import pathlib
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

BUILD_DIR = pathlib.Path(os.environ.get("REVOLVE_BUILD_DIR", SOURCE_DIR / "build"))


def test_cmake_install_puts_an_importable_package_under_the_prefix(tmp_path):
    if not (BUILD_DIR / "CMakeCache.txt").exists():
        pytest.skip(f"no CMake build at {BUILD_DIR} (set REVOLVE_BUILD_DIR)")
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", str(BUILD_DIR), "--component", "python", "--prefix", str(prefix)], check=True,
                   capture_output=True)
    packages = sorted(prefix.glob("lib/python3*/dist-packages/revolve"))
    assert len(packages) == 1, f"expected one installed package under {prefix}, found {packages}"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(packages[0].parent)
    # A unit cylinder's top, 4 below a ray's origin at z = 5.
    program = ("import numpy, revolve; print(revolve.__file__); s = revolve.RaycastingScene(); "
               "s.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]]); "
               "print(s.cast_rays(numpy.array([[0.2, 0.1, 5, 0, 0, -1]], numpy.float32))['t_hit'][0])")
    done = subprocess.run([sys.executable, "-c", program], env=env, cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    where, t = done.stdout.split()
    assert pathlib.Path(where).parent == packages[0] and float(t) == 4.0
