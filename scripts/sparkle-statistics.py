#!/usr/bin/env python3
"""Sparkle statistics of glint renders in one crop (examples/results/glint/REPORT.md, issue 11): how many pixels
sparkle and how bright, so that an effect can be compared with its reference and the reference with itself (the
floor) where block means hide it. A pixel sparkles when its luminance (Rec. 709) exceeds `--factor` times the
median luminance of its row inside the crop (the glint-free background). Prints, per image: sparkle pixels, their
summed excess over the row median (the sparkles' energy), and quantiles of the excess (how bright one is).
Reads EXR through `oiiotool --dumpdata` (no Python image library needed).

    scripts/sparkle-statistics.py --crop X0,Y0,X1,Y1 [--factor F] IMAGE.exr [IMAGE.exr ...]
"""
import argparse
import statistics
import subprocess
import sys


def luminance_rows(path, x0, y0, x1, y1):
    out = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True, check=True).stdout
    rows = {}
    for line in out.splitlines():
        line = line.strip()
        if not line.startswith("Pixel ("):
            continue
        head, values = line.split(":", 1)
        x, y = (int(v) for v in head[len("Pixel ("):-1].split(","))
        if x0 <= x < x1 and y0 <= y < y1:
            r, g, b = (float(v) for v in values.split()[:3])
            rows.setdefault(y, []).append(0.2126 * r + 0.7152 * g + 0.0722 * b)
    if len(rows) != y1 - y0:
        sys.exit(f"sparkle-statistics.py: {path}: the crop {x0},{y0},{x1},{y1} is not inside the image")
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--crop", required=True, help="X0,Y0,X1,Y1 (pixels, end exclusive)")
    parser.add_argument("--factor", type=float, default=2.0)
    parser.add_argument("images", nargs="+")
    args = parser.parse_args()
    x0, y0, x1, y1 = (int(v) for v in args.crop.split(","))
    print(f"crop {x0},{y0}-{x1},{y1} ({(x1 - x0) * (y1 - y0)} pixels), sparkle: luminance > {args.factor} x row median")
    print("image | sparkle pixels | summed excess | excess quantiles 50% / 90% / max")
    for path in args.images:
        excess = []
        for row in luminance_rows(path, x0, y0, x1, y1).values():
            median = statistics.median(row)
            excess += [v - median for v in row if v > args.factor * median]
        q = sorted(excess)
        quantile = (lambda p: q[min(len(q) - 1, int(p * len(q)))]) if q else (lambda p: 0.0)
        print(f"{path} | {len(q)} | {sum(q):.2f} | {quantile(0.5):.3f} / {quantile(0.9):.3f} / {quantile(1.0):.3f}")


if __name__ == "__main__":
    main()
