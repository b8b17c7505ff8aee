#!/usr/bin/env python3
"""Writes the bundled scenes: patio.json, patio_points.json, still_life.json, spline_still_life.json,
vessels.json, many.json and profiles/*.csv.

Run from anywhere: python3 scenes/make_scenes.py. The committed files are this script's output;
edit the script, not them. Units are metres, z is up, angles in degrees (README, "Scene format").
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Every object stands this far (0.1 mm) above what it stands on. Faces that coincide (a glass's
# foot on a table top) speckle, each pixel showing whichever of the two the rounding hits first.
GAP = 1e-4


def r6(x):
    return round(x, 6)


def pts(points):
    return [[r6(r), r6(z)] for r, z in points]


# ----------------------------------------------------------------------------------------------
# Profiles. Closed solids are listed from the axis at the bottom, up the outside, and (for hollow
# vessels) back down the inside to the axis, so normals point out of the material: glass needs that.

def hollow(outer, wall, floor):
    """A vessel: `outer` = [(r, z), ...] from the bottom rim (z = 0) up to the lip; the inside is the
    outer wall moved in by `wall`, down to a floor `floor` thick."""
    profile = [(0.0, 0.0)] + outer
    r_lip, z_lip = outer[-1]
    inner = [(max(r - wall, 0.001), z) for r, z in reversed(outer) if z > floor + 1e-9]
    profile.append((r_lip - wall, z_lip))
    profile += inner[1:]
    profile.append((0.0, floor))
    return profile


def curve(f, z0, z1, n):
    return [(f(z0 + (z1 - z0) * i / n), z0 + (z1 - z0) * i / n) for i in range(n + 1)]


def bead(r, z, radius, n=6, start=-90, end=90):
    """A half-round bead of a turned spindle: points on a circle bulging outwards."""
    out = []
    for i in range(n + 1):
        a = math.radians(start + (end - start) * i / n)
        out.append((r + radius * math.cos(a), z + radius * math.sin(a)))
    return out


def pedestal_table(top_r, height, base_r):
    return [(0, 0), (base_r, 0), (base_r, 0.02), (base_r * 0.5, 0.05), (0.045, 0.08), (0.04, 0.12)] + \
        [(0.035 + 0.008 * math.sin(math.pi * t / 10), 0.12 + (height - 0.2) * t / 10) for t in range(1, 10)] + \
        [(0.04, height - 0.08), (0.09, height - 0.05), (top_r - 0.01, height - 0.035), (top_r, height - 0.025),
         (top_r, height), (0, height)]


def chair_seat():
    # A round seat on a turned pedestal with a foot.
    return [(0, 0), (0.22, 0), (0.22, 0.015), (0.1, 0.04), (0.03, 0.07)] + \
        [(0.026 + 0.006 * math.sin(math.pi * t / 8), 0.07 + 0.3 * t / 8) for t in range(1, 8)] + \
        [(0.03, 0.37), (0.07, 0.41), (0.2, 0.43), (0.215, 0.44), (0.215, 0.46), (0.2, 0.47), (0, 0.47)]


def spindle(length, r):
    """A turned spindle along z from 0 to length: beads near the ends, a swelling in the middle."""
    body = [(0, 0), (r, 0)]
    body += bead(r, 0.06 * length, r * 0.5)
    body += [(r * (1 + 0.35 * math.sin(math.pi * t / 8)), length * (0.12 + 0.76 * t / 8)) for t in range(0, 9)]
    body += bead(r, 0.94 * length, r * 0.5)
    body += [(r, length), (0, length)]
    return body


def rail_post(height):
    """A round rail fixture: square-ish plinth, a shaft with rings, a ball top."""
    p = [(0, 0), (0.07, 0), (0.07, 0.06), (0.05, 0.08), (0.035, 0.1)]
    p += bead(0.035, 0.14, 0.012)
    p += [(0.03, 0.2), (0.03, height - 0.2)]
    p += bead(0.03, height - 0.16, 0.012)
    p += [(0.035, height - 0.1), (0.05, height - 0.08), (0.05, height - 0.06), (0.02, height - 0.05)]
    # ball top
    c = height - 0.05 + 0.035
    p += [(0.035 * math.cos(math.radians(a)), c + 0.035 * math.sin(math.radians(a))) for a in range(-60, 91, 15)][1:]
    p[-1] = (0.0, p[-1][1])
    return p


def wine_bottle():
    outer = [(0.037, 0.0), (0.038, 0.01)] + [(0.038, z) for z in (0.05, 0.12, 0.18)] + \
        curve(lambda z: 0.0135 + (0.038 - 0.0135) * (0.5 + 0.5 * math.cos(math.pi * (z - 0.18) / 0.07)), 0.18, 0.25, 8)[1:] + \
        [(0.0135, 0.29), (0.015, 0.292), (0.015, 0.30)]
    return hollow(outer, 0.003, 0.006)


def beer_bottle():
    outer = [(0.029, 0.0), (0.03, 0.008), (0.03, 0.13)] + \
        curve(lambda z: 0.012 + (0.03 - 0.012) * (0.5 + 0.5 * math.cos(math.pi * (z - 0.13) / 0.06)), 0.13, 0.19, 8)[1:] + \
        [(0.012, 0.22), (0.0135, 0.223), (0.0135, 0.23)]
    return hollow(outer, 0.0025, 0.005)


def wine_glass():
    # Foot, stem, bowl: solid glass up to the bowl's floor, then a thin wall.
    p = [(0, 0), (0.035, 0), (0.035, 0.003), (0.01, 0.006), (0.004, 0.012), (0.0035, 0.07), (0.008, 0.08)]
    bowl = [(0.008 + 0.036 * math.sin(math.pi / 2 * t / 10) ** 0.8, 0.08 + 0.09 * t / 10) for t in range(1, 11)]
    bowl += [(0.042, 0.18), (0.040, 0.2)]
    p += bowl
    p += [(0.0385, 0.2)]
    inner = [(r - 0.0015, z) for r, z in reversed(bowl[:-1]) if z > 0.088]
    p += inner
    p += [(0, 0.086)]
    return p


def coffee_cup():
    outer = [(0.025, 0.0), (0.028, 0.004), (0.04, 0.03), (0.045, 0.06), (0.046, 0.07)]
    return hollow(outer, 0.004, 0.008)


def plate(r, h):
    return [(0, 0), (r * 0.55, 0), (r * 0.6, 0.006), (r * 0.62, 0.006), (r * 0.95, h), (r, h + 0.002),
            (r - 0.004, h + 0.004), (r * 0.62 - 0.004, 0.01), (0, 0.01)]


def bowl(r, h, wall):
    outer = [(r * 0.45, 0.0), (r * 0.5, 0.006)] + [(r * (0.5 + 0.5 * math.sin(math.pi / 2 * t / 8)), h * t / 8) for t in range(1, 9)]
    return hollow(outer, wall, wall * 1.5)


def barrel():
    return [(0, 0), (0.28, 0), (0.29, 0.02)] + [(0.29 + 0.04 * math.sin(math.pi * t / 10), 0.02 + 0.84 * t / 10) for t in range(1, 10)] + \
        [(0.29, 0.86), (0.28, 0.88), (0, 0.88)]


def traffic_cone():
    return [(0, 0), (0.2, 0), (0.2, 0.03), (0.13, 0.03), (0.025, 0.7), (0, 0.7)]


def keg():
    return [(0, 0), (0.2, 0), (0.21, 0.03), (0.21, 0.08), (0.2, 0.1), (0.2, 0.5), (0.21, 0.52), (0.21, 0.57),
            (0.2, 0.6), (0.06, 0.6), (0.06, 0.63), (0, 0.63)]


def goblet():
    p = [(0, 0), (0.05, 0), (0.05, 0.004), (0.015, 0.01), (0.006, 0.02), (0.005, 0.06)] + bead(0.005, 0.07, 0.006, 4) + \
        [(0.006, 0.085), (0.015, 0.095)]
    bowl = [(0.015 + 0.045 * math.sin(math.pi / 2 * t / 12), 0.095 + 0.11 * t / 12) for t in range(1, 13)]
    p += bowl + [(0.058, 0.215)]
    p += [(0.0555, 0.215)] + [(r - 0.0025, z) for r, z in reversed(bowl) if z > 0.105] + [(0, 0.103)]
    return p


def vase():
    outer = [(0.05, 0.0), (0.055, 0.01)] + \
        [(0.055 + 0.045 * math.sin(math.pi * t / 14) - 0.03 * t / 14, 0.01 + 0.24 * t / 14) for t in range(1, 15)] + \
        [(0.03, 0.28), (0.04, 0.3), (0.042, 0.305)]
    return hollow(outer, 0.003, 0.006)


def write_csv(name, points):
    with open(os.path.join(HERE, "profiles", name), "w") as f:
        f.write("r,z\n")
        for r, z in pts(points):
            f.write(f"{r},{z}\n")


def dump(name, scene, compact_points=False):
    """Writes the scene; compact_points puts each profile's points on one line (long profiles)."""
    with open(os.path.join(HERE, name), "w") as f:
        if not compact_points:
            json.dump(scene, f, indent=1)
        else:
            inline = {}
            for key, profile in scene["profiles"].items():
                marker = f"@points:{key}@"
                inline[json.dumps(marker)] = json.dumps(profile["points"], separators=(",", ":"))
                profile["points"] = marker
            text = json.dumps(scene, indent=1)
            for marker, points in inline.items():
                text = text.replace(marker, points)
            f.write(text)
        f.write("\n")


# ----------------------------------------------------------------------------------------------
def patio(points_only=False):
    """The paper's Example scene: three round tables, six chairs, cups, bottles and bowls on the
    tables, and patio rails on forty round rail fixtures: one hundred surfaces of revolution.
    Each chair is four: a seat on its pedestal, two turned back posts and a turned top rail."""
    profiles = {
        "table": {"points": pts(pedestal_table(0.45, 0.74, 0.3)), "crease": 40},
        "chair_seat": {"points": pts(chair_seat()), "crease": 40},
        "chair_post": {"points": pts(spindle(0.5, 0.014))},
        "chair_rail": {"points": pts(spindle(0.3, 0.012))},
        "rail_post": {"points": pts(rail_post(1.0))},
        "wine_bottle": {"csv": "profiles/wine_bottle.csv"},
        "beer_bottle": {"points": pts(beer_bottle())},
        "wine_glass": {"points": pts(wine_glass())},
        "coffee_cup": {"points": pts(coffee_cup())},
        "plate": {"points": pts(plate(0.12, 0.018))},
        "small_bowl": {"points": pts(bowl(0.07, 0.05, 0.004))},
        "salad_bowl": {"points": pts(bowl(0.12, 0.08, 0.003))},
    }
    write_csv("wine_bottle.csv", wine_bottle())
    materials = {
        "stone": {"type": "diffuse", "color": [0.4, 0.36, 0.31]},
        "table_metal": {"type": "metal", "color": [0.25, 0.3, 0.28], "roughness": 0.45},
        "wood": {"type": "diffuse", "color": [0.42, 0.24, 0.12]},
        "white_paint": {"type": "diffuse", "color": [0.82, 0.82, 0.79]},
        "green_glass": {"type": "glass", "ior": 1.5, "tint": [0.35, 0.7, 0.4]},
        "amber_glass": {"type": "glass", "ior": 1.5, "tint": [0.8, 0.5, 0.15]},
        "clear_glass": {"type": "glass", "ior": 1.5},
        "porcelain": {"type": "diffuse", "color": [0.85, 0.84, 0.8]},
        "terracotta": {"type": "diffuse", "color": [0.62, 0.3, 0.18]},
        "steel": {"type": "metal", "color": [0.8, 0.8, 0.82], "roughness": 0.2},
        "hedge": {"type": "diffuse", "color": [0.1, 0.2, 0.07]},
        "wall": {"type": "diffuse", "color": [0.75, 0.62, 0.48]},
    }
    objects = []

    def add(profile, material, x, y, z=0.0, rotate=None, name=None):
        o = {"profile": profile, "material": material, "translate": [r6(x), r6(y), r6(z)]}
        if rotate:
            o["rotate"] = [r6(v) for v in rotate]
        if name:
            o["name"] = name
        objects.append(o)

    tables = [(-1.6, 1.0), (0.4, 2.6), (1.7, 0.7)]
    top = 0.74 + GAP  # the table's top face, the table standing GAP above the floor
    for t, (tx, ty) in enumerate(tables):
        add("table", "table_metal", tx, ty, GAP, name=f"table {t + 1}")
        # Two chairs facing each other across the table, their backs away from it.
        facing = [math.radians(200 + 35 * t), math.radians(20 + 35 * t)]
        for c, a in enumerate(facing):
            cx, cy = tx + 0.62 * math.cos(a), ty + 0.62 * math.sin(a)
            add("chair_seat", "wood", cx, cy, GAP, name=f"chair {2 * t + c + 1}")
            # Back posts behind the seat (away from the table), then the rail across their tops.
            bx, by = cx + 0.17 * math.cos(a), cy + 0.17 * math.sin(a)
            sx, sy = -math.sin(a), math.cos(a)
            for side in (-1, 1):
                add("chair_post", "wood", bx + side * 0.15 * sx, by + side * 0.15 * sy, 0.45)
            # The rail's axis runs along (sx, sy): rotate z onto it (about the horizontal (-sy, sx), 90 deg).
            add("chair_rail", "wood", bx - 0.15 * sx, by - 0.15 * sy, 0.93, rotate=[-sy, sx, 0, 90])
        # Tableware: two bottles, two wine glasses, two cups, two plates, two small bowls, a salad bowl.
        k = math.radians(35 * t)
        def at(r, a):
            return tx + r * math.cos(a + k), ty + r * math.sin(a + k)
        wares = [("wine_bottle", "green_glass", 0.06, 90), ("beer_bottle", "amber_glass", 0.17, 130),
                 ("wine_glass", "clear_glass", 0.28, 155), ("wine_glass", "clear_glass", 0.28, 335),
                 ("coffee_cup", "porcelain", 0.3, 240), ("coffee_cup", "porcelain", 0.3, 60),
                 ("plate", "porcelain", 0.27, 200), ("plate", "porcelain", 0.27, 20),
                 ("small_bowl", "terracotta", 0.22, 280), ("small_bowl", "terracotta", 0.25, 105),
                 ("salad_bowl", "steel", 0.12, 250)]
        for profile, material, r, a in wares:
            x, y = at(r, math.radians(a))
            add(profile, material, x, y, top + GAP)

    # Rails: posts along the back and both sides of the patio, a rail over them (quads).
    posts = []
    for i in range(16):
        posts.append((-4.5 + 9.0 * i / 15, 4.2))
    for side in (-4.5, 4.5):
        for i in range(12):
            posts.append((side, -2.4 + 6.6 * i / 12))
    for x, y in posts:
        add("rail_post", "white_paint", x, y, GAP)
    assert len(objects) == 100, len(objects)

    quads = [{"corners": [[-30, -30, 0], [30, -30, 0], [30, 30, 0], [-30, 30, 0]], "material": "stone"}]

    def box(x0, y0, x1, y1, z0, z1, material):
        # The four long faces of a rail, from (x0, y0) to (x1, y1).
        quads.extend([
            {"corners": [[x0, y0, z1], [x1, y1, z1], [x1, y1, z0], [x0, y0, z0]], "material": material},
        ])

    def rail(x0, y0, x1, y1, z, w, material):
        dx, dy = x1 - x0, y1 - y0
        n = math.hypot(dx, dy)
        ox, oy = -dy / n * w, dx / n * w
        c = [[x0 + ox, y0 + oy], [x1 + ox, y1 + oy], [x1 - ox, y1 - oy], [x0 - ox, y0 - oy]]
        lo, hi = z - w, z + w
        def q(a, b, za, zb):
            quads.append({"corners": [[r6(a[0]), r6(a[1]), za], [r6(b[0]), r6(b[1]), za], [r6(b[0]), r6(b[1]), zb], [r6(a[0]), r6(a[1]), zb]],
                          "material": material})
        q(c[0], c[1], lo, hi)
        q(c[3], c[2], lo, hi)
        quads.append({"corners": [[r6(c[0][0]), r6(c[0][1]), hi], [r6(c[1][0]), r6(c[1][1]), hi], [r6(c[2][0]), r6(c[2][1]), hi], [r6(c[3][0]), r6(c[3][1]), hi]], "material": material})
        quads.append({"corners": [[r6(c[0][0]), r6(c[0][1]), lo], [r6(c[1][0]), r6(c[1][1]), lo], [r6(c[2][0]), r6(c[2][1]), lo], [r6(c[3][0]), r6(c[3][1]), lo]], "material": material})

    for z, w in ((1.0, 0.035), (0.35, 0.02)):
        rail(-4.5, 4.2, 4.5, 4.2, z, w, "white_paint")
        rail(-4.5, -2.4, -4.5, 4.2, z, w, "white_paint")
        rail(4.5, -2.4, 4.5, 4.2, z, w, "white_paint")
    # A hedge beyond the back rail and the restaurant's wall to the left, for a sense of place.
    quads.append({"corners": [[-12, 6.0, 0], [12, 6.0, 0], [12, 6.0, 1.6], [-12, 6.0, 1.6]], "material": "hedge"})
    quads.append({"corners": [[-12, 6.0, 1.6], [12, 6.0, 1.6], [12, 6.6, 1.6], [-12, 6.6, 1.6]], "material": "hedge"})
    quads.append({"corners": [[-6.5, -8, 0], [-6.5, 12, 0], [-6.5, 12, 4.5], [-6.5, -8, 4.5]], "material": "wall"})

    camera = {"from": [0.1, -3.1, 1.6], "to": [0.1, 1.4, 0.6], "up": [0, 0, 1], "fov": 48,
              "width": 640, "height": 480, "spp": 64}
    sun = [0.55, 0.65, -0.75]
    if not points_only:
        dump("patio.json", {
            "description": "The paper's outdoor restaurant patio (Baciu, Jia & Lam 2001, Figures 10 and 11): "
                           "three round tables, six chairs, cups, bottles and bowls on the tables, patio rails on "
                           "forty round rail fixtures; one hundred surfaces of revolution. Written by make_scenes.py.",
            "camera": camera,
            "profiles": profiles,
            "materials": materials,
            "objects": objects,
            "quads": quads,
            "lights": [{"type": "sun", "direction": sun, "irradiance": [3.2, 3.0, 2.7], "angle": 1.0}],
            "environment": {"sky": {"zenith": [0.22, 0.38, 0.75], "horizon": [0.75, 0.8, 0.88]}},
        })
        return
    # What POV-Ray renders the same way (README, "Against POV-Ray"): the sun becomes a point light
    # 40 m away along its direction (the same irradiance at the tables: I = E d^2), the sky a uniform
    # environment, the rough metals a diffuse table finish and a mirror-steel bowl.
    materials["table_metal"] = {"type": "diffuse", "color": [0.25, 0.3, 0.28]}
    materials["steel"] = {"type": "mirror", "color": [0.8, 0.8, 0.82]}
    d = 40.0
    n = math.sqrt(sum(c * c for c in sun))
    position = [r6(0.1 - sun[0] / n * d), r6(1.4 - sun[1] / n * d), r6(0.0 - sun[2] / n * d)]
    dump("patio_points.json", {
        "description": "The patio (patio.json) lit only by what POV-Ray renders the same way: a point light "
                       "instead of the sun, a uniform environment instead of the sky, no rough metal. "
                       "Written by make_scenes.py.",
        "camera": camera,
        "profiles": profiles,
        "materials": materials,
        "objects": objects,
        "quads": quads,
        "lights": [{"type": "point", "position": position, "intensity": [r6(e * d * d) for e in (3.2, 3.0, 2.7)]}],
        "environment": {"color": [0.4, 0.45, 0.55]},
    })


def still_life():
    profiles = {
        "goblet": {"points": pts(goblet())},
        "vase": {"points": pts(vase())},
        "bottle": {"csv": "profiles/wine_bottle.csv"},
        "bowl": {"points": pts(bowl(0.09, 0.06, 0.003))},
        "table": {"points": pts([(0, 0), (0.05, 0), (0.05, 0.68), (0.58, 0.70), (0.6, 0.72), (0.6, 0.75), (0, 0.75)])},
    }
    materials = {
        "clear_glass": {"type": "glass", "ior": 1.5},
        "green_glass": {"type": "glass", "ior": 1.52, "tint": [0.45, 0.78, 0.5]},
        "copper": {"type": "metal", "color": [0.95, 0.64, 0.54], "roughness": 0.25},
        "chrome": {"type": "mirror", "color": [0.9, 0.9, 0.9]},
        "walnut": {"type": "diffuse", "color": [0.35, 0.2, 0.1]},
        "floor": {"type": "diffuse", "color": [0.5, 0.5, 0.5]},
        "cream": {"type": "diffuse", "color": [0.85, 0.8, 0.7]},
        "blue": {"type": "diffuse", "color": [0.1, 0.2, 0.55]},
    }
    top = r6(0.75 + 2 * GAP)  # on the table's top face, the table standing GAP above the floor
    objects = [
        {"profile": "table", "material": "walnut", "translate": [0, 0, GAP], "name": "table"},
        {"profile": "goblet", "material": "clear_glass", "translate": [-0.2, 0.0, top], "name": "goblet"},
        {"profile": "vase", "material": "copper", "translate": [0.17, 0.12, top], "name": "vase"},
        {"profile": "bottle", "material": "green_glass", "translate": [0.0, 0.2, top], "name": "bottle"},
        {"profile": "bowl", "material": "chrome", "translate": [0.1, -0.2, top], "name": "bowl"},
    ]
    quads = [{"corners": [[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], "material": "floor"}]
    # A striped backdrop: its edges, bent by the glass, are what makes glass read as glass.
    for i in range(-6, 6):
        x0, x1 = 0.25 * i, 0.25 * (i + 1)
        quads.append({"corners": [[x0, 1.2, 0], [x1, 1.2, 0], [x1, 1.2, 2.5], [x0, 1.2, 2.5]],
                      "material": "cream" if i % 2 == 0 else "blue"})
    dump("still_life.json", {
        "description": "Glass and metal vessels on a table: a goblet, a copper vase, a green bottle, a chrome bowl.",
        "camera": {"from": [0.05, -1.35, 1.18], "to": [0.0, 0.05, 0.86], "up": [0, 0, 1], "fov": 26,
                   "width": 480, "height": 360, "spp": 64},
        "profiles": profiles,
        "materials": materials,
        "objects": objects,
        "quads": quads,
        "lights": [{"type": "point", "position": [-1.2, -1.0, 2.0], "intensity": [3.5, 3.3, 3.0]},
                   {"type": "point", "position": [1.5, -0.5, 1.6], "intensity": [1.0, 1.1, 1.3]}],
        "environment": {"color": [0.35, 0.35, 0.38]},
    })


# ----------------------------------------------------------------------------------------------
# Smooth profiles: splines (README, "Splines"), traced exactly. Each is a closed solid listed from
# the axis at the bottom, up the outside and, for hollow vessels, back down the inside.

def line_to(path, to):
    """A straight cubic piece from the path's last point: inner points at the thirds."""
    (r0, z0), (r1, z1) = path[-1], to
    path += [(r0 + (r1 - r0) / 3, z0 + (z1 - z0) / 3), (r1 + (r0 - r1) / 3, z1 + (z0 - z1) / 3), to]


def curve_to(path, c1, c2, to):
    path += [c1, c2, to]


def spline_vase():
    """Catmull-Rom through the outside, a rolled lip and the inside: the curve rounds every point."""
    outside = [(0.0, 0.0), (0.045, 0.0), (0.058, 0.012), (0.08, 0.06), (0.092, 0.12), (0.082, 0.18), (0.055, 0.23),
               (0.036, 0.27), (0.034, 0.3), (0.042, 0.325), (0.05, 0.335)]
    lip = [(0.049, 0.341), (0.044, 0.338)]
    inside = [(0.037, 0.327), (0.0295, 0.3), (0.031, 0.27), (0.05, 0.23), (0.077, 0.18), (0.0865, 0.12),
              (0.0745, 0.06), (0.052, 0.018), (0.0, 0.012)]
    return outside + lip + inside


def spline_wine_glass():
    """Bezier pieces: a flat foot with a rounded edge, a stem flaring into a tulip bowl, a thin rim."""
    p = [(0.0, 0.0)]
    line_to(p, (0.034, 0.0))
    curve_to(p, (0.0375, 0.0), (0.0375, 0.004), (0.034, 0.004))                  # the foot's rounded edge
    curve_to(p, (0.012, 0.006), (0.004, 0.012), (0.0035, 0.03))                   # foot into the stem
    line_to(p, (0.0035, 0.085))                                                    # the stem
    curve_to(p, (0.0035, 0.1), (0.012, 0.102), (0.03, 0.112))                      # the bowl's base
    curve_to(p, (0.05, 0.124), (0.05, 0.165), (0.038, 0.2))                        # the tulip bowl
    curve_to(p, (0.0376, 0.2012), (0.0362, 0.2012), (0.0358, 0.2))                 # the rim
    curve_to(p, (0.0472, 0.166), (0.0472, 0.126), (0.0285, 0.1145))                # inside, back down
    curve_to(p, (0.014, 0.106), (0.006, 0.1045), (0.0, 0.104))
    return p


def spline_tumbler():
    """Quadratic pieces: a heavy base, straight flared walls, a rounded rim."""
    return [(0.0, 0.0), (0.028, 0.0), (0.031, 0.003), (0.0345, 0.006), (0.0345, 0.03), (0.0375, 0.06), (0.04, 0.095),
            (0.0403, 0.0975), (0.0385, 0.0975), (0.0362, 0.06), (0.0335, 0.03), (0.033, 0.016), (0.0, 0.016)]


def spline_jug():
    """A natural spline through a pear-shaped outline, closed by its cap on the axis."""
    return [(0.0, 0.0), (0.05, 0.002), (0.07, 0.03), (0.075, 0.08), (0.06, 0.13), (0.035, 0.17), (0.028, 0.21),
            (0.034, 0.235), (0.0, 0.24)]


def spline_bowl():
    """Bezier: a foot ring, a wide curved wall, a rolled rim and the inside."""
    p = [(0.0, 0.0)]
    line_to(p, (0.035, 0.0))
    curve_to(p, (0.04, 0.0), (0.04, 0.006), (0.045, 0.008))
    curve_to(p, (0.09, 0.012), (0.11, 0.03), (0.115, 0.06))
    curve_to(p, (0.1155, 0.0635), (0.1115, 0.0645), (0.111, 0.06))
    curve_to(p, (0.104, 0.03), (0.08, 0.016), (0.035, 0.012))
    line_to(p, (0.0, 0.012))
    return p


def spline_still_life():
    """A still life of spline vessels, every profile traced exactly: render with
    build/bin/revolve-render scenes/spline_still_life.json -o docs/spline_still_life.png"""
    profiles = {
        "vase": {"spline": "catmull-rom", "points": pts(spline_vase())},
        "wine_glass": {"spline": "bezier", "points": pts(spline_wine_glass())},
        "tumbler": {"spline": "quadratic", "points": pts(spline_tumbler())},
        "jug": {"spline": "natural", "points": pts(spline_jug())},
        "bowl": {"spline": "bezier", "points": pts(spline_bowl())},
        "table": {"points": pts([(0, 0), (0.05, 0), (0.05, 0.68), (0.58, 0.70), (0.6, 0.72), (0.6, 0.75), (0, 0.75)])},
    }
    materials = {
        "clear_glass": {"type": "glass", "ior": 1.5},
        "amber_glass": {"type": "glass", "ior": 1.52, "tint": [0.92, 0.7, 0.35]},
        "glaze": {"type": "metal", "color": [0.12, 0.28, 0.6], "roughness": 0.35},
        "copper": {"type": "metal", "color": [0.95, 0.64, 0.54], "roughness": 0.2},
        "porcelain": {"type": "diffuse", "color": [0.88, 0.86, 0.8]},
        "walnut": {"type": "diffuse", "color": [0.35, 0.2, 0.1]},
        "floor": {"type": "diffuse", "color": [0.5, 0.5, 0.5]},
        "cream": {"type": "diffuse", "color": [0.85, 0.8, 0.7]},
        "red": {"type": "diffuse", "color": [0.55, 0.12, 0.1]},
    }
    top = 0.75
    objects = [
        {"profile": "table", "material": "walnut", "name": "table"},
        {"profile": "vase", "material": "glaze", "translate": [0.2, 0.2, top], "name": "vase"},
        {"profile": "wine_glass", "material": "clear_glass", "translate": [-0.1, -0.09, top], "name": "wine glass"},
        {"profile": "wine_glass", "material": "clear_glass", "translate": [0.01, 0.12, top], "name": "second glass"},
        {"profile": "tumbler", "material": "amber_glass", "translate": [0.07, -0.17, top], "name": "tumbler"},
        {"profile": "jug", "material": "copper", "translate": [-0.25, 0.17, top], "name": "jug"},
        {"profile": "bowl", "material": "porcelain", "translate": [0.25, -0.1, top], "name": "bowl"},
    ]
    quads = [{"corners": [[-5, -5, 0], [5, -5, 0], [5, 5, 0], [-5, 5, 0]], "material": "floor"}]
    for i in range(-6, 6):
        x0, x1 = 0.25 * i, 0.25 * (i + 1)
        quads.append({"corners": [[x0, 1.2, 0], [x1, 1.2, 0], [x1, 1.2, 2.5], [x0, 1.2, 2.5]],
                      "material": "cream" if i % 2 == 0 else "red"})
    dump("spline_still_life.json", {
        "description": "Spline vessels on a table, each traced exactly: a Catmull-Rom vase, Bezier wine glasses and bowl, "
                       "a quadratic tumbler, a natural-spline jug.",
        "camera": {"from": [0.05, -1.3, 1.12], "to": [0.0, 0.05, 0.86], "up": [0, 0, 1], "fov": 24,
                   "width": 640, "height": 420, "spp": 64},
        "profiles": profiles,
        "materials": materials,
        "objects": objects,
        "quads": quads,
        "lights": [{"type": "point", "position": [-1.2, -1.0, 2.0], "intensity": [3.5, 3.3, 3.0]},
                   {"type": "point", "position": [1.5, -0.5, 1.6], "intensity": [1.0, 1.1, 1.3]}],
        "environment": {"color": [0.35, 0.35, 0.38]},
    })


def many():
    """A warehouse yard: 3,000 instances of four profiles."""
    profiles = {
        "barrel": {"points": pts(barrel())},
        "keg": {"points": pts(keg())},
        "cone": {"points": pts(traffic_cone())},
        "drum": {"points": pts([(0, 0), (0.3, 0), (0.3, 0.9), (0, 0.9)])},
    }
    materials = {
        "oak": {"type": "diffuse", "color": [0.45, 0.28, 0.14]},
        "steel": {"type": "metal", "color": [0.75, 0.75, 0.78], "roughness": 0.3},
        "orange": {"type": "diffuse", "color": [0.85, 0.3, 0.05]},
        "blue": {"type": "diffuse", "color": [0.1, 0.25, 0.6]},
        "concrete": {"type": "diffuse", "color": [0.5, 0.5, 0.48]},
    }
    kinds = [("barrel", "oak"), ("keg", "steel"), ("cone", "orange"), ("drum", "blue")]
    objects = []
    n = 0
    for i in range(60):
        for j in range(50):
            profile, material = kinds[(i * 7 + j * 3 + (i * j) % 5) % 4]
            objects.append({"profile": profile, "material": material,
                            "translate": [r6(-15 + 0.75 * i), r6(-2 + 0.75 * j), GAP],
                            "rotate": [0, 0, 1, (i * 37 + j * 11) % 360]})
            n += 1
    dump("many.json", {
        "description": "3,000 instances of four profiles: each profile is built once and instanced.",
        "camera": {"from": [-19, -9, 7], "to": [0, 12, 0], "up": [0, 0, 1], "fov": 45,
                   "width": 480, "height": 320, "spp": 16},
        "profiles": profiles,
        "materials": materials,
        "objects": objects,
        "quads": [{"corners": [[-60, -60, 0], [60, -60, 0], [60, 60, 0], [-60, 60, 0]], "material": "concrete"}],
        "lights": [{"type": "sun", "direction": [0.4, 0.7, -0.6], "irradiance": [3, 2.9, 2.7], "angle": 1.0}],
        "environment": {"sky": {"zenith": [0.25, 0.4, 0.75], "horizon": [0.75, 0.8, 0.88]}},
    })


def turned_vessel(height, radius, waves, n):
    """A hollow turned vessel of n outer points: radius(t), t in [0, 1] from foot to lip, times
    `radius`, with a flared lip; the inside follows the outer wall."""
    outer = [(radius * (0.7 + 0.25 * math.sin(math.pi * t * 1.15) + 0.035 * math.sin(2 * math.pi * waves * t)) *
              (1 + 0.35 * max(0.0, (t - 0.85) / 0.15) ** 2), height * t)
             for t in (i / n for i in range(n + 1))]
    return hollow(outer, 0.0035 * radius / 0.06, 0.006)


def vessels(n=1000):
    """Fifteen turned vessels on a table, each profile of about 2n points (distinct profiles, so no
    two objects share a lathe): the lathe-heavy scene of the comparison with POV-Ray."""
    profiles, objects = {}, []
    materials = {
        "glaze_blue": {"type": "diffuse", "color": [0.15, 0.3, 0.6]},
        "glaze_cream": {"type": "diffuse", "color": [0.85, 0.8, 0.68]},
        "terracotta": {"type": "diffuse", "color": [0.62, 0.3, 0.18]},
        "chrome": {"type": "mirror", "color": [0.85, 0.85, 0.87]},
        "clear_glass": {"type": "glass", "ior": 1.5},
        "table": {"type": "diffuse", "color": [0.4, 0.3, 0.22]},
        "wall": {"type": "diffuse", "color": [0.7, 0.68, 0.62]},
    }
    kinds = ["glaze_blue", "terracotta", "chrome", "glaze_cream", "clear_glass"]
    for row in range(3):
        for col in range(5):
            i = row * 5 + col
            name = f"vessel_{i + 1}"
            height = 0.18 + 0.04 * ((i * 7) % 5)
            radius = 0.045 + 0.006 * ((i * 3) % 4)
            profiles[name] = {"points": pts(turned_vessel(height, radius, 1 + i % 3, n))}
            objects.append({"profile": name, "material": kinds[(i + row) % 5], "name": name,
                            "translate": [r6(-0.46 + 0.22 * col + 0.05 * row), r6(0.25 * row), 0.0]})
    quads = [{"corners": [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]], "material": "table"},
             {"corners": [[-2, 0.9, 0], [2, 0.9, 0], [2, 0.9, 2], [-2, 0.9, 2]], "material": "wall"}]
    dump("vessels.json", {
        "description": f"Fifteen turned vessels on a table, each a distinct profile of about {2 * n} points: "
                       "lathe-heavy. Written by make_scenes.py.",
        "camera": {"from": [0.03, -1.7, 0.75], "to": [0.03, 0.22, 0.12], "up": [0, 0, 1], "fov": 30,
                   "width": 640, "height": 480, "spp": 16},
        "profiles": profiles,
        "materials": materials,
        "objects": objects,
        "quads": quads,
        "lights": [{"type": "point", "position": [-1.0, -1.2, 1.6], "intensity": [3.0, 2.9, 2.7]},
                   {"type": "point", "position": [1.2, -0.6, 1.0], "intensity": [0.8, 0.85, 1.0]}],
        "environment": {"color": [0.3, 0.3, 0.33]},
    }, compact_points=True)


if __name__ == "__main__":
    patio()
    patio(points_only=True)
    still_life()
    vessels()
    spline_still_life()
    many()
