"""An independent reader of .mbk files, written from formats/SPEC.md alone (it shares no code with microbake's
formats/ and links nothing of it): the header, the metadata, the section table, every rule of the container
(sections 1 to 5 and step by step, section 9) and each kind's required sections (section 7). read() returns what
it read or raises SpecError naming the rule a file breaks. spec_reader_test.py runs it over freshly baked files of
every kind and compares it with `microbake info` and `microbake validate`."""

import json
import re
import struct

from xxh3 import xxh3_64

MAGIC = b"\x89MBK\r\n\x1a\n"
READER_MAJOR, READER_MINOR = 1, 0
HEADER_SIZE = 64
ENTRY_SIZE_V1 = 128
MAX_SECTIONS = 65536
ALIGNMENT = 64

# SPEC section 5: code -> (name, bytes per element).
ELEMENT_TYPES = {1: ("u8", 1), 2: ("i8", 1), 3: ("u16", 2), 4: ("i16", 2), 5: ("u32", 4), 6: ("i32", 4),
                 7: ("u64", 8), 8: ("i64", 8), 9: ("f16", 2), 10: ("f32", 4), 11: ("f64", 8)}

# SPEC section 7: kind id -> name, and the sections every file of the kind holds with their allowed types.
KINDS = {1: "mip", 3: "rmq", 4: "sh", 5: "vmf", 6: "crease", 7: "colormap", 8: "moments", 9: "graph", 10: "lut",
         11: "histogram", 12: "neural_histogram"}
REQUIRED_SECTIONS = {
    "mip": {"level_0": ("f32",)},
    "lut": {"knots_n_x": ("f32",), "knots_n_y": ("f32",)},
    "rmq": {"table": ("u16", "u8"), "range": ("f64",)},
    "sh": {"normals": ("f32",), "window": ("f32",)},
    "vmf": {"level_0": ("f32",)},
    "colormap": {"knots": ("f32",), "colors": ("f32",), "table": ("f32",)},
    "moments": {"level_0": ("f32",)},
    "crease": {"normals": ("f32",), "distance": ("f32",), "side": ("i8",), "gradient": ("f32",),
               "crossing_h": ("f32",), "crossing_v": ("f32",), "segments": ("u16",)},
    "graph": {"stacks": ("f32",), "candidates": ("u32",), "transfer": ("f32",), "synthesis_pca_mean": ("f32",),
              "synthesis_pca_basis": ("f32",)},
    "histogram": {"theta_edges": ("f64",), "theta_centres": ("f64",), "phi_edges": ("f64",),
                  "bin_counts": ("u32",)},
    "neural_histogram": {"theta_edges": ("f64",), "theta_centres": ("f64",), "texel_bins": ("u16",),
                         "features": ("f16",), "mlp": ("f16",)},
}

SECTION_NAME = re.compile(r"[a-z][a-z0-9_.-]{0,30}\Z")


class SpecError(Exception):
    """A file breaking a rule of formats/SPEC.md; `rule` is a short stable name of the rule."""

    def __init__(self, rule, message):
        super().__init__(f"{rule}: {message}")
        self.rule = rule


def _strict_json(text):
    """SPEC section 3: RFC 8259 JSON in UTF-8, no byte-order mark, no repeated key within an object, no NaN or
    Infinity."""
    if text.startswith(b"\xef\xbb\xbf"):
        raise SpecError("metadata-not-json", "the metadata starts with a byte-order mark")
    try:
        decoded = text.decode("utf-8", errors="strict")
    except UnicodeDecodeError as e:
        raise SpecError("metadata-not-json", f"not UTF-8: {e}")

    def no_repeats(pairs):
        keys = [k for k, _ in pairs]
        if len(keys) != len(set(keys)):
            raise SpecError("metadata-duplicate-key", f"a key repeats in {sorted(keys)}")
        return dict(pairs)

    def no_constants(name):
        raise SpecError("metadata-not-json", f"{name} is not JSON")

    try:
        value = json.loads(decoded, object_pairs_hook=no_repeats, parse_constant=no_constants)
    except json.JSONDecodeError as e:
        raise SpecError("metadata-not-json", str(e))
    if not isinstance(value, dict):
        raise SpecError("metadata-not-json", "the metadata is not a JSON object")
    return value


def _check_metadata(meta, kind):
    for key in ("kind", "producer", "inputs", "parameters", "conventions", "statistics"):
        if key not in meta:
            raise SpecError("metadata-missing-key", key)
    producer = meta["producer"]
    if not (isinstance(producer, dict) and isinstance(producer.get("name"), str) and
            isinstance(producer.get("version"), str)):
        raise SpecError("metadata-wrong-type", "producer")
    if not isinstance(meta["inputs"], list):
        raise SpecError("metadata-wrong-type", "inputs")
    for key in ("parameters", "conventions", "statistics"):
        if not isinstance(meta[key], dict):
            raise SpecError("metadata-wrong-type", key)
    for record in meta["inputs"]:
        # Every input record (SPEC section 3): path, content_hash ("xxh3:" + 16 lowercase hex digits), bytes.
        if not (isinstance(record, dict) and isinstance(record.get("path"), str) and
                isinstance(record.get("bytes"), int) and
                re.fullmatch(r"xxh3:[0-9a-f]{16}", str(record.get("content_hash")))):
            raise SpecError("metadata-wrong-type", f"input record {record}")
    if meta["kind"] != kind:
        raise SpecError("kind-mismatch", f"header kind {kind}, metadata {meta['kind']!r}")


def _read_entry(data, at, index):
    raw_name = data[at:at + 32]
    name = raw_name.split(b"\0", 1)[0]
    if raw_name[len(name):].strip(b"\0") or not SECTION_NAME.match(name.decode("ascii", errors="replace")):
        raise SpecError("bad-section-name", f"entry {index}: {raw_name!r}")
    name = name.decode("ascii")
    type_code, rank = struct.unpack_from("<II", data, at + 32)
    dims = struct.unpack_from("<6Q", data, at + 40)
    offset, byte_length, checksum = struct.unpack_from("<QQQ", data, at + 88)
    if type_code not in ELEMENT_TYPES:
        raise SpecError("unknown-element-type", f"{name}: {type_code}")
    if not 1 <= rank <= 6:
        raise SpecError("bad-rank", f"{name}: {rank}")
    if any(dims[rank:]) or any(data[at + 112:at + 128]):
        raise SpecError("reserved-not-zero", name)
    count = 1
    for d in dims[:rank]:
        count *= d
    type_name, size = ELEMENT_TYPES[type_code]
    if count * size >= 1 << 64:
        raise SpecError("shape-overflow", name)
    if byte_length != count * size:
        raise SpecError("length-mismatch", f"{name}: {byte_length} bytes, shape needs {count * size}")
    return {"name": name, "type": type_name, "shape": list(dims[:rank]), "offset": offset, "bytes": byte_length,
            "checksum": checksum}


def _check_placement(sections, regions, file_size):
    """Bounds, alignment and overlap of the sections' data (SPEC sections 1 and 4)."""
    for s in sections:
        begin, end = s["offset"], s["offset"] + s["bytes"]
        if end > file_size:
            raise SpecError("section-out-of-bounds", s["name"])
        if begin % ALIGNMENT:
            raise SpecError("misaligned-section", f"{s['name']} at {begin}")
        for (b, e, what) in regions:
            # Non-empty ranges overlap when they share a byte; an empty section lies at a point, which may be the
            # start or the end of another region but not strictly inside one.
            inside = (b < end and begin < e) if begin < end else (b < begin < e)
            if inside:
                raise SpecError("sections-overlap", f"{s['name']} and {what}")
        regions.append((begin, end, f"section {s['name']}"))


def _check_gaps(data, regions):
    """Every byte outside the regions is a zero padding byte, and the file ends where the last region ends."""
    covered = 0
    for (b, e, _) in sorted(regions):
        if b > covered and any(data[covered:b]):
            raise SpecError("padding-not-zero", f"bytes {covered}..{b}")
        covered = max(covered, e)
    if covered != len(data):
        raise SpecError("trailing-bytes", f"the last region ends at {covered}, the file at {len(data)}")


def read(data):
    """Reads an .mbk file's bytes; returns a dict of what the header, metadata and section table say."""
    data = bytes(data)
    if data[:8] != MAGIC[:len(data[:8])]:
        if data.startswith(b"\x89MBK\n\x1a\n") or data.startswith(b"\x89MBK\r\r\n\x1a\r\n"):
            raise SpecError("text-mode-corruption", "line endings were converted")
        raise SpecError("bad-magic", repr(data[:8]))
    if len(data) < HEADER_SIZE:
        raise SpecError("file-too-small", f"{len(data)} bytes")
    (major, minor, kind_id, file_size, meta_offset, meta_size, table_offset, count, entry_size,
     header_checksum) = struct.unpack_from("<HHIQQQQIIQ", data, 8)
    if major > READER_MAJOR:
        raise SpecError("newer-major", f"file is format {major}.{minor}, this reader reads 1.0")
    if major == 0:
        raise SpecError("bad-major", "major 0")
    if file_size != len(data):
        raise SpecError("file-size-mismatch", f"header {file_size}, file {len(data)}")
    if meta_offset < HEADER_SIZE or meta_offset + meta_size > file_size:
        raise SpecError("metadata-out-of-bounds", f"[{meta_offset}, +{meta_size})")
    if entry_size < ENTRY_SIZE_V1:
        raise SpecError("section-entry-too-small", str(entry_size))
    if count > MAX_SECTIONS:
        raise SpecError("too-many-sections", str(count))
    table_size = count * entry_size
    if table_offset < HEADER_SIZE or table_offset + table_size > file_size:
        raise SpecError("section-table-out-of-bounds", f"[{table_offset}, +{table_size})")
    if meta_size and table_size and meta_offset < table_offset + table_size and table_offset < meta_offset + meta_size:
        raise SpecError("regions-overlap", "metadata and section table")
    metadata_bytes = data[meta_offset:meta_offset + meta_size]
    table_bytes = data[table_offset:table_offset + table_size]
    if xxh3_64(data[:56] + metadata_bytes + table_bytes) != header_checksum:
        raise SpecError("header-checksum-mismatch", "")
    metadata = _strict_json(metadata_bytes)
    if kind_id not in KINDS:
        raise SpecError("unknown-kind", str(kind_id))
    kind = KINDS[kind_id]
    _check_metadata(metadata, kind)

    sections = [_read_entry(data, table_offset + i * entry_size, i) for i in range(count)]
    names = [s["name"] for s in sections]
    if len(set(names)) != len(names):
        raise SpecError("duplicate-section", str(names))
    regions = [(0, HEADER_SIZE, "header"), (meta_offset, meta_offset + meta_size, "metadata"),
               (table_offset, table_offset + table_size, "section table")]
    _check_placement(sections, regions, file_size)
    _check_gaps(data, regions)
    for s in sections:
        if xxh3_64(data[s["offset"]:s["offset"] + s["bytes"]]) != s["checksum"]:
            raise SpecError("section-checksum-mismatch", s["name"])
    by_name = {s["name"]: s for s in sections}
    for name, types in REQUIRED_SECTIONS[kind].items():
        if name not in by_name:
            raise SpecError("missing-required-section", name)
        if by_name[name]["type"] not in types:
            raise SpecError("wrong-section-type", f"{name} is {by_name[name]['type']}")
    return {"format_version": f"{major}.{minor}", "kind_id": kind_id, "kind": kind, "file_size": file_size,
            "metadata": metadata, "sections": sections, "newer_minor": minor > READER_MINOR}
