"""Checks a screenshot of `opencrg view`'s page (taken by headless Chromium in test.sh):
the road must be drawn, i.e. many pixels below the page's text differ from its
background, some of them in the elevation colours, and the reference line's red is there.

usage: python3 check_view.py SCREENSHOT.png
"""

import struct
import sys
import zlib


def pixels(path):
    """The rows of an 8-bit RGB or RGBA PNG as lists of (r, g, b)."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), f"unexpected PNG type {depth} {colour}"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, channels)])
        prev = line
    return rows


if __name__ == "__main__":
    rows = pixels(sys.argv[1])
    body = [p for row in rows[80:] for p in row]
    background = (244, 244, 242)
    drawn = [p for p in body if max(abs(p[k] - background[k]) for k in range(3)) > 24]
    red = [p for p in drawn if p[0] > 150 and p[1] < 80 and p[2] < 80]
    share = len(drawn) / len(body)
    print(f"{sys.argv[1]}: {len(drawn)} of {len(body)} pixels drawn ({100 * share:.1f} %), {len(red)} of the reference line")
    assert share > 0.01, "the road is not drawn"
    assert red, "the reference line is not drawn"
