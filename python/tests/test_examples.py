"""The Python page's example (docs/python.md) runs as the page shows it, and prints the closed forms it states."""

import re
import subprocess
import sys

from conftest import SOURCE_DIR


def test_readme_example_prints_its_closed_forms():
    done = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python" / "raycasting.py")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    # A point 1 above the can's lid; the can's centre, 0.5 inside its lid, floor and side alike.
    assert lines[0] == "above the can: 1.000000; its centre: -0.500000"
    can, vase, floor = map(int, re.fullmatch(r"depth image \(480, 640\): (\d+) pixels see the can, (\d+) the vase, (\d+) the floor",
                                             lines[1]).groups())
    assert min(can, vase, floor) > 1000 and can + vase + floor <= 480 * 640
    assert lines[2] == "the can's lid: t = 2.000000, normal [0.0, 0.0, 1.0]"
