#!/usr/bin/env python3
"""Writes small TrueType fonts into fuzz/corpus/font/ (the system fonts are ~700 KB, too big to mutate
usefully and to commit as seeds).

Each font has the tables FreeType and HarfBuzz read (OpenType specification: head, hhea, maxp, OS/2,
hmtx, cmap format 4, loca, glyf, name, post) and a few glyphs: .notdef, a square (on-curve points only),
a shape with off-curve points (quadratics, implied on-curve midpoints included), an empty glyph and a
composite glyph that places two others with an offset and a scale. Variants differ in the loca format and
the units per em. Written with struct only. The colour-glyph test fonts of tests/fonts are copied in too.
"""
import pathlib
import struct

ROOT = pathlib.Path(__file__).resolve().parents[2]
DIRECTORY = ROOT / "fuzz" / "corpus" / "font"


def simple_glyph(contours):
    """contours: lists of (x, y, on_curve)."""
    points = [p for contour in contours for p in contour]
    if not points:
        return b""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    out = struct.pack(">hhhhh", len(contours), min(xs), min(ys), max(xs), max(ys))
    end = -1
    for contour in contours:
        end += len(contour)
        out += struct.pack(">H", end)
    out += struct.pack(">H", 0)  # no instructions
    out += bytes(1 if p[2] else 0 for p in points)  # flags: coordinates as 16-bit deltas
    previous = 0
    for x in xs:
        out += struct.pack(">h", x - previous)
        previous = x
    previous = 0
    for y in ys:
        out += struct.pack(">h", y - previous)
        previous = y
    return out


def composite_glyph(parts):
    """parts: (glyph index, dx, dy, scale or None)."""
    out = struct.pack(">hhhhh", -1, 0, 0, 1000, 1000)
    for index, (glyph, dx, dy, scale) in enumerate(parts):
        flags = 0x0001 | 0x0002  # ARG_1_AND_2_ARE_WORDS, ARGS_ARE_XY_VALUES
        if scale is not None:
            flags |= 0x0008  # WE_HAVE_A_SCALE
        if index + 1 < len(parts):
            flags |= 0x0020  # MORE_COMPONENTS
        out += struct.pack(">HHhh", flags, glyph, dx, dy)
        if scale is not None:
            out += struct.pack(">h", int(scale * 16384))  # F2Dot14
    return out


def cmap_format4(mapping):
    segments = [(code, code, glyph) for code, glyph in sorted(mapping.items())] + [(0xFFFF, 0xFFFF, 0)]
    count = len(segments)
    subtable = struct.pack(">HHHHHHH", 4, 16 + 8 * count, 0, 2 * count, 2, 0, 2 * count - 2)
    subtable += b"".join(struct.pack(">H", end) for _, end, _ in segments) + b"\x00\x00"
    subtable += b"".join(struct.pack(">H", start) for start, _, _ in segments)
    subtable += b"".join(struct.pack(">h", (glyph - start) if glyph else 1) for start, _, glyph in segments)
    subtable += b"".join(struct.pack(">H", 0) for _ in segments)
    return struct.pack(">HHHHI", 0, 1, 3, 1, 12) + subtable


def name_table(family):
    strings = [(1, family), (2, "Regular"), (4, family + " Regular"), (6, family.replace(" ", ""))]
    records, storage = b"", b""
    for name_id, text in strings:
        encoded = text.encode("utf-16-be")
        records += struct.pack(">HHHHHH", 3, 1, 0x409, name_id, len(encoded), len(storage))
        storage += encoded
    return struct.pack(">HHH", 0, len(strings), 6 + 12 * len(strings)) + records + storage


def font(units_per_em, long_loca, family):
    glyphs = [
        simple_glyph([[(50, 0, 1), (450, 0, 1), (450, 700, 1), (50, 700, 1)],
                      [(100, 50, 1), (100, 650, 1), (400, 650, 1), (400, 50, 1)]]),  # .notdef: a box
        simple_glyph([[(0, 0, 1), (500, 0, 1), (500, 500, 1), (0, 500, 1)]]),      # 'A': a square
        simple_glyph([[(0, 0, 1), (250, 600, 0), (500, 0, 1), (400, -100, 0), (100, -100, 0)]]),  # 'B'
        b"",                                                                          # ' ': empty
        composite_glyph([(1, 0, 0, None), (2, 300, 100, 0.5)]),                       # 'C': composite
    ]
    glyf, offsets = b"", []
    for glyph in glyphs:
        offsets.append(len(glyf))
        glyf += glyph + b"\x00" * (len(glyph) % 2)
    offsets.append(len(glyf))
    loca = b"".join(struct.pack(">I", o) if long_loca else struct.pack(">H", o // 2) for o in offsets)
    count = len(glyphs)
    tables = {
        b"cmap": cmap_format4({0x41: 1, 0x42: 2, 0x20: 3, 0x43: 4}),
        b"glyf": glyf,
        b"head": struct.pack(">IIIIHHqqhhhhHHhhh", 0x00010000, 0x00010000, 0, 0x5F0F3CF5, 0x000B, units_per_em,
                             0, 0, -100, -100, 500, 700, 0, 8, 2, 1 if long_loca else 0, 0),
        b"hhea": struct.pack(">IhhhHhhhhhhhhhhhH", 0x00010000, 800, -200, 90, 600, 0, 0, 500, 1, 0, 0, 0, 0, 0, 0,
                             0, count),
        b"hmtx": b"".join(struct.pack(">Hh", 550, 0) for _ in range(count)),
        b"loca": loca,
        b"maxp": struct.pack(">IHHHHHHHHHHHHHH", 0x00010000, count, 10, 2, 10, 2, 2, 0, 0, 0, 0, 0, 0, 2, 1),
        b"name": name_table(family),
        b"OS/2": struct.pack(">HhHHHhhhhhhhhhhh", 1, 500, 400, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0) +
                 bytes(10) + bytes(16) + b"NONE" + struct.pack(">HHHhhhHHII", 0x40, 0x20, 0x43, 800, -200, 90,
                                                               800, 200, 1, 0),
        b"post": struct.pack(">IIhhIIIII", 0x00030000, 0, -100, 50, 0, 0, 0, 0, 0),
    }
    tags = sorted(tables)
    offset = 12 + 16 * len(tags)
    directory, body = struct.pack(">IHHHH", 0x00010000, len(tags), 64, 2, len(tags) * 16 - 64), b""
    for tag in tags:
        data = tables[tag]
        checksum = sum(struct.unpack(">%dI" % ((len(data) + 3) // 4), data + b"\x00" * (-len(data) % 4))) & 0xFFFFFFFF
        directory += struct.pack(">4sIII", tag, checksum, offset + len(body), len(data))
        body += data + b"\x00" * (-len(data) % 4)
    return directory + body


# The colour-glyph test fonts (COLR/CPAL and SVG; sbix; CBDT/CBLC; an SVG table with a broken document),
# made by tests/fonts/make_colour_test_font.py and make_bitmap_test_fonts.py: copied as seeds of the
# colour-glyph readers.
COLOUR_TEST_FONTS = ["CurvescanColourTest.ttf", "CurvescanSbixTest.ttf", "CurvescanCbdtTest.ttf",
                     "CurvescanBrokenSvgTest.ttf"]


def main():
    DIRECTORY.mkdir(parents=True, exist_ok=True)
    for name in COLOUR_TEST_FONTS:
        (DIRECTORY / ("colour_" + name)).write_bytes((ROOT / "tests" / "fonts" / name).read_bytes())
    (DIRECTORY / "tiny_short_loca.ttf").write_bytes(font(1000, False, "Fuzz Seed"))
    (DIRECTORY / "tiny_long_loca.ttf").write_bytes(font(2048, True, "Fuzz Seed Long"))
    (DIRECTORY / "tiny_upem16.ttf").write_bytes(font(16, False, "Fuzz Seed Small"))


if __name__ == "__main__":
    main()
