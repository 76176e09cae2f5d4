#!/usr/bin/env python3
"""Writes assets/scenes/sky_sun.pfm, the equirectangular map of courtyard_envmap.json: a blue
sky brighter toward the horizon, a dim ground below it and a one-texel sun where
courtyard_sky.json's sun light comes from (docs/scene-format.md "environment" for the
convention: top row the zenith, the centre column toward -z, u = 3/4 toward +x)."""
import math
import struct
import sys

WIDTH, HEIGHT = 128, 64
SUN_TRAVELS = (0.35, -0.6, 0.72)  # courtyard_sky.json's sun direction
SUN_RADIANCE = (3000.0, 2900.0, 2700.0)  # W/(m^2 sr) over one texel (about 2.8 degrees)
GROUND_RADIANCE = (0.05, 0.05, 0.04)


def main(path):
    toward = [-c for c in SUN_TRAVELS]
    norm = math.sqrt(sum(c * c for c in toward))
    x, y, z = (c / norm for c in toward)
    sun_texel = (int((0.5 + math.atan2(x, -z) / (2 * math.pi)) * WIDTH),
                 int(math.acos(y) / math.pi * HEIGHT))
    rows = []
    for j in range(HEIGHT):
        theta = (j + 0.5) / HEIGHT * math.pi
        row = []
        for i in range(WIDTH):
            if (i, j) == sun_texel:
                row.append(SUN_RADIANCE)
            elif theta < math.pi / 2:
                c = math.cos(theta)
                row.append((0.9 * (0.4 + 0.6 * (1 - c)), 1.5 * (0.4 + 0.6 * (1 - c)),
                            3.0 * (0.5 + 0.5 * c)))
            else:
                row.append(GROUND_RADIANCE)
        rows.append(row)
    with open(path, "wb") as out:
        out.write(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
        for row in reversed(rows):  # PFM stores the bottom row first
            for texel in row:
                out.write(struct.pack("<3f", *texel))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "assets/scenes/sky_sun.pfm")
