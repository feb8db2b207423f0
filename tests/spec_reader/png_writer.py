"""A minimal PNG encoder (greyscale, RGB or RGBA; 8 or 16 bits; no filtering) for the spec reader's test, so that
it can give microbake integer images whose codes it knows."""

import struct
import zlib


def _chunk(tag, body):
    return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)


def write_png(path, width, height, channels, bits, rows):
    """rows: `height` lists of width * channels integer codes, row 0 at the top."""
    color_type = {1: 0, 3: 2, 4: 6}[channels]
    sample = ">" + ("B" if bits == 8 else "H") * (width * channels)
    raw = b"".join(b"\0" + struct.pack(sample, *row) for row in rows)  # filter type 0 (none) per row
    header = struct.pack(">IIBBBBB", width, height, bits, color_type, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(raw)) +
                _chunk(b"IEND", b""))
