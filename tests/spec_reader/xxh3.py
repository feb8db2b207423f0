"""XXH3-64 with seed 0 and the default secret, in pure Python: the one checksum of the .mbk format
(formats/SPEC.md: "XXH3-64, xxHash 0.8, XXH3_64bits, seed 0"), written from the xxHash specification for the
independent reader (mbk_reader.py), so that it shares no code with microbake. Slow (about 5 MB/s), which is
plenty for the small files the reader's test bakes."""

import struct

M64 = (1 << 64) - 1

PRIME32_1 = 0x9E3779B1
PRIME32_2 = 0x85EBCA77
PRIME32_3 = 0xC2B2AE3D
PRIME64_1 = 0x9E3779B185EBCA87
PRIME64_2 = 0xC2B2AE3D27D4EB4F
PRIME64_3 = 0x165667B19E3779F9
PRIME64_4 = 0x85EBCA77C2B2AE63
PRIME64_5 = 0x27D4EB2F165667C5
PRIME_MX1 = 0x165667919E3779F9
PRIME_MX2 = 0x9FB21C651E98DF25

# The 192-byte default secret of the specification.
SECRET = bytes.fromhex(
    "b8fe6c3923a44bbe7c01812cf721ad1cded46de9839097db7240a4a4b7b3671f"
    "cb79e64eccc0e578825ad07dccff7221b8084674f743248ee03590e6813a264c"
    "3c2852bb91c300cb88d0658b1b532ea371644897a20df94e3819ef46a9deacd8"
    "a8fa763fe39c343ff9dcbbc7c70b4f1d8a51e04bcdb45931c89f7ec9d9787364"
    "eac5ac8334d3ebc3c581a0fffa1363eb170ddd51b7f0da49d316552629d4689e"
    "2b16be587d47a1fc8ff8b8d17ad031ce45cb3a8f95160428afd7fbcabb4b407e")

STRIPE = 64
STRIPES_PER_BLOCK = (len(SECRET) - STRIPE) // 8  # 16
BLOCK = STRIPE * STRIPES_PER_BLOCK  # 1024 bytes


def _u32(b, i):
    return struct.unpack_from("<I", b, i)[0]


def _u64(b, i):
    return struct.unpack_from("<Q", b, i)[0]


def _rotl(x, r):
    return ((x << r) | (x >> (64 - r))) & M64


def _swap64(x):
    return int.from_bytes(x.to_bytes(8, "little"), "big")


def _fold(a, b):
    """The 128-bit product of a and b, its two halves xored."""
    p = a * b
    return (p ^ (p >> 64)) & M64


def _xxh64_avalanche(h):
    h ^= h >> 33
    h = (h * PRIME64_2) & M64
    h ^= h >> 29
    h = (h * PRIME64_3) & M64
    return h ^ (h >> 32)


def _avalanche(h):
    h ^= h >> 37
    h = (h * PRIME_MX1) & M64
    return h ^ (h >> 32)


def _rrmxmx(h, length):
    h ^= _rotl(h, 49) ^ _rotl(h, 24)
    h = (h * PRIME_MX2) & M64
    h ^= ((h >> 35) + length) & M64
    h = (h * PRIME_MX2) & M64
    return h ^ (h >> 28)


def _mix16(data, i, s):
    return _fold(_u64(data, i) ^ _u64(SECRET, s), _u64(data, i + 8) ^ _u64(SECRET, s + 8))


def _short(data):
    n = len(data)
    if n == 0:
        return _xxh64_avalanche(_u64(SECRET, 56) ^ _u64(SECRET, 64))
    if n <= 3:
        combined = (data[0] << 16) | (data[n >> 1] << 24) | data[n - 1] | (n << 8)
        return _xxh64_avalanche(combined ^ (_u32(SECRET, 0) ^ _u32(SECRET, 4)))
    if n <= 8:
        keyed = (_u32(data, n - 4) + (_u32(data, 0) << 32)) ^ (_u64(SECRET, 8) ^ _u64(SECRET, 16))
        return _rrmxmx(keyed, n)
    lo = _u64(data, 0) ^ (_u64(SECRET, 24) ^ _u64(SECRET, 32))
    hi = _u64(data, n - 8) ^ (_u64(SECRET, 40) ^ _u64(SECRET, 48))
    return _avalanche((n + _swap64(lo) + hi + _fold(lo, hi)) & M64)


def _medium(data):
    n = len(data)
    acc = (n * PRIME64_1) & M64
    if n <= 128:
        # Pairs of 16-byte blocks from both ends, as many as the length needs.
        pairs = 1 + (n > 32) + (n > 64) + (n > 96)
        for k in range(pairs):
            acc += _mix16(data, 16 * k, 32 * k) + _mix16(data, n - 16 * (k + 1), 32 * k + 16)
        return _avalanche(acc & M64)
    for k in range(8):
        acc += _mix16(data, 16 * k, 16 * k)
    acc = _avalanche(acc & M64)
    for k in range(8, n // 16):
        acc += _mix16(data, 16 * k, 16 * (k - 8) + 3)
    acc += _mix16(data, n - 16, 136 - 17)
    return _avalanche(acc & M64)


def _accumulate_stripe(acc, data, i, s):
    lanes = struct.unpack_from("<8Q", data, i)
    keys = struct.unpack_from("<8Q", SECRET, s)
    for k in range(8):
        v = lanes[k]
        key = v ^ keys[k]
        acc[k ^ 1] = (acc[k ^ 1] + v) & M64
        acc[k] = (acc[k] + (key & 0xFFFFFFFF) * (key >> 32)) & M64


def _scramble(acc):
    keys = struct.unpack_from("<8Q", SECRET, len(SECRET) - STRIPE)
    for k in range(8):
        a = acc[k]
        a ^= a >> 47
        a ^= keys[k]
        acc[k] = (a * PRIME32_1) & M64


def _long(data):
    n = len(data)
    acc = [PRIME32_3, PRIME64_1, PRIME64_2, PRIME64_3, PRIME64_4, PRIME32_2, PRIME64_5, PRIME32_1]
    blocks = (n - 1) // BLOCK
    for b in range(blocks):
        for s in range(STRIPES_PER_BLOCK):
            _accumulate_stripe(acc, data, b * BLOCK + s * STRIPE, 8 * s)
        _scramble(acc)
    tail_stripes = ((n - 1) - blocks * BLOCK) // STRIPE
    for s in range(tail_stripes):
        _accumulate_stripe(acc, data, blocks * BLOCK + s * STRIPE, 8 * s)
    _accumulate_stripe(acc, data, n - STRIPE, len(SECRET) - STRIPE - 7)
    result = (n * PRIME64_1) & M64
    for k in range(4):
        result += _fold(acc[2 * k] ^ _u64(SECRET, 11 + 16 * k), acc[2 * k + 1] ^ _u64(SECRET, 11 + 16 * k + 8))
    return _avalanche(result & M64)


def xxh3_64(data):
    """XXH3-64 (seed 0) of a bytes-like object, as an int."""
    data = bytes(data)
    if len(data) <= 16:
        return _short(data)
    if len(data) <= 240:
        return _medium(data)
    return _long(data)
