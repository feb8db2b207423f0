#!/usr/bin/env python3
"""Writes the histogram example's lighting and roughness inputs as PFM images (OpenImageIO reads them as float):
  studio.pfm     a 256 x 128 lat-long environment (sh_lighting.h conventions: row 0 the zenith +Y, column i at azimuth
                 2 pi (i + 1/2) / W, direction (sin t cos p, cos t, sin t sin p)): a dim sky gradient, a warm soft box
                 and a cool strip light, each with a 3-degree soft edge;
  roughness.pfm  a 64 x 64 roughness texture (first channel = sigma in radians): 0.02 at the left, 0.12 at the right,
                 with a band of 0.06 through the middle rows.
Usage: make_lighting.py OUT_DIR"""
import math
import struct
import sys


def write_pfm(path, width, height, channels, pixel):
    with open(path, "wb") as f:
        f.write(b"PF\n" if channels == 3 else b"Pf\n")
        f.write(b"%d %d\n-1.0\n" % (width, height))
        for row in reversed(range(height)):  # PFM stores the bottom row first
            for x in range(width):
                f.write(struct.pack("<%df" % channels, *pixel(x, row)))


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def studio(x, row, width=256, height=128):
    theta = math.pi * (row + 0.5) / height
    phi = 2 * math.pi * (x + 0.5) / width
    d = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
    radiance = [0.04 + 0.12 * max(d[1], 0.0)] * 3
    soft_edge = math.radians(3)
    lights = [(normalized((-0.45, 0.55, -0.7)), math.radians(12), (7.0, 6.4, 5.6)),
              (normalized((0.8, 0.35, -0.45)), math.radians(7), (1.6, 2.6, 4.2))]
    for axis, radius, colour in lights:
        angle = math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(axis, d)))))
        weight = max(0.0, min(1.0, (radius - angle) / soft_edge + 0.5))
        radiance = [r + weight * c for r, c in zip(radiance, colour)]
    return radiance


def roughness(x, row, size=64):
    sigma = 0.02 + 0.10 * x / (size - 1)
    return (0.06 if abs(row - size / 2) < size / 8 else sigma,)


out = sys.argv[1] if len(sys.argv) > 1 else "."
write_pfm(out + "/studio.pfm", 256, 128, 3, studio)
write_pfm(out + "/roughness.pfm", 64, 64, 1, roughness)
