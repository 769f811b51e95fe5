#!/usr/bin/python3
"""Builds tests/fonts/CurvescanSbixTest.ttf and tests/fonts/CurvescanCbdtTest.ttf, the bitmap colour fonts of
the bitmap colour-glyph tests.

Run with Debian's python3-fonttools (/usr/bin/python3 tests/fonts/make_bitmap_test_fonts.py); the output is
committed, so the build does not need fontTools. The PNG images are written here with zlib alone.

Both fonts have a 1000-unit em, ascent 800, descent -200, and glyph "A" (advance 700) whose image is four
opaque quadrants, top-left red, top-right green, bottom-left blue, bottom-right half-transparent white
(alpha 128), with a 2-pixel transparent border on every side:

  Curvescan Sbix Test  "sbix" strikes at 20 and 50 pixels per em (12 x 12 and 30 x 30 images: the box
                       (0,0)-(600,600) in font units), glyph outlines (0,0)-(600,600) in "glyf"; glyph "B"
                       has the same images placed 5 strike pixels right and 5 down (originOffsetX 5,
                       originOffsetY -5). FreeType reads an sbix face as not scalable.
  Curvescan Cbdt Test  "CBDT"/"CBLC" strike at 50 pixels per em (30 x 30 image of "A", bearing (0, 30)), no
                       outlines at all (a bitmap-only face); "B" has no image.
"""
import os
import struct
import zlib

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import newTable
from fontTools.ttLib.tables import sbixGlyph, sbixStrike

HERE = os.path.dirname(os.path.abspath(__file__))


def png(width, height, pixel):
    """An RGBA PNG, pixel(x, y) -> (r, g, b, a) straight alpha."""
    raw = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(width)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def quadrants(size):
    def pixel(x, y):
        if x < 2 or y < 2 or x >= size - 2 or y >= size - 2:
            return (0, 0, 0, 0)
        left, top = x < size // 2, y < size // 2
        if top:
            return (255, 0, 0, 255) if left else (0, 255, 0, 255)
        return (0, 0, 255, 255) if left else (255, 255, 255, 128)
    return png(size, size, pixel)


def rectangle(x0, y0, x1, y1):
    pen = TTGlyphPen(None)
    pen.moveTo((x0, y0))
    pen.lineTo((x0, y1))
    pen.lineTo((x1, y1))
    pen.lineTo((x1, y0))
    pen.closePath()
    return pen.glyph()


def common(builder, family, glyphs):
    order = [".notdef", "A", "B"]
    builder.setupGlyphOrder(order)
    builder.setupCharacterMap({ord("A"): "A", ord("B"): "B"})
    builder.setupGlyf(glyphs)
    for glyph in glyphs.values():
        glyph.recalcBounds(None)
    builder.setupHorizontalMetrics({name: (700, getattr(glyphs[name], "xMin", 0)) for name in order})
    builder.setupHorizontalHeader(ascent=800, descent=-200)
    builder.setupNameTable({"familyName": family, "styleName": "Regular"})
    builder.setupOS2(sTypoAscender=800, sTypoDescender=-200, usWinAscent=800, usWinDescent=200)
    builder.setupPost()


def sbix_font():
    builder = FontBuilder(1000, isTTF=True)
    glyphs = {".notdef": rectangle(0, 0, 500, 700), "A": rectangle(0, 0, 600, 600), "B": rectangle(0, 0, 600, 600)}
    common(builder, "Curvescan Sbix Test", glyphs)
    sbix = newTable("sbix")
    sbix.version, sbix.flags = 1, 1
    for ppem, size in ((20, 12), (50, 30)):
        strike = sbixStrike.Strike(ppem=ppem, resolution=72)
        image = quadrants(size)
        strike.glyphs["A"] = sbixGlyph.Glyph(glyphName="A", graphicType="png ", imageData=image)
        strike.glyphs["B"] = sbixGlyph.Glyph(glyphName="B", graphicType="png ", imageData=image,
                                             originOffsetX=5, originOffsetY=-5)
        sbix.strikes[ppem] = strike
    builder.font["sbix"] = sbix
    builder.save(os.path.join(HERE, "CurvescanSbixTest.ttf"))


def cbdt_font():
    from fontTools.ttLib.tables import E_B_L_C_, C_B_D_T_
    from fontTools.ttLib.tables.BitmapGlyphMetrics import SmallGlyphMetrics
    from fontTools.ttLib.tables.E_B_L_C_ import SbitLineMetrics
    builder = FontBuilder(1000, isTTF=True)
    empty = TTGlyphPen(None).glyph()
    glyphs = {".notdef": empty, "A": TTGlyphPen(None).glyph(), "B": TTGlyphPen(None).glyph()}
    common(builder, "Curvescan Cbdt Test", glyphs)
    del builder.font["glyf"], builder.font["loca"]
    builder.font["maxp"].tableVersion = 0x00005000
    image = quadrants(30)
    cbdt = newTable("CBDT")
    cbdt.version = 3.0
    glyph = C_B_D_T_.cbdt_bitmap_classes[17](data=b"", ttFont=builder.font)
    metrics = SmallGlyphMetrics()
    metrics.height, metrics.width, metrics.BearingX, metrics.BearingY, metrics.Advance = 30, 30, 0, 30, 35
    glyph.metrics = metrics
    glyph.imageData = image
    cbdt.strikeData = [{"A": glyph}]
    cblc = newTable("CBLC")
    cblc.version = 3.0
    strike = E_B_L_C_.Strike()
    line = SbitLineMetrics()
    for name, value in (("ascender", 40), ("descender", -10), ("widthMax", 35), ("caretSlopeNumerator", 0),
                        ("caretSlopeDenominator", 0), ("caretOffset", 0), ("minOriginSB", 0),
                        ("minAdvanceSB", 0), ("maxBeforeBL", 30), ("minAfterBL", 0), ("pad1", 0), ("pad2", 0)):
        setattr(line, name, value)
    strike.bitmapSizeTable.hori = line
    vert = SbitLineMetrics()
    for name in ("ascender", "descender", "widthMax", "caretSlopeNumerator", "caretSlopeDenominator",
                 "caretOffset", "minOriginSB", "minAdvanceSB", "maxBeforeBL", "minAfterBL", "pad1", "pad2"):
        setattr(vert, name, getattr(line, name))
    strike.bitmapSizeTable.vert = vert
    for name, value in (("colorRef", 0), ("startGlyphIndex", 1), ("endGlyphIndex", 1), ("ppemX", 50),
                        ("ppemY", 50), ("bitDepth", 32), ("flags", 1)):
        setattr(strike.bitmapSizeTable, name, value)
    index = E_B_L_C_.eblc_sub_table_classes[1](data=b"", ttFont=builder.font)
    index.indexFormat, index.imageFormat = 1, 17
    index.names = ["A"]
    index.firstGlyphIndex, index.lastGlyphIndex = 1, 1
    strike.indexSubTables = [index]
    cblc.strikes = [strike]
    builder.font["CBDT"] = cbdt
    builder.font["CBLC"] = cblc
    builder.save(os.path.join(HERE, "CurvescanCbdtTest.ttf"))


if __name__ == "__main__":
    sbix_font()
    cbdt_font()
