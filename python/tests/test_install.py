"""The package as `cmake --install BUILD --component python --prefix P` installs it, and as
`pip install --no-build-isolation .` installs it into a virtual environment that sees the system's
packages (docs/python.md): importable from there alone, from another folder."""

import os
import pathlib
import subprocess
import sys
import tomllib

import pytest

from conftest import SOURCE_DIR

BUILD_DIR = pathlib.Path(os.environ.get("REVOLVE_BUILD_DIR", SOURCE_DIR / "build"))

# A unit cylinder's top, 4 below a ray's origin at z = 5.
CAST_A_RAY = ("import numpy, revolve; print(revolve.__file__); s = revolve.RaycastingScene(); "
              "s.add_revolution([[0, 0], [1, 0], [1, 1], [0, 1]]); "
              "print(s.cast_rays(numpy.array([[0.2, 0.1, 5, 0, 0, -1]], numpy.float32))['t_hit'][0])")


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
    done = subprocess.run([sys.executable, "-c", CAST_A_RAY], env=env, cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    where, t = done.stdout.split()
    assert pathlib.Path(where).parent == packages[0] and float(t) == 4.0


def test_pip_install_into_a_fresh_virtual_environment(tmp_path):
    """`pip install --no-build-isolation SOURCE` into a fresh venv made with --system-site-packages
    (Debian's numpy and pybind11 visible, nothing downloaded): pip runs the build backend of
    python/build_backend, which builds the module with CMake (Release, the module's target only) in
    a folder of tmp_path. The venv's interpreter then imports the installed package from elsewhere."""
    if os.environ.get("REVOLVE_SANITIZED"):
        pytest.skip("the sanitizer suite's interpreter runs with the sanitizers' runtime preloaded, which pip's "
                    "own Release build must not inherit; the Release suite runs this test")
    # The interpreter and pip alone: not the build tree (CTest's PYTHONPATH), not the sanitizers' runtime,
    # not the user's pip configuration (an index or links of its own), not the user's site-packages.
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LD_PRELOAD") and not k.startswith("PIP_")}
    env.update(PIP_CONFIG_FILE=os.devnull, PYTHONNOUSERSITE="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    venv = tmp_path / "venv"
    made = subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], env=env,
                          capture_output=True, text=True)
    if made.returncode != 0 and "ensurepip" in made.stdout + made.stderr:
        pytest.skip(f"{sys.executable} cannot make a virtual environment with pip: it needs ensurepip "
                    "(Debian: python3-venv, which scripts/install-deps.sh --test installs)")
    assert made.returncode == 0, f"python3 -m venv failed: {made.stdout}{made.stderr}"
    python = venv / "bin" / "python"
    # --no-index: nothing is downloaded (numpy, the one dependency, is the system's).
    pip = [str(python), "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir",
           "--config-settings", f"build-dir={tmp_path / 'build'}", str(SOURCE_DIR)]
    done = subprocess.run(pip, env=env, cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, f"{' '.join(pip)} exited {done.returncode}:\n{done.stdout[-6000:]}\n{done.stderr[-6000:]}"

    outside = tmp_path / "elsewhere"
    outside.mkdir()
    ran = subprocess.run([str(python), "-c", CAST_A_RAY], env=env, cwd=outside, capture_output=True, text=True)
    assert ran.returncode == 0, ran.stderr
    where, t = ran.stdout.split()
    site_packages = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('platlib'))"],
                                   env=env, capture_output=True, text=True, check=True).stdout.strip()
    assert pathlib.Path(where).parent == pathlib.Path(site_packages) / "revolve", \
        f"revolve imported from {where}, not from the venv's {site_packages}"
    assert float(t) == 4.0
    # pip knows it: `pip uninstall revolve` would remove it.
    shown = subprocess.run([str(python), "-m", "pip", "show", "revolve"], env=env, capture_output=True, text=True)
    with open(SOURCE_DIR / "pyproject.toml", "rb") as f:
        version = tomllib.load(f)["project"]["version"]
    assert shown.returncode == 0 and f"Version: {version}" in shown.stdout, shown.stdout + shown.stderr
