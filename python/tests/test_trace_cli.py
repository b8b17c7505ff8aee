"""RaycastingScene.cast_rays against revolve-trace run as a process on the same profile and rays:
the same hits, t, u and v bit for bit (revolve-trace prints %.9g, which tells floats apart), and the
same normals to a float's rounding: revolve-trace divides the unit normal revolve gives it by its
length again in float, which moves some components by an ulp; cast_rays hands it on as given."""

import numpy as np
import pytest

import revolve
from closed_forms import SEED, incoherent_rays
from conftest import SOURCE_DIR, run_tool

CURVE = [[0, 0], [0.3, 0], [0.4, 0.3], [0.25, 0.7], [0.3, 0.9], [0, 0.9]]


def write_rays(path, rays):
    with open(path, "w") as out:
        out.write("ox,oy,oz,dx,dy,dz,tnear,tfar\n")
        for r in rays:
            # A float's exact value as a double's shortest text: read back as the same float.
            out.write(",".join(repr(float(v)) for v in r) + ",0,inf\n")


@pytest.mark.parametrize("profile, spline", [("vase", None), ("curve", "catmull-rom"), ("curve", "natural")])
def test_hits_are_revolve_traces_bit_for_bit(tmp_path, profile, spline):
    print(f"seed {SEED}")
    if profile == "vase":
        points_file = SOURCE_DIR / "examples" / "vase.csv"
        points = np.loadtxt(points_file, delimiter=",", skiprows=1)  # the tool reads doubles the same way
    else:
        points = np.array(CURVE, dtype=np.float64)
        points_file = tmp_path / "curve.csv"
        points_file.write_text("r,z\n" + "".join(f"{r!r},{z!r}\n" for r, z in points.tolist()))
    rng = np.random.default_rng(SEED + 7)
    rmax, zlo, zhi = points[:, 0].max(), points[:, 1].min(), points[:, 1].max()
    rays = incoherent_rays(rng, 5000, [0, 0, 0.5 * (zlo + zhi)], np.hypot(rmax, zhi - zlo), [-rmax, -rmax, zlo], [rmax, rmax, zhi])
    write_rays(tmp_path / "rays.csv", rays)
    options = ["--spline", spline] if spline else []
    run_tool("revolve-trace", "--profile", points_file, "--rays", tmp_path / "rays.csv", "--out", tmp_path / "hits.csv", *options)
    expected = (tmp_path / "hits.csv").read_text().splitlines()[1:]

    scene = revolve.RaycastingScene()
    scene.add_revolution(points, spline=spline)
    got = scene.cast_rays(rays)
    hits = 0
    for i, line in enumerate(expected):
        if not np.isfinite(got["t_hit"][i]):
            assert line == "0,inf,0,0,0,0,0", i
            continue
        hits += 1
        fields = line.split(",")
        assert fields[0] == "1" and fields[1] == f"{float(got['t_hit'][i]):.9g}", i
        assert fields[5:] == [f"{float(v):.9g}" for v in got["primitive_uvs"][i]], i
        assert np.allclose([float(x) for x in fields[2:5]], got["primitive_normals"][i], rtol=0, atol=2.0**-23), i
    assert hits > 1000
