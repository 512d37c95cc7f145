#!/usr/bin/env python3
"""PNG pixels without an imaging library (python3's zlib only): read 8-bit, non-interlaced PNGs (what cairo
and libpng write for raycam's figures), and join frames of one size into a grid.

    png_pixels.py join COLUMNS OUT.png FRAME.png...   # the frames row by row, COLUMNS to a row
    png_pixels.py same A.png B.png                    # exit 0 when both decode to the same pixels

scripts/docs_figures.sh joins the docs' montages with it; tests/docs/check_docs_figures.py compares them.
Pixels, not bytes: the same pixels compress differently under another zlib.
"""
import struct
import sys
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"
CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # colour type -> samples a pixel (grey, RGB, grey+alpha, RGBA)


class Image:
    def __init__(self, width, height, colour_type, rows, phys=None):
        self.width, self.height, self.colour_type, self.rows, self.phys = width, height, colour_type, rows, phys


def chunks(data):
    if data[:8] != SIGNATURE:
        raise ValueError("not a PNG")
    at = 8
    while at + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        yield kind, data[at + 8:at + 8 + length]
        at += 12 + length


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def unfilter(kind, row, previous, step):
    """One scanline with its filter undone (the five filters of the PNG specification, section 9)."""
    if kind == 0:
        return row
    if kind == 2:  # up: libpng's choice for the figures, done in one pass
        return bytes((x + p) & 255 for x, p in zip(row, previous))
    out = bytearray(row)
    for i in range(len(out)):
        left = out[i - step] if i >= step else 0
        up = previous[i]
        if kind == 1:
            out[i] = (out[i] + left) & 255
        elif kind == 3:
            out[i] = (out[i] + (left + up) // 2) & 255
        elif kind == 4:
            out[i] = (out[i] + paeth(left, up, previous[i - step] if i >= step else 0)) & 255
        else:
            raise ValueError("unknown filter %d" % kind)
    return bytes(out)


def read(path):
    with open(path, "rb") as f:
        data = f.read()
    header, compressed, phys = None, [], None
    for kind, body in chunks(data):
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            compressed.append(body)
        elif kind == b"pHYs":
            phys = body
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or interlace != 0 or colour_type not in CHANNELS:
        raise ValueError("%s: only 8-bit, non-interlaced grey or RGB(A) PNGs are read here" % path)
    step = CHANNELS[colour_type]
    stride = width * step
    raw = zlib.decompress(b"".join(compressed))
    rows, previous = [], bytes(stride)
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        previous = unfilter(line[0], line[1:], previous, step)
        rows.append(previous)
    return Image(width, height, colour_type, rows, phys)


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def write(path, image):
    # Every row with the "up" filter, as the figures' own PNGs: the montage's frames repeat row to row.
    filtered, previous = [], bytes(len(image.rows[0]))
    for row in image.rows:
        filtered.append(b"\x02" + bytes((x - p) & 255 for x, p in zip(row, previous)))
        previous = row
    header = struct.pack(">IIBBBBB", image.width, image.height, 8, image.colour_type, 0, 0, 0)
    body = chunk(b"IHDR", header)
    if image.phys:
        body += chunk(b"pHYs", image.phys)
    body += chunk(b"IDAT", zlib.compress(b"".join(filtered), 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(SIGNATURE + body)


def join(columns, frames):
    first = frames[0]
    for frame in frames:
        if (frame.width, frame.height, frame.colour_type) != (first.width, first.height, first.colour_type):
            raise ValueError("the frames differ in size or colour type")
    grid_rows = (len(frames) + columns - 1) // columns
    blank = bytes(len(first.rows[0]))  # a short last row of frames ends in black
    rows = []
    for r in range(grid_rows):
        line = frames[r * columns:(r + 1) * columns]
        for y in range(first.height):
            rows.append(b"".join(f.rows[y] for f in line) + blank * (columns - len(line)))
    return Image(first.width * columns, first.height * grid_rows, first.colour_type, rows, first.phys)


def differing_pixels(a, b):
    """How many pixels differ, or None when the sizes or colour types differ."""
    if (a.width, a.height, a.colour_type) != (b.width, b.height, b.colour_type):
        return None
    step = CHANNELS[a.colour_type]
    count = 0
    for row_a, row_b in zip(a.rows, b.rows):
        if row_a != row_b:
            count += sum(row_a[i:i + step] != row_b[i:i + step] for i in range(0, len(row_a), step))
    return count


def main(argv):
    if len(argv) >= 4 and argv[0] == "join":
        write(argv[2], join(int(argv[1]), [read(p) for p in argv[3:]]))
        return 0
    if len(argv) == 3 and argv[0] == "same":
        a, b = read(argv[1]), read(argv[2])
        differing = differing_pixels(a, b)
        if differing == 0:
            return 0
        print("%s, %s: %s" % (argv[1], argv[2], "sizes differ (%dx%d, %dx%d)" % (a.width, a.height, b.width, b.height)
                              if differing is None else "%d pixels differ" % differing))
        return 1
    print(__doc__.strip(), file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
