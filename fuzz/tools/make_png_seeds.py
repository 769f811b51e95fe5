#!/usr/bin/env python3
"""Writes the PNG seeds of fuzz/corpus/png_read/ and the PNG-pair seeds of fuzz/corpus/image_diff/.

Every colour type and bit depth that PNG allows (grey 1/2/4/8/16, RGB 8/16, palette 1/2/4/8 with and
without tRNS, grey+alpha 8/16, RGBA 8/16), interlaced (Adam7) and not, all filter types, written with
zlib and struct only (PNG specification, ISO/IEC 15948, sections 5-11), so the seeds need no imaging
library. Small (at most 9 x 7 pixels) so that libFuzzer mutates headers and chunks, not pixel runs.
"""
import pathlib
import random
import struct
import zlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "fuzz" / "corpus"

CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}
# Adam7 passes: (x start, y start, x step, y step), PNG specification section 8.2.
ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def pack_row(samples, depth):
    if depth >= 8:
        return b"".join(s.to_bytes(depth // 8, "big") for s in samples)
    out, bits, accumulator = bytearray(), 0, 0
    for sample in samples:
        accumulator = (accumulator << depth) | sample
        bits += depth
        if bits == 8:
            out.append(accumulator)
            bits, accumulator = 0, 0
    if bits:
        out.append(accumulator << (8 - bits))
    return bytes(out)


def encode(width, height, colour_type, depth, interlace, rng, extra_chunks=b""):
    channels = CHANNELS[colour_type]
    limit = (1 << depth) - 1
    pixels = [[[rng.randint(0, limit) for _ in range(channels)] for _ in range(width)] for _ in range(height)]
    passes = ADAM7 if interlace else [(0, 0, 1, 1)]
    raw = bytearray()
    for x0, y0, dx, dy in passes:
        for y in range(y0, height, dy):
            row = [sample for x in range(x0, width, dx) for sample in pixels[y][x]]
            if row:
                raw.append(rng.randrange(5) if depth >= 8 else 0)  # filter type; 0 keeps low depths valid
                raw += filtered(pack_row(row, depth), raw[-1], max(1, channels * depth // 8))
    header = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 1 if interlace else 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + extra_chunks +
            chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def filtered(row, filter_type, bpp):
    # The filters are applied against an all-zero previous line (lossy for real images, but the decoder
    # only has to undo them, and any byte sequence is a valid filtered line).
    if filter_type == 0:
        return row
    out = bytearray(row)
    for i in range(len(row)):
        left = row[i - bpp] if i >= bpp else 0
        out[i] = (row[i] - (left if filter_type in (1, 4) else left // 2 if filter_type == 3 else 0)) & 0xFF
    return bytes(out)


def main():
    rng = random.Random(15948)
    seeds = {}
    for colour_type, depths in {0: [1, 2, 4, 8, 16], 2: [8, 16], 3: [1, 2, 4, 8], 4: [8, 16], 6: [8, 16]}.items():
        for depth in depths:
            for interlace in (False, True):
                extra = b""
                if colour_type == 3:
                    entries = 1 << depth
                    extra = chunk(b"PLTE", bytes(rng.randrange(256) for _ in range(3 * entries)))
                    if interlace:
                        extra += chunk(b"tRNS", bytes(rng.randrange(256) for _ in range(entries)))
                elif colour_type in (0, 2) and interlace:
                    extra = chunk(b"tRNS", bytes(2 * CHANNELS[colour_type]))
                name = f"type{colour_type}_depth{depth}{'_adam7' if interlace else ''}.png"
                seeds[name] = encode(rng.randint(1, 9), rng.randint(1, 7), colour_type, depth, interlace, rng, extra)
    seeds["gamma_and_text.png"] = encode(3, 3, 6, 8, False, rng, chunk(b"gAMA", struct.pack(">I", 45455)) +
                                         chunk(b"tEXt", b"Comment\x00fuzz seed"))
    directory = CORPUS / "png_read"
    directory.mkdir(parents=True, exist_ok=True)
    for name, data in seeds.items():
        (directory / name).write_bytes(data)

    # image_diff: mode byte 0 (two PNGs), diff options, the length of the first PNG, the two PNGs.
    names = sorted(seeds)
    pairs = [(names[i], names[(i * 7 + 3) % len(names)]) for i in range(0, len(names), 3)]
    pairs.append((names[0], names[0]))
    directory = CORPUS / "image_diff"
    for index, (first, second) in enumerate(pairs):
        options = bytes([index % 32, 100, 8, 2, 1, 30, 30, 10, 10])
        data = bytes([0]) + options + struct.pack("<I", len(seeds[first])) + seeds[first] + seeds[second]
        (directory / f"png_pair_{index:02d}").write_bytes(data)


if __name__ == "__main__":
    main()
