#!/usr/bin/env python3
"""Writes the two example beam patterns (revolve-lidar's `pattern` sensor key, docs/robot.md).

vlp16_pattern.csv: a 16-channel spinning sensor as the Velodyne VLP-16 user manual describes it.
Its 16 lasers fire one after another, 2.304 us apart, in the order of the manual's elevation table
(-15, 1, -13, 3, ..., -1, 15 degrees); a firing sequence of 16 takes 55.296 us with the recharge,
and the head turns on meanwhile. At 20 Hz, one revolution is 904 sequences (0.4 degrees apart);
each beam's azimuth is where the head points at its own firing time. The head turns clockwise
seen from above, as the VLP-16's does: the azimuth (counter-clockwise from +X) decreases.

rosette_pattern.csv: a non-repetitive rosette as two counter-rotating wedge prisms (a Risley pair,
as in Livox's sensors) draw it: at time t the beam points at
    azimuth + i elevation = (fov / 4) (exp(2 pi i f1 t) + exp(-2 pi i f2 t)),
fov = 38.4 degrees across, f1 = 120 Hz, f2 = 77 Hz (incommensurate enough that the petals do not
repeat within a sweep), 100,000 beams a second for 0.1 s: 10,000 beams. These rates are this
example's, not a product's.

Run from anywhere: python3 examples/robot/make_beam_patterns.py
"""
import math
from pathlib import Path

HERE = Path(__file__).resolve().parent


def write(name, beams):
    path = HERE / name
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w") as out:
        out.write("azimuth,elevation,time\n")
        for azimuth, elevation, time in beams:
            out.write(f"{azimuth:.9g},{elevation:.9g},{time:.9g}\n")
    tmp.replace(path)
    print(f"{path}: {len(beams)} beams")


def vlp16(rate_hz=20.0):
    elevations_deg = [-15, 1, -13, 3, -11, 5, -9, 7, -7, 9, -5, 11, -3, 13, -1, 15]  # laser IDs 0..15
    laser_gap, sequence = 2.304e-6, 55.296e-6
    sequences = round(1 / (rate_hz * sequence))  # 904 at 20 Hz
    beams = []
    for s in range(sequences):
        for laser, elevation in enumerate(elevations_deg):
            time = s * sequence + laser * laser_gap
            turned = 2 * math.pi * rate_hz * time  # clockwise from +X
            azimuth = math.remainder(-turned, 2 * math.pi) + 0.0  # no "-0"
            beams.append((azimuth, math.radians(elevation), time))
    return beams


def rosette(fov_deg=38.4, f1=120.0, f2=77.0, rate=100_000, duration=0.1):
    a = math.radians(fov_deg) / 4
    beams = []
    for k in range(round(rate * duration)):
        t = k / rate
        azimuth = a * (math.cos(2 * math.pi * f1 * t) + math.cos(2 * math.pi * f2 * t))
        elevation = a * (math.sin(2 * math.pi * f1 * t) - math.sin(2 * math.pi * f2 * t))
        beams.append((azimuth, elevation, t))
    return beams


if __name__ == "__main__":
    write("vlp16_pattern.csv", vlp16())
    write("rosette_pattern.csv", rosette())
