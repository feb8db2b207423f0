#!/usr/bin/env python3
"""The independent reader (mbk_reader.py, written from formats/SPEC.md alone) against microbake (ctest spec_reader).

Bakes small inputs of every asset kind with the real executable, then for each file: the reader parses the header,
section table, metadata and every checksum, and agrees with `microbake info --format json` on every field info
reports. Then the spec's numeric conventions that a second implementation needs, recomputed here from the spec's
words: how 8- and 16-bit texels become unit normals, how an integer moments driver becomes f and the shift, the
lanczos window. Last, files written here from the spec (mbk_writer.py) that break or keep the rules a reader had
to guess before (trailing bytes, empty sections, duplicate metadata keys, a byte-order mark): the reader and
`microbake validate` must give the same verdict, with the finding ids of SPEC section 8.

Usage: spec_reader_test.py MICROBAKE_EXE
"""

import json
import math
import os
import struct
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mbk_reader  # noqa: E402
import mbk_writer  # noqa: E402
from png_writer import write_png  # noqa: E402

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def floats(data, section):
    return struct.unpack_from(f"<{section['bytes'] // 4}f", data, section["offset"])


class Microbake:
    def __init__(self, exe, folder):
        self.exe, self.folder = exe, folder

    def run(self, *args, expect=0):
        r = subprocess.run([self.exe, *args], cwd=self.folder, capture_output=True, text=True)
        if r.returncode != expect:
            raise RuntimeError(f"microbake {' '.join(args)} exited {r.returncode}: {r.stderr.strip()}")
        return r.stdout


def make_inputs(mb, folder):
    """The generated maps, and integer images written here so that their codes are known."""
    mb.run("gen", "bumps", "--size", "16", "-q", "-o", "bumps.png")
    mb.run("gen", "leather", "--size", "16", "--seed", "2", "-q", "-o", "leather.png")
    mb.run("gen", "panels", "--size", "32", "-q", "-o", "panels.png", "--creases", "panels.json")
    mb.run("gen", "flakes", "--size", "16", "-q", "-o", "flakes.exr")
    with open(os.path.join(folder, "graph.json"), "w") as f:
        json.dump({"exemplars": [{"id": "a", "path": "bumps.png"}, {"id": "b", "path": "leather.png"}],
                   "root": "a", "edges": [{"source": "a", "destination": "b", "r": 1},
                                          {"source": "b", "destination": "b", "r": 1}]}, f)
    codes = {}
    # 8-bit RGB: every code in x (and its mirror 255 - c in y, whose decoded values are not exact negatives),
    # z in the upper half; 16-bit RGB: a spread of codes. Both 16 x 16.
    codes["codes8"] = (255, [[v for x in range(16) for v in (16 * r + x, 255 - 16 * r - x, 128 + (16 * r + x) % 128)]
                             for r in range(16)])
    codes["codes16"] = (65535, [[v for x in range(16) for v in ((r * 4099 + x * 257) % 65536,
                                                                 (r * 911 + x * 6151) % 65536,
                                                                 32768 + (r * 16 + x) * 127)] for r in range(16)])
    for name, (top, rows) in codes.items():
        write_png(os.path.join(folder, name + ".png"), 16, 16, 3, 8 if top == 255 else 16, rows)
    # An 8-bit one-channel driver of 13 x 7 texels (odd sizes: partly covered texels in the coarser levels).
    codes["driver8"] = (255, [[(r * 37 + x * 11) % 256 for x in range(13)] for r in range(7)])
    write_png(os.path.join(folder, "driver8.png"), 13, 7, 1, 8, codes["driver8"][1])
    return codes


BAKES = [
    ("mip", ["mip", "bumps.png"]),
    ("mip_codes8", ["mip", "codes8.png", "--convention", "+Y"]),
    ("mip_codes16", ["mip", "codes16.png", "--convention", "+Y"]),
    ("mip_exr", ["mip", "flakes.exr"]),
    ("sh", ["sh", "bumps.png", "--order", "4"]),
    ("sh_lanczos", ["sh", "bumps.png", "--order", "6", "--precision", "f32", "--window", "lanczos"]),
    ("vmf", ["vmf", "bumps.png", "--lobes", "3", "--max-iterations", "20"]),
    ("vmf_material", ["vmf", "bumps.png", "--lobes", "2", "--align", "0.5", "--material", "codes8.png"]),
    ("lut", ["lut", "bumps.png"]),
    ("rmq", ["rmq", "bumps.png", "--patch", "4"]),
    ("rmq_8bit", ["rmq", "leather.png", "--patch", "8", "--bits", "8"]),
    ("moments", ["moments", "driver8.png"]),
    ("moments_channel", ["moments", "bumps.png", "--channel", "2"]),
    ("histogram", ["histogram", "bumps.png", "--method", "exact"]),
    ("neural_histogram", ["histogram", "bumps.png", "--iterations", "20", "--batch", "64"]),
    ("colormap", ["colormap", os.path.join(SOURCE_DIR, "examples", "colormaps", "stripes.json"), "--size", "32x16"]),
    ("colormap_image", ["colormap", "codes8.png", "--size", "16x8"]),
    ("crease", ["crease", "panels.png", "--curves", "panels.json"]),
    ("graph", ["graph", "graph.json"]),
]


def compare_with_info(mb, name, read):
    info = json.loads(mb.run("info", "--format", "json", name + ".mbk"))
    for key in ("file_size", "format_version", "kind", "kind_id", "metadata"):
        check(info[key] == read[key], f"{name}: info's {key} differs from the reader's")
    check(len(info["sections"]) == len(read["sections"]), f"{name}: section count")
    for theirs, ours in zip(info["sections"], read["sections"]):
        mine = {"name": ours["name"], "type": ours["type"], "shape": ours["shape"], "offset": ours["offset"],
                "bytes": ours["bytes"], "checksum": "xxh3:%016x" % ours["checksum"], "checksum_ok": True}
        check(theirs == mine, f"{name}: section {ours['name']}: info {theirs}, reader {mine}")


def decoded_normal(codes, top):
    """SPEC 'Normal-map inputs': v = float(c * float(1 / top)), x = 2v - 1 in double, normalised in double."""
    scale = f32(1.0 / top)
    x, y, z = (2.0 * f32(c * scale) - 1.0 for c in codes)
    z = max(z, 0.0) if z >= -1.0 / top * (1 + 1e-6) else z  # the code just below the middle is the horizon
    length = math.sqrt(x * x + y * y + z * z)
    return [f32(x / length), f32(y / length), f32(z / length)]


def check_conventions(files, codes):
    for name in ("codes8", "codes16"):
        data, read = files["mip_" + name]
        top, rows = codes[name]
        level0 = floats(data, read["sections"][0])
        want = [v for row in rows for x in range(16) for v in decoded_normal(row[3 * x:3 * x + 3], top)]
        check(list(level0) == want, f"mip_{name}: level_0 is not the spec's decoding of the codes")
    # Moments of an integer driver: f = float(c * float(1 / top)); the shift s = float(mean), the mean summed in
    # double along each row, then the row sums in row order; level 0 = (float(f - s), float(d * d)).
    data, read = files["moments"]
    top, rows = codes["driver8"]
    f = [[f32(c * f32(1.0 / top)) for c in row] for row in rows]
    total = 0.0
    for row in f:
        row_sum = 0.0
        for v in row:
            row_sum += v
        total += row_sum
    shift = f32(total / (13 * 7))
    check(read["metadata"]["parameters"]["shift"] == shift, "moments: shift is not the spec's mean")
    want = []
    for row in f:
        for v in row:
            d = f32(v - shift)
            want += [d, f32(d * d)]
    check(list(floats(data, read["sections"][0])) == want, "moments: level_0 is not (f - s, (f - s)^2)")
    # The lanczos window: the normalised sinc, w_l = sin(pi t) / (pi t) with t = l / (L + 1).
    data, read = files["sh_lanczos"]
    window = floats(data, next(s for s in read["sections"] if s["name"] == "window"))
    order = len(window) - 1
    want = [1.0] + [math.sin(math.pi * l / (order + 1)) / (math.pi * l / (order + 1)) for l in range(1, order + 1)]
    check(all(abs(a - b) <= 2 ** -23 * b for a, b in zip(window, want)), f"sh: lanczos window {window}")


def reader_verdict(data):
    try:
        mbk_reader.read(data)
        return None
    except mbk_reader.SpecError as e:
        return e.rule


def validate_ids(mb, folder, data):
    path = os.path.join(folder, "case.mbk")
    with open(path, "wb") as f:
        f.write(data)
    r = subprocess.run([mb.exe, "validate", "--format", "json", path], capture_output=True, text=True)
    (result,) = json.loads(r.stdout)["files"]  # microbake.validate/1: one result per file
    return sorted({m["id"] for m in result["messages"] if m["severity"] == "error"})


def check_rule_cases(mb, folder, mip_bytes):
    """Files written here from the spec: microbake's file again, byte for byte, and one file per rule, on which the
    reader and `microbake validate` agree, with the spec's ids."""
    cases = mbk_writer.rule_cases(mbk_reader.read(mip_bytes), mip_bytes)
    check(cases[0][1] == mip_bytes, "the spec's writer does not reproduce microbake's mip file byte for byte")
    for name, data, rule, finding in cases:
        verdict, ids = reader_verdict(data), validate_ids(mb, folder, data)
        check(verdict == rule, f"case {name}: reader says {verdict}, the spec {rule}")
        check(ids == ([finding] if finding else []), f"case {name}: validate reports {ids}, the spec {finding}")


def main():
    exe = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory(prefix="spec_reader_") as folder:
        mb = Microbake(exe, folder)
        codes = make_inputs(mb, folder)
        files = {}
        for name, args in BAKES:
            mb.run(*args, "-q", "-o", name + ".mbk")
            with open(os.path.join(folder, name + ".mbk"), "rb") as f:
                data = f.read()
            try:
                read = mbk_reader.read(data)
            except mbk_reader.SpecError as e:
                check(False, f"{name}: the reader refuses microbake's file: {e}")
                continue
            files[name] = (data, read)
            compare_with_info(mb, name, read)
        kinds = {read["kind"] for _, read in files.values()}
        check(kinds == set(mbk_reader.KINDS.values()), f"kinds read: {sorted(kinds)}")
        check_conventions(files, codes)
        check_rule_cases(mb, folder, files["mip"][0])
    print(f"{len(BAKES)} files of {len(kinds)} kinds read; {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
