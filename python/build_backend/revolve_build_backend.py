"""The build backend of `pip install .` (PEP 517, named in pyproject.toml): CMake builds the module
revolve._revolve and installs the package's `python` component into a staging folder, and the
standard library writes that folder as a wheel. It needs python3, CMake and the compilers, and
nothing from PyPI: Debian 12 and 13 both have all of it, and pip's `--no-build-isolation` builds
with Debian's pybind11 (docs/python.md).

Settings (pip's `--config-settings KEY=VALUE`, or the environment):
  build-dir    (REVOLVE_PIP_BUILD_DIR)    CMake's build folder, kept for the next install
                                          (default: a temporary folder, removed afterwards)
  cmake-args   (REVOLVE_PIP_CMAKE_ARGS)   more arguments for CMake's configure, split as a shell does
"""

import base64
import hashlib
import os
import pathlib
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import tomllib
import zipfile

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
CMAKE_MINIMUM = (3, 25)


class BuildError(RuntimeError):
    """A build that cannot go on; the message says why and what to install."""


def _project():
    with open(SOURCE_DIR / "pyproject.toml", "rb") as f:
        return tomllib.load(f)["project"]


def _distribution(project):
    # The wheel's and the .dist-info's name: the project's name normalized (PEP 427, PEP 503).
    return project["name"].replace("-", "_").replace(".", "_").lower()


def _tag():
    """The wheel's tag: this interpreter (CPython X.Y), its ABI and its platform, since the module is
    compiled against this interpreter's headers."""
    if sys.implementation.name != "cpython":
        raise BuildError(f"revolve's module is built for CPython; this interpreter is {sys.implementation.name}")
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    abi = python
    if sysconfig.get_config_var("Py_GIL_DISABLED"):
        abi += "t"
    if hasattr(sys, "gettotalrefcount"):
        abi += "d"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{abi}-{platform}"


def _metadata(project):
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}", f"Version: {project['version']}"]
    if "description" in project:
        lines.append(f"Summary: {project['description']}")
    if "text" in project.get("license", {}):
        lines.append(f"License: {project['license']['text']}")
    if "requires-python" in project:
        lines.append(f"Requires-Python: {project['requires-python']}")
    lines += [f"Requires-Dist: {requirement}" for requirement in project.get("dependencies", [])]
    return "\n".join(lines) + "\n"


def _wheel_file():
    return f"Wheel-Version: 1.0\nGenerator: revolve_build_backend\nRoot-Is-Purelib: false\nTag: {_tag()}\n"


def _write_dist_info(folder, project):
    dist_info = pathlib.Path(folder) / f"{_distribution(project)}-{project['version']}.dist-info"
    dist_info.mkdir(parents=True, exist_ok=True)
    (dist_info / "METADATA").write_text(_metadata(project))
    (dist_info / "WHEEL").write_text(_wheel_file())
    return dist_info


def _setting(config_settings, key, variable):
    value = (config_settings or {}).get(key)
    if isinstance(value, list):  # pip passes a key given twice as a list; the last one wins
        value = value[-1]
    return value if value is not None else os.environ.get(variable)


def _cmake():
    cmake = shutil.which("cmake")
    if cmake is None:
        raise BuildError("revolve's build needs CMake 3.25 or newer, and found no `cmake` on PATH (Debian: apt install cmake)")
    version_text = subprocess.run([cmake, "--version"], capture_output=True, text=True, check=True).stdout.split()
    version = tuple(int(part) for part in version_text[2].split("-")[0].split(".")[:2])
    if version < CMAKE_MINIMUM:
        raise BuildError(f"revolve's build needs CMake 3.25 or newer; {cmake} is {version_text[2]}")
    return cmake


def _run(command, what):
    print("revolve_build_backend:", shlex.join(command), flush=True)
    done = subprocess.run(command)
    if done.returncode != 0:
        raise BuildError(f"revolve's build failed while {what} (exit status {done.returncode}); CMake's messages above say why")


def _numpy():
    # The module is built for this interpreter, which needs numpy; pip's default build isolation
    # runs the build in an environment that hides the system's packages, Debian's numpy among them.
    try:
        import numpy  # noqa: F401
    except ImportError:
        raise BuildError(f"revolve's build needs numpy for {sys.executable} (Debian: apt install python3-numpy), and "
                         "this interpreter does not see it: with Debian's packages, install with "
                         "`pip install --no-build-isolation .` into a virtual environment made with "
                         "`python3 -m venv --system-site-packages` (pip's default build isolation hides them)") from None


def _build_and_stage(build_dir, stage_dir, config_settings):
    """Configures and builds the module in build_dir and installs the package into stage_dir."""
    cmake = _cmake()
    _numpy()
    command = [cmake, "-S", str(SOURCE_DIR), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
               f"-DPython3_EXECUTABLE={sys.executable}", "-DREVOLVE_BUILD_PYTHON=ON", "-DREVOLVE_BUILD_TOOLS=ON",
               "-DREVOLVE_BUILD_TESTS=OFF", "-DREVOLVE_BUILD_BENCH=OFF", "-DREVOLVE_PYTHON_INSTALL_DIR=."]
    if not (pathlib.Path(build_dir) / "CMakeCache.txt").exists() and shutil.which("ninja"):
        command += ["-G", "Ninja"]
    command += shlex.split(_setting(config_settings, "cmake-args", "REVOLVE_PIP_CMAKE_ARGS") or "")
    _run(command, "configuring with CMake")
    _run([cmake, "--build", str(build_dir), "--target", "_revolve", "--parallel", str(os.cpu_count() or 1)],
         "building the module _revolve")
    _run([cmake, "--install", str(build_dir), "--component", "python", "--prefix", str(stage_dir)],
         "installing the package's files")
    package = pathlib.Path(stage_dir) / "revolve"
    if not any(package.glob("_revolve*.so")):
        raise BuildError(f"CMake's install put no module _revolve*.so in {package}")


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def _zip_wheel(stage_dir, wheel_path, dist_info_name):
    stage_dir = pathlib.Path(stage_dir)
    files = sorted(p for p in stage_dir.rglob("*") if p.is_file())
    record_name = f"{dist_info_name}/RECORD"
    records = []
    with zipfile.ZipFile(wheel_path, "w", compression=zipfile.ZIP_DEFLATED) as wheel:
        # The .dist-info last, as the wheel format recommends.
        for path in sorted(files, key=lambda p: (p.relative_to(stage_dir).parts[0] == dist_info_name, str(p))):
            name = path.relative_to(stage_dir).as_posix()
            data = path.read_bytes()
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            info.external_attr = (path.stat().st_mode & 0o777 | 0o100000) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(info, data)
            records.append(_record_line(name, data))
        records.append(f"{record_name},,")
        wheel.writestr(zipfile.ZipInfo(record_name, date_time=(1980, 1, 1, 0, 0, 0)), "\n".join(records) + "\n",
                       compress_type=zipfile.ZIP_DEFLATED)


# The PEP 517 hooks.

def get_requires_for_build_wheel(config_settings=None):
    return []  # CMake, the compilers and pybind11 are the system's (Debian's packages), not PyPI's


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _write_dist_info(metadata_directory, _project()).name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    project = _project()
    build_dir = _setting(config_settings, "build-dir", "REVOLVE_PIP_BUILD_DIR")
    with tempfile.TemporaryDirectory(prefix="revolve-wheel-") as scratch:
        scratch = pathlib.Path(scratch)
        stage_dir = scratch / "stage"
        try:
            _build_and_stage(pathlib.Path(build_dir).resolve() if build_dir else scratch / "build", stage_dir,
                             config_settings)
        except BuildError as error:
            # The message alone, at the end of the build's output pip shows (after CMake's own messages).
            raise SystemExit(f"error: {error}") from None
        dist_info = _write_dist_info(stage_dir, project)
        wheel_name = f"{_distribution(project)}-{project['version']}-{_tag()}.whl"
        _zip_wheel(stage_dir, pathlib.Path(wheel_directory) / wheel_name, dist_info.name)
    return wheel_name
