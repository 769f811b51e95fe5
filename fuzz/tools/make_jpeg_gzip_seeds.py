#!/usr/bin/env python3
"""Writes the seed corpora of the jpeg_read and gzip_input fuzz targets (docs/fuzzing.md).

jpeg_read: small JPEGs made by cjpeg (Debian package libjpeg-turbo-progs, needed only to regenerate these
seeds) from images drawn here: RGB and greyscale, baseline, progressive, arithmetic-coded, with restart
markers, 4:4:4 and 4:2:0 sampling, odd sizes, 1 x 1; plus a truncated one.
gzip_input: gzip members (mtime 0, so the bytes are deterministic) of small SVG documents: one member,
two concatenated members, a highly compressible one that expands far, a truncated one, and one with
trailing garbage.

Run from the repository root: python3 fuzz/tools/make_jpeg_gzip_seeds.py
"""
import gzip
import io
import os
import subprocess

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'corpus')


def ppm(width, height, grey=False):
    pixels = bytearray()
    for y in range(height):
        for x in range(width):
            r, g, b = (x * 37 + y * 11) % 256, (x * 5 + y * 53) % 256, (x * y * 7) % 256
            pixels += bytes([r]) if grey else bytes([r, g, b])
    magic = b'P5' if grey else b'P6'
    return magic + b'\n%d %d\n255\n' % (width, height) + bytes(pixels)


def cjpeg(image, *flags):
    return subprocess.run(['cjpeg', *flags], input=image, capture_output=True, check=True).stdout


def write(directory, name, data):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, name), 'wb') as f:
        f.write(data)


def jpeg_seeds():
    out = os.path.join(ROOT, 'jpeg_read')
    write(out, 'rgb_baseline_16x16.jpg', cjpeg(ppm(16, 16), '-quality', '75'))
    write(out, 'grey_17x13.jpg', cjpeg(ppm(17, 13, grey=True), '-grayscale'))
    write(out, 'rgb_progressive_24x8.jpg', cjpeg(ppm(24, 8), '-progressive'))
    write(out, 'rgb_arithmetic_8x8.jpg', cjpeg(ppm(8, 8), '-arithmetic'))
    write(out, 'rgb_restart_32x32.jpg', cjpeg(ppm(32, 32), '-restart', '1B'))
    write(out, 'rgb_444_9x9.jpg', cjpeg(ppm(9, 9), '-sample', '1x1'))
    write(out, 'rgb_1x1.jpg', cjpeg(ppm(1, 1), '-quality', '10'))
    whole = cjpeg(ppm(16, 16), '-optimize')
    write(out, 'truncated.jpg', whole[:len(whole) // 2])


def gz(data):
    buffer = io.BytesIO()
    with gzip.GzipFile(fileobj=buffer, mode='wb', mtime=0) as f:
        f.write(data)
    return buffer.getvalue()


def gzip_seeds():
    out = os.path.join(ROOT, 'gzip_input')
    svg = b'<svg xmlns="http://www.w3.org/2000/svg" width="8" height="8"><rect width="4" height="4"/></svg>'
    write(out, 'one_member.svgz', gz(svg))
    write(out, 'two_members.svgz', gz(svg[:40]) + gz(svg[40:]))
    write(out, 'expands.svgz', gz(b' ' * 200000))
    whole = gz(svg)
    write(out, 'truncated.svgz', whole[:len(whole) - 6])
    write(out, 'trailing_garbage.svgz', whole + b'not gzip')


if __name__ == '__main__':
    jpeg_seeds()
    gzip_seeds()
