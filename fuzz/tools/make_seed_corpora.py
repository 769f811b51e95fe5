#!/usr/bin/env python3
"""Writes the seed corpora of the text and structured fuzz targets into fuzz/corpus/ (docs/fuzzing.md).

Deterministic: running it again rewrites the same files. Seeds come from the project's own inputs (the SVG
corpus documents and their attribute values, the curve-spec examples) plus hand-written edge cases, and
for the byte-decoded targets (raster_stroke, image_diff) from a seeded generator. The PNG and font seeds
are made by make_png_seeds.py and make_font_seeds.py.
"""
import hashlib
import pathlib
import random
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "fuzz" / "corpus"


def write(target, name, data):
    directory = CORPUS / target
    directory.mkdir(parents=True, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    (directory / name).write_bytes(data)


def svg_documents():
    documents = sorted((ROOT / "tests" / "svg_corpus" / "documents").glob("*.svg"))
    for path in documents:
        if path.stat().st_size <= 8192:
            write("svg_document", path.name, path.read_bytes())
    return documents


def svg_attribute_values(documents):
    values = set()
    pattern = re.compile(r'\b(d|transform|style|viewBox|preserveAspectRatio|points|fill|stroke|width)="([^"]*)"')
    for path in documents:
        for _, value in pattern.findall(path.read_text(errors="replace")):
            if value:
                values.add(value)
    values.update([
        "M0 0L10 10", "M1.5.5l-2-3e2z", "m10 10 h5v5h-5z", "M0 0C1 2 3 4 5 6S7 8 9 10",
        "M0 0Q1 1 2 0T4 0", "M5 5a3 2 30 1 0 6 6", "M0 0a1 1 0 00 1 1", "M1e308 0l1e308 0",
        "M0 0L1e-320 1e-320", "M 0,0 L 16,16 M 16,0 L 0,16 Z", "rotate(45 16 16) scale(2,-1)",
        "matrix(1 0 0 1 1e300 0)", "#fff", "rgb(10%, 20%, 30%)", "hsla(120, 50%, 50%, .5)",
        "12.5mm", "3em", "-1e400", "0 0 100 50", "xMinYMax slice", "fill:red;stroke-width:2",
    ])
    for value in sorted(values):  # named by content, so that new documents add files and rename none
        write("svg_path_data", "value_" + hashlib.sha1(value.encode()).hexdigest()[:12], value)


def curve_specs():
    specs = {
        "bezier_cubic": '{"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]}',
        "bezier_degree7": '{"type": "bezier", "points": [[0,0],[1,5],[2,-5],[3,5],[4,-5],[5,5],[6,-5],[7,0]]}',
        "rational_conic": '{"type": "rational", "points": [[1,0],[1,1],[0,1]], "weights": [1,0.7071067811865476,1]}',
        "bspline_default": '{"type": "bspline", "degree": 3, "points": [[0,0],[1,2],[2,0],[3,2],[4,0]]}',
        "bspline_closed": '{"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0],[1,-1]], "closed": true}',
        "bspline_knots": '{"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0],[3,1]], "knots": [0,0,0,0.5,1,1,1]}',
        "nurbs_circle": '{"type": "nurbs", "degree": 2, "points": [[1,0],[1,1],[0,1],[-1,1],[-1,0],[-1,-1],[0,-1],[1,-1],[1,0]], '
                        '"weights": [1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1,0.7071067811865476,1], '
                        '"knots": [0,0,0,0.25,0.25,0.5,0.5,0.75,0.75,1,1,1]}',
        "hermite": '{"type": "hermite", "points": [[0,0],[1,1],[2,0]], "tangents": [[1,0],[1,0],[1,-1]], "parameters": [0,1,3]}',
        "catmull_rom": '{"type": "catmull-rom", "points": [[0,0],[1,1],[2,0],[3,1]], "alpha": 0.5}',
        "catmull_rom_closed": '{"type": "catmull-rom", "points": [[0,0],[1,1],[2,0]], "alpha": 1, "closed": true}',
        "interpolate_natural": '{"type": "interpolate", "points": [[0,0],[1,1],[2,0],[3,1]], "parameterization": "uniform"}',
        "interpolate_clamped": '{"type": "interpolate", "points": [[0,0],[1,1],[2,0]], "ends": "clamped", '
                               '"start_tangent": [1,0], "end_tangent": [0,1]}',
        "interpolate_closed": '{"type": "interpolate", "points": [[0,0],[1,1],[2,0],[1,-1]], "closed": true}',
        "repeated_points": '{"type": "bspline", "degree": 3, "points": [[1,1],[1,1],[1,1],[1,1],[1,1]]}',
        "huge_coordinates": '{"type": "bezier", "points": [[-1e308,0],[1e308,1e308],[0,-1e308]]}',
        "tiny_weights": '{"type": "rational", "points": [[0,0],[1,1],[2,0]], "weights": [1e-300,1,1e300]}',
        "explicit_tan": '{"type": "explicit", "f": "tan(x)", "x": [-3, 3], "y": [-10, 10]}',
        "implicit_lemniscate": '{"type": "implicit", "f": "(x^2+y^2)^2 - 2*(x^2-y^2)", "box": [[-2,-1],[2,1.1]]}',
        "bezier_patch": '{"type": "bezier-patch", "patches": [[[0,0,0],[1,0,0],[2,0,0],[3,0,0],[0,1,0],[1,1,1],'
                        '[2,1,1],[3,1,0],[0,2,0],[1,2,1],[2,2,1],[3,2,0],[0,3,0],[1,3,0],[2,3,0],[3,3,0]]], '
                        '"view": {"eye": [-5,-6,4], "target": [1.5,1.5,0], "focal": 300}, "iso": [3, 3]}',
    }
    for name, text in specs.items():
        write("curve_spec", name + ".json", text + "\n")


EXPRESSION_SEEDS = {
    "sine": "sin(x)",
    "circle": "x^2 + y^2 - 1",
    "lemniscate": "(x^2 + y^2)^2 - 2*(x^2 - y^2)",
    "poles_and_domains": "tan(x) + 1/x - log(y) * sqrt(-x)",
    "every_kind": "atan2(y, x) - min(abs(x), max(y, t)) + pow(x, 0.5) - 2^-3^2",
    "overflow": "exp(exp(exp(x))) - asin(x*1e308) / acos(y)",
    "nested": "((((((x))))))",
    "unclosed": "sin(x",
}


def expression_seeds():
    for name, text in EXPRESSION_SEEDS.items():
        write("expression", name, text)


def raster_stroke_seeds():
    # Hand-made scenes (the layout is in fuzz/targets/raster_stroke.cpp) and seeded random bytes.
    write("raster_stroke", "square_stroked", bytes([0, 0, 1, 140, 0, 0, 100, 0]) +
          bytes([0, 1, 90, 90, 1, 1, 130, 90, 1, 1, 130, 130, 1, 1, 90, 130, 5]))
    write("raster_stroke", "cubic_dashed_round", bytes([0, 0, 0, 120, 2, 2, 110, 2, 120, 60, 0]) +
          bytes([0, 1, 60, 60, 3, 1, 100, 20, 1, 140, 20, 1, 180, 180]))
    write("raster_stroke", "zero_length_round_cap", bytes([0, 0, 1, 160, 2, 1, 110, 0]) +
          bytes([0, 1, 100, 100, 1, 0, 1, 0]))
    write("raster_stroke", "nan_width", bytes([4, 0, 1, 200, 0, 0, 110, 0, 0, 1, 90, 90, 1, 1, 130, 130]))
    # Scaled by 25.75 (a scale of 1e7 made a pending finding: fuzz/pending/README.md).
    write("raster_stroke", "scaled_arc", bytes([0, 1, 199, 199, 1, 140, 1, 0, 100, 0]) +
          bytes([6, 1, 100, 100, 120, 120, 100, 100, 180]))
    rng = random.Random(8)
    for index in range(12):
        write("raster_stroke", f"random_{index:02d}", bytes(rng.randrange(256) for _ in range(rng.randrange(16, 200))))


def image_diff_seeds():
    rng = random.Random(88)
    for index in range(8):
        mode = 1 | (2 if index % 2 else 0)
        options = bytes([index * 7 % 32, 100, 8, 3, rng.randrange(4)]) + bytes(rng.randrange(256) for _ in range(16))
        pixels = bytes(rng.randrange(256) for _ in range(rng.randrange(8, 600)))
        write("image_diff", f"raw_{index:02d}", bytes([mode]) + options + pixels)


CSS_SEEDS = {
    "illustrator": ".cls-1{fill:#e6332a;}.cls-2{fill:#1d71b8;stroke:#000;stroke-width:2px}\n",
    "selectors": "svg > g#g1 rect:first-child, .a.b ~ line, circle + g path:nth-child(2n+1) "
                 "{ fill: green } :not(.a, #r1):last-child { stroke: red } :root :empty { opacity: .5 }",
    "attributes": "[lang|=en] [data-x~=two] { fill: blue } [class^='cls'] { stroke: #0f0 } "
                  "[id$=\"1\" i], [data-x*=ne] { fill: url(#grad) red }",
    "important": "#r1 { fill: green !important } #r1 { fill: red } g { fill: inherit ! IMPORTANT }",
    "at_rules": "@charset \"utf-8\"; @import url(x.css); @media screen { rect { fill: red } } "
                "@font-face { font-family: x; src: url(x.ttf) } .s0 { stop-color: #ff0 } .s1 { stop-opacity: 50% }",
    "unsupported": "a:hover, p::before { fill: red } svg|rect { } rect:nth-of-type(2) { } .a { fill: green }",
    "malformed": "<!-- .a { fill: red; } --> .b { fill: 'unterminated\n } } { ; .c { fill: url(a b) } "
                 ".d { x: ( ] } /* open comment",
    "escapes": ".cl\\73-1, #\\72 1 { f\\69ll: r\\65 d } .\\31 23 { stroke: blue }",
    "font": ".u { font: italic bold 12px/30px Georgia, serif; stroke-width: 1em } line { font-size: 200% }",
    "declarations": "fill: red; stroke-width: 2px /* c; d */; opacity: .5 !important; x:; : y; fill",
}


def css_seeds():
    for name, text in CSS_SEEDS.items():
        write("css", name + ".css", text)
    # Whole documents with <style> sheets and DTD entities for svg_document.
    write("svg_document", "style_sheets.svg",
          '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10"><defs><style>.a{fill:#e6332a}'
          'g > .b:nth-child(2){fill:blue !important} @media print{rect{fill:red}}</style></defs>'
          '<g><rect class="a" width="10" height="10"/><rect class="b" x="10" width="10" height="10" '
          'style="fill:red"/></g><style type="text/plain">x</style><style><![CDATA[ rect { stroke: #000 } ]]></style></svg>')
    write("svg_document", "dtd_entities.svg",
          '<?xml version="1.0"?>\n<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "svg11.dtd" [\n'
          '  <!ENTITY st0 "fill:#F00;">\n  <!ENTITY ns "http://www.w3.org/2000/svg">\n'
          '  <!ENTITY r "<rect x=\'10\' width=\'10\' height=\'10\' style=\'&st0;\'/>">\n'
          '  <!ENTITY ext SYSTEM "x.svg">\n]>\n'
          '<svg xmlns="&ns;" viewBox="0 0 20 10"><rect style="&st0;" width="10" height="10"/>&r;&ext;</svg>')


def text_layout_seeds():
    # First byte: options (bits 0-1 direction, 2 bidi override, 3 vertical, 4-5 caps, 6 no kerning,
    # 7 fallback); second: the size; then the text (fuzz/targets/text_layout.cpp).
    texts = {
        "latin": "Hello, world! AV Wa fi ffl",
        "mixed_bidi": "abc \u05e9\u05dc\u05d5\u05dd 123 \u0645\u0631\u062d\u0628\u0627 (x) def",
        "arabic_joined": "\u0627\u0644\u0639\u0631\u0628\u064a\u0629 \u0644\u0627",
        "marks": "a" + "\u0301\u0308\u0323" * 20 + "e\u0300",
        "controls": "\u202e\u202blrm\u200e\u200f\u2066x\u2069\u202c\u2067y\u2069",
        "lines": "one\ntwo\r\nthree\n\n\u05d0\n",
        "cjk_emoji": "\u6f22\u5b57\u304b\u306a \U0001f600\U0001f44d\U0001f3fd \ufe0f\u200d",
        "private_and_notdef": "\ue000\U000f0000\ufffd\u0000x",
        "small_caps": "Small Caps \u00df\u0131\u0130 \ufb01",
    }
    for i, (name, text) in enumerate(sorted(texts.items())):
        write("text_layout", name + ".txt", bytes([(i * 37) & 0xFF, i]) + text.encode())
    write("text_layout", "invalid_utf8.txt", b"\x80\x02abc\xc3\x28\xed\xa0\x80\xf4\x90\x80\x80")


def data_uri_seeds():
    # hrefs of <image>: data URIs well-formed and not (fuzz/targets/data_uri.cpp), and other schemes.
    png_1x1 = ("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==")
    seeds = {
        "png_base64": "data:image/png;base64," + png_1x1,
        "png_base64_wrapped": "data:image/png;base64," + "\n ".join(png_1x1[i:i + 16] for i in range(0, len(png_1x1), 16)),
        "svg_percent": "data:image/svg+xml,%3Csvg%20xmlns%3D%22http%3A%2F%2Fwww.w3.org%2F2000%2Fsvg%22%2F%3E",
        "svg_utf8_charset": "data:image/svg+xml;charset=utf-8,<svg xmlns='http://www.w3.org/2000/svg'/>",
        "gif_header_base64": "DATA:image/gif;BASE64,R0lGODlhAQABAAAAACw=",
        "jpeg_mislabelled": "data:image/jpg;base64,/9j/4AAQSkZJRgABAQAAAQABAAD/2wBDAA==",
        "webp_header_base64": "data:;base64,UklGRiQAAABXRUJQVlA4IBgAAAAwAQCdASoBAAEAAQAcJaQAA3AA/v3AgAA=",
        "bad_padding": "data:image/png;base64,iVBORw0=KGgo==",
        "bad_alphabet": "data:image/png;base64,iVBO*Rw0KGgo",
        "one_char_tail": "data:image/png;base64,iVBORw0KG",
        "bad_percent": "data:text/plain,%zz%4%",
        "no_comma": "data:image/png;base64",
        "empty": "data:,",
        "params": "data:image/png;name=a.png;foo=\"b,c\";base64,AAAA",
        "https": "https://example.com/a.png",
        "file_relative": "file:images/a%20b.png",
        "drive_letter": "C:/images/a.png",
        "climbing": "../../etc/passwd",
    }
    for name, text in seeds.items():
        write("data_uri", name, text)


def cli_options_seeds():
    # Option values of the commands (fuzz/targets/cli_options.cpp): the examples of their help texts and
    # of docs/svg.md, docs/diff.md and docs/text.md, and values each parser must refuse.
    seeds = {
        "accept_language": "es-MX,de;q=0.8,en;q=0.5",
        "accept_language_spaces": " fr-CA ; q=1 , *;q=0 ,de",
        "accept_language_bad_weight": "en;q=1.5,de;q=abc",
        "accept_language_empty_item": "en,,de",
        "length_cm": "10cm",
        "length_inch": "2.5in",
        "length_percent": "50%",
        "length_huge": "1e308pt",
        "length_exponent": "-3.5E+2mm",
        "region": "0,0,200,40",
        "region_negative_size": "10,10,-1,5",
        "region_overflow": "2147483648,0,99999999999,1",
        "region_tail": "1,2,3,4x",
        "names": "a.svg\r\nicons/b.svg\n\n c.svg \n",
        "names_no_final_newline": "one.svg\ntwo.svgz",
        "names_double_cr": "a.svg\r\r\nb.svg\r\r",
        "features": "smcp,-liga,salt=2",
        "features_bad_value": "salt=65536, kern",
        "features_short_tag": "abc,=1",
        "colour_hex": "#ff000080",
        "colour_functional": "rgb(10%, 20%, 30%)",
        "colour_hsl": "hsla(120deg 50% 50% / 0.5)",
        "colour_keyword": "none",
        "number_small": "1e-9",
        "number_nan": "nan",
        "number_inf": "-inf",
        "number_hex": "0x1p-3",
        "number_out_of_range": "1e400",
        "integer_budget": "2147483648",
        "integer_negative": "-1",
        "integer_spaces": " 42 ",
    }
    for name, text in seeds.items():
        write("cli_options", name, text)


def fnv1a64(data):
    # The content hash of report manifests (raster/diff/report_manifest.cpp): 64-bit FNV-1a.
    value = 0xcbf29ce484222325
    for byte in data:
        value = ((value ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return value


def report_manifest_seeds():
    # Manifests of a `diff --report` directory (fuzz/targets/report_manifest.cpp makes the directory): the
    # stamps of its files, so that mutations start from lines that remove something, and hostile paths
    # carrying the stamp of the file outside the report.
    def line(path, data):
        return "%d %016x %s\n" % (len(data), fnv1a64(data), path)

    header = "curvescan report files 1\n"
    report = (line("images/a.png/diff.png", b"diff a") + line("images/b.png/actual.png", b"actual b")
              + line("images/b.png/diff.png", b"diff b") + line("images/deep/c%20d%25.png/diff.png", b"diff c")
              + line("index.html", b"page"))
    outside = b"not the report's"
    seeds = {
        "previous_report": header + report,
        "changed_since": header + line("images/b.png/diff.png", b"diff B") + line("notes.txt", b"notes"),
        "outside_by_dot_dot": header + line("../outside/keep.png", outside) + line("images/..%2F..%2Foutside%2Fkeep.png", outside),
        "outside_by_links": header + line("link/keep.png", outside) + line("images/outside.png", outside) + line("link", b""),
        "outside_absolute": header + line("/tmp/outside/keep.png", outside) + line("%2Ftmp%2Fkeep.png", outside),
        "the_directory_and_itself": header + line(".", b"") + line("images/", b"") + line(".curvescan-report-files", b"")
                                    + line("./images/b.png/../b.png/diff.png", b"diff b"),
        "bad_escape": header + line("images/b.png/diff.png%4", b"diff b") + line("%zz", b""),
        "newline_and_nul_in_name": header + line("images/b.png%0Adiff.png", b"diff b") + line("notes%00.txt", b"a user's notes"),
        "overflowing_numbers": header + "99999999999999999999999 ffffffffffffffffff images/b.png/diff.png\n-1 -1 x\n",
        "other_format": "curvescan report files 2\n" + report,
        "header_only": header,
        "no_final_line_break": (header + report).rstrip("\n"),
        "crlf": (header + report).replace("\n", "\r\n"),
    }
    for name, text in seeds.items():
        write("report_manifest", name, text)


def main():
    documents = svg_documents()
    css_seeds()
    svg_attribute_values(documents)
    curve_specs()
    expression_seeds()
    raster_stroke_seeds()
    image_diff_seeds()
    text_layout_seeds()
    data_uri_seeds()
    cli_options_seeds()
    report_manifest_seeds()


if __name__ == "__main__":
    main()
