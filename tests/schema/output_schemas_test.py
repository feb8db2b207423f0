#!/usr/bin/env python3
"""Every `--format json` output of microbake against its JSON Schema (formats/schema/<name>.schema.json).

Runs each command that offers `--format text|json` (found from `microbake help`, so a new command cannot be missed)
on small generated inputs, on success and on failure paths (an unreadable and a damaged asset, a bake that fails, a
comparison above its threshold), and checks each output with python3-jsonschema (Debian), an implementation
independent of ours. The schemas are checked against the draft 2020-12 meta-schema. A schema must not be stale: for
every object in every output, a key the output does not have makes the document invalid (additionalProperties false),
except in the free-form places listed in OPEN_OBJECTS; and a wrong "schema" name or version is refused.

usage: output_schemas_test.py MICROBAKE SOURCE_DIR
"""
import copy
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("output_schemas_test: python3-jsonschema is missing: run scripts/install-deps.sh")

EXE, SOURCE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
SCHEMA_DIR = os.path.join(SOURCE, "formats", "schema")

# Objects whose keys are not fixed by the output's schema, as JSON pointer patterns, and why.
OPEN_OBJECTS = {
    "info": [r"/metadata(/.*)?"],  # the asset's own metadata, per kind in formats/SPEC.md
    "validate": [r"/files/\d+/messages/\d+/details"],  # a finding's details, per finding id
    "baker": [r"/parameters"],  # the technique's parameters, declared by its parameter schema
}

failures = []
checked = {}  # schema name -> number of documents checked


def fail(what):
    failures.append(what)
    print("FAIL: " + what, file=sys.stderr)


def run(args, cwd, expect_exit):
    r = subprocess.run([EXE] + args, cwd=cwd, capture_output=True, text=True)
    if r.returncode != expect_exit:
        fail("microbake %s: exit %d, expected %d\n%s" % (" ".join(args), r.returncode, expect_exit, r.stderr))
    return r


def load_schema(name):
    with open(os.path.join(SCHEMA_DIR, name + ".schema.json")) as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    return schema


def errors(schema, document):
    return list(jsonschema.Draft202012Validator(schema).iter_errors(document))


def objects(node, pointer=""):
    """Every JSON object in the document with its JSON pointer."""
    if isinstance(node, dict):
        yield pointer, node
        for k, v in node.items():
            yield from objects(v, pointer + "/" + k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from objects(v, pointer + "/" + str(i))


def resolve(document, pointer):
    node = document
    for part in pointer.split("/")[1:]:
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def check(name, args, cwd, expect_exit=0):
    """Runs a command with --format json; its stdout must be one document its schema accepts, closed everywhere."""
    r = run(args + ["--format", "json"], cwd, expect_exit)
    what = "microbake " + " ".join(args)
    try:
        document = json.loads(r.stdout)
    except ValueError as e:
        fail("%s: stdout is not one JSON document (%s): %r" % (what, e, r.stdout[:200]))
        return None
    schema = load_schema(name)
    for e in errors(schema, document):
        fail("%s: does not match %s.schema.json at %s: %s" % (what, name, "/".join(map(str, e.absolute_path)), e.message))
    if document.get("schema") != schema["title"]:
        fail("%s: \"schema\" is %r, its schema file's title %r" % (what, document.get("schema"), schema["title"]))
    wrong = dict(document, schema=re.sub(r"/\d+$", "/0", schema["title"]))
    if not errors(schema, wrong):
        fail("%s: %s.schema.json accepts another version in \"schema\"" % (what, name))
    for pointer, _ in objects(document):
        if any(re.fullmatch(p, pointer) for p in OPEN_OBJECTS.get(name, [])):
            continue
        tampered = copy.deepcopy(document)
        resolve(tampered, pointer)["key_not_in_the_schema"] = 1
        if not errors(schema, tampered):
            fail("%s: %s.schema.json accepts an unknown key at '%s' (stale or open schema)" % (what, name, pointer))
    checked[name] = checked.get(name, 0) + 1
    return document


def commands_with_json():
    names = []
    listing = run(["help"], None, 0).stdout
    for line in listing[listing.index("Commands:\n") + 10:].splitlines():
        if not line.startswith("  "):
            break
        names.append(line.split()[0])
    return {n for n in names if "--format text|json" in run(["help", n], None, 0).stdout}


def main():
    tmp = tempfile.mkdtemp(prefix="microbake_schemas_")
    try:
        covered = exercise(tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    offered = commands_with_json()
    for c in sorted(offered - covered):
        fail("'%s' offers --format json but this test does not check it" % c)
    for c in sorted(covered - offered):
        fail("'%s' is checked here but its help does not offer --format text|json" % c)
    for f in sorted(os.listdir(SCHEMA_DIR)):
        if f.endswith(".schema.json") and f[: -len(".schema.json")] not in checked:
            fail("formats/schema/%s: no output was checked against it" % f)
    print("checked %d documents of %d schemas; %d commands offer --format json" %
          (sum(checked.values()), len(checked), len(offered)))
    if failures:
        sys.exit("output_schemas_test: %d failure(s)" % len(failures))


def exercise(t):
    """Runs every command on small inputs; returns the command names checked."""
    def setup(args):
        run(args + ["-q"], t, 0)

    setup(["gen", "bumps", "--size", "32", "--seed", "1", "-o", "bumps.png"])
    setup(["gen", "panels", "--size", "32", "-o", "panels.png", "--creases", "panels.json"])
    shutil.copy(os.path.join(SOURCE, "examples", "colormaps", "terrain.json"), t)
    with open(os.path.join(t, "graph.json"), "w") as f:
        json.dump({"exemplars": [{"id": "a", "path": "bumps.png"}], "root": "a",
                   "edges": [{"source": "a", "destination": "a", "r": 1}]}, f)
    shutil.copy(os.path.join(SOURCE, "tests", "cli", "scenes", "mip_scene.json"), os.path.join(t, "scene.json"))

    bakers = {
        "mip": ["mip", "bumps.png", "-o", "mip.mbk"],
        "lut": ["lut", "bumps.png", "--size", "16", "-o", "lut.mbk"],
        "rmq": ["rmq", "bumps.png", "--patch", "8", "-o", "rmq.mbk"],
        "sh": ["sh", "bumps.png", "--order", "4", "-o", "sh.mbk"],
        "vmf": ["vmf", "bumps.png", "--lobes", "2", "-o", "vmf.mbk"],
        "histogram": ["histogram", "bumps.png", "--iterations", "20", "--batch", "64", "-o", "histogram.mbk"],
        "colormap": ["colormap", "terrain.json", "--size", "16x4", "-o", "colormap.mbk"],
        "moments": ["moments", "bumps.png", "--channel", "2", "-o", "moments.mbk"],
        "crease": ["crease", "panels.png", "--curves", "panels.json", "-o", "crease.mbk"],
        "graph": ["graph", "graph.json", "-o", "graph.mbk"],
        "synth": ["synth", "graph.mbk", "--level", "5", "--window", "-3,2,12,8", "-o", "synth.png"],
    }
    for technique, args in bakers.items():
        report = check("baker", args, t)
        if report and report["technique"] != technique:
            fail("%s: technique %r" % (technique, report["technique"]))
        if report and report["output_bytes"] != os.path.getsize(os.path.join(t, args[args.index("-o") + 1])):
            fail("%s: output_bytes is not the file's size" % technique)

    check("info", ["info", "sh.mbk"], t)
    with open(os.path.join(t, "mip.mbk"), "rb") as f:
        damaged = bytearray(f.read())
    damaged[-1] ^= 0xFF  # the last section's last byte: its checksum fails
    with open(os.path.join(t, "damaged.mbk"), "wb") as f:
        f.write(damaged)
    check("info", ["info", "damaged.mbk"], t, expect_exit=3)
    report = check("validate", ["validate", "mip.mbk", "damaged.mbk", "absent.mbk", "vmf.mbk"], t, expect_exit=3)
    if report:
        got = [(r["file"], r["valid"], r["exit_code"]) for r in report["files"]]
        want = [("mip.mbk", True, 0), ("damaged.mbk", False, 3), ("absent.mbk", False, 2), ("vmf.mbk", True, 0)]
        if got != want:
            fail("validate: one result per file in order: got %s, expected %s" % (got, want))

    check("bake", ["bake", "scene.json", "--out-dir", "assets", "--dry-run"], t)
    check("bake", ["bake", "scene.json", "--out-dir", "assets"], t)
    check("bake", ["bake", "absent_scene.json"], t, expect_exit=2)
    check("render", ["render", "scene.json", "--assets", "assets", "-o", "effects.exr"], t)
    check("render", ["render", "scene.json", "--reference", "2", "-o", "reference.exr"], t)
    check("compare", ["compare", "effects.exr", "reference.exr"], t)
    check("compare", ["compare", "effects.exr", "effects.exr", "--max-rmse", "0"], t)
    check("compare", ["compare", "effects.exr", "reference.exr", "--max-rmse", "1e-9"], t, expect_exit=6)
    return {"info", "validate", "bake", "render", "compare"} | set(bakers)


if __name__ == "__main__":
    main()
