"""An independent .mbk writer, from formats/SPEC.md alone (the layout of section 1, the header of section 2, the
canonical metadata of section 3), and the files the spec reader's test makes with it: microbake's file written
again (which must come out byte for byte), and one file per container rule that a reader had to guess before the
spec fixed it, each with the reader rule and the `validate` finding id it must give (None: valid)."""

import json
import struct

import mbk_reader
from mbk_reader import ALIGNMENT, ELEMENT_TYPES, ENTRY_SIZE_V1, HEADER_SIZE, MAGIC
from xxh3 import xxh3_64

TYPE_CODES = {name: code for code, (name, _) in ELEMENT_TYPES.items()}


def align(n):
    return (n + ALIGNMENT - 1) // ALIGNMENT * ALIGNMENT


def canonical_metadata(metadata):
    """SPEC section 3: compact, keys sorted, UTF-8."""
    return json.dumps(metadata, sort_keys=True, separators=(",", ":"), ensure_ascii=False).encode("utf-8")


def write(kind_id, metadata_text, sections, offsets=None, file_size=None):
    """sections: dicts with name, type, shape and data (bytes). offsets: name -> offset to place a section
    elsewhere than the v1.0 writers' order; file_size: the size to record and pad to (default: where the last
    region ends)."""
    offsets = dict(offsets or {})
    table_offset = align(HEADER_SIZE + len(metadata_text))
    cursor = align(table_offset + ENTRY_SIZE_V1 * len(sections))
    for s in sections:
        offsets.setdefault(s["name"], cursor)
        cursor = align(offsets[s["name"]] + len(s["data"]))
    end = max([table_offset + ENTRY_SIZE_V1 * len(sections)] + [offsets[s["name"]] + len(s["data"])
                                                                  for s in sections])
    size = end if file_size is None else file_size
    out = bytearray(size)
    out[HEADER_SIZE:HEADER_SIZE + len(metadata_text)] = metadata_text
    for i, s in enumerate(sections):
        at = table_offset + i * ENTRY_SIZE_V1
        out[at:at + len(s["name"])] = s["name"].encode("ascii")
        shape = list(s["shape"]) + [0] * (6 - len(s["shape"]))
        struct.pack_into("<II6QQQQ", out, at + 32, TYPE_CODES[s["type"]], len(s["shape"]), *shape,
                         offsets[s["name"]], len(s["data"]), xxh3_64(s["data"]))
        out[offsets[s["name"]]:offsets[s["name"]] + len(s["data"])] = s["data"]
    struct.pack_into("<8sHHIQQQQII", out, 0, MAGIC, 1, 0, kind_id, size, HEADER_SIZE, len(metadata_text),
                     table_offset, len(sections), ENTRY_SIZE_V1)
    table = bytes(out[table_offset:table_offset + ENTRY_SIZE_V1 * len(sections)])
    struct.pack_into("<Q", out, 56, xxh3_64(bytes(out[:56]) + metadata_text + table))
    return bytes(out)


def rule_cases(read, data):
    """`read`: what mbk_reader.read() returned for a valid mip file, `data` its bytes. Returns (name, bytes,
    reader rule or None, validate error id or None)."""
    meta = canonical_metadata(read["metadata"])
    sections = [dict(s, data=data[s["offset"]:s["offset"] + s["bytes"]]) for s in read["sections"]]
    empty = {"name": "empty", "type": "f32", "shape": [0], "data": b""}
    kind = read["kind_id"]
    as_written = write(kind, meta, sections)
    empty_last = write(kind, meta, sections + [empty])
    level0 = mbk_reader.read(empty_last)["sections"][0]  # where the first section moved with the longer table
    return [
        ("rewritten", as_written, None, None),
        # SPEC section 1: the file ends where its last region ends.
        ("trailing_zero_bytes", write(kind, meta, sections, file_size=len(as_written) + 64), "trailing-bytes",
         1007),
        # SPEC section 4: an empty section lies at a multiple of 64 that is no other region's interior.
        ("empty_section_last", empty_last, None, None),
        ("empty_section_at_a_section_start", write(kind, meta, sections + [empty],
                                                   offsets={"empty": level0["offset"]}), None, None),
        ("empty_section_inside_a_section", write(kind, meta, sections + [empty],
                                                 offsets={"empty": level0["offset"] + ALIGNMENT}),
         "sections-overlap", 3009),
        # SPEC section 3: strict JSON, no byte-order mark, no key twice in one object (at any depth).
        ("metadata_duplicate_key", write(kind, b'{"kind":"mip",' + meta[1:], sections), "metadata-duplicate-key",
         2015),
        ("metadata_nested_duplicate_key",
         write(kind, meta.replace(b'"parameters":{', b'"parameters":{"levels":0,', 1), sections),
         "metadata-duplicate-key", 2015),
        ("metadata_byte_order_mark", write(kind, b"\xef\xbb\xbf" + meta, sections), "metadata-not-json", 2009),
    ]
