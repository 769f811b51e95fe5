#!/usr/bin/python3
"""Builds tests/fonts/CurvescanColourTest.ttf, the colour font of the colour-glyph tests, and
tests/fonts/CurvescanBrokenSvgTest.ttf, the same with a glyph document that is not SVG.

Run with Debian's python3-fonttools (/usr/bin/python3 tests/fonts/make_colour_test_font.py); the output is
committed, so the build does not need fontTools. Every outline is an axis-aligned rectangle on a 100-unit
grid of a 1000-unit em, so that at a font size of 100 px every edge falls on a pixel boundary and a test can
state the colour of every pixel from this file alone.

Glyphs (family "Curvescan Colour Test", advance 700 each):
  A  COLR version 0: three layers over the base outline (0,0)-(600,600), painted in this order:
       (0,0)-(600,600)     palette entry 0, opaque red
       (100,100)-(300,500) 0xFFFF, the foreground colour (the text's own fill)
       (200,200)-(500,400) palette entry 1, blue at alpha 128
  B  COLR version 1 (a PaintGlyph of a solid green); its plain outline is (0,0)-(600,600)
  C  an SVG-in-OpenType glyph (a green square); its plain outline is (0,0)-(600,600)
  D  a plain outline (0,0)-(600,600), no colour
  E  an SVG-in-OpenType glyph whose document draws beyond its outline and its line box: a green rectangle
     from (-200,-1000) to (900,300) in the document's units (y down: 1000 units above the baseline, 300
     below it, 200 left of the origin), over the plain outline (0,0)-(600,600); a canvas sized from the
     outline would crop it
"""
import os

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen
from fontTools.ttLib import newTable
from fontTools.ttLib.tables.S_V_G_ import SVGDocument


def rectangle(x0, y0, x1, y1):
    pen = TTGlyphPen(None)
    pen.moveTo((x0, y0))  # clockwise in y-up font units: the filled side on the right (TrueType)
    pen.lineTo((x0, y1))
    pen.lineTo((x1, y1))
    pen.lineTo((x1, y0))
    pen.closePath()
    return pen.glyph()


# Glyph E's document: ink beyond the glyph's outline on every side.
OVERSIZED_SVG = ('<svg xmlns="http://www.w3.org/2000/svg" id="glyph%d"><rect x="-200" y="-1000" width="1100" '
                 'height="1300" fill="green"/></svg>')


def build(family, svg_text, file_name):
    # E comes last, so that the other glyphs keep the indices they had before it was added.
    order = [".notdef", "A", "B", "C", "D", "layer.red", "layer.fg", "layer.blue", "E"]
    builder = FontBuilder(1000, isTTF=True)
    builder.setupGlyphOrder(order)
    builder.setupCharacterMap({ord(name): name for name in "ABCDE"})
    glyphs = {
        ".notdef": rectangle(0, 0, 500, 700),
        "A": rectangle(0, 0, 600, 600),
        "B": rectangle(0, 0, 600, 600),
        "C": rectangle(0, 0, 600, 600),
        "D": rectangle(0, 0, 600, 600),
        "layer.red": rectangle(0, 0, 600, 600),
        "layer.fg": rectangle(100, 100, 300, 500),
        "layer.blue": rectangle(200, 200, 500, 400),
        "E": rectangle(0, 0, 600, 600),
    }
    builder.setupGlyf(glyphs)
    # The left side bearing must be the outline's xMin: FreeType places a TrueType outline by it.
    for glyph in glyphs.values():
        glyph.recalcBounds(None)
    builder.setupHorizontalMetrics({name: (700, glyphs[name].xMin) for name in order})
    builder.setupHorizontalHeader(ascent=800, descent=-200)
    builder.setupNameTable({"familyName": family, "styleName": "Regular"})
    builder.setupOS2(sTypoAscender=800, sTypoDescender=-200, usWinAscent=800, usWinDescent=200)
    builder.setupPost()
    # CPAL colours are (red, green, blue, alpha) in 0..1.
    builder.setupCPAL([[(1.0, 0.0, 0.0, 1.0), (0.0, 0.0, 1.0, 128 / 255), (0.0, 0.5, 0.0, 1.0)]])
    builder.setupCOLR({
        "A": [("layer.red", 0), ("layer.fg", 0xFFFF), ("layer.blue", 1)],
        "B": {"Format": 10, "Paint": {"Format": 2, "PaletteIndex": 2, "Alpha": 1.0}, "Glyph": "layer.red"},
    })
    svg = newTable("SVG ")
    glyph_c = order.index("C")
    glyph_e = order.index("E")
    svg.docList = [SVGDocument(svg_text % glyph_c, glyph_c, glyph_c, False),
                   SVGDocument(OVERSIZED_SVG % glyph_e, glyph_e, glyph_e, False)]
    builder.font["SVG "] = svg
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), file_name)
    builder.save(out)


def main():
    build("Curvescan Colour Test",
          '<svg xmlns="http://www.w3.org/2000/svg" id="glyph%d"><rect width="600" height="600" y="-600" '
          'fill="green"/></svg>', "CurvescanColourTest.ttf")
    # The same font with a glyph document that is not SVG (a hostile or broken table): glyph C then falls
    # back to its plain outline.
    build("Curvescan Broken Svg Test", '<html id="glyph%d"><rect width="600" height="600"/></html>',
          "CurvescanBrokenSvgTest.ttf")


if __name__ == "__main__":
    main()
