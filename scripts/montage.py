#!/usr/bin/python3
"""Frames of one size joined into one picture, row by row (Debian's python3-pil): the docs' montages.

    montage.py [--columns N] [--scale S] [--gap PX] OUT.png FRAME.png...

--columns: frames to a row (default: all in one row); --scale: each frame resized by S (Lanczos; default 1, the
pixels as they are); --gap: white pixels between frames (default 0). The first frame's resolution (dpi) is
kept. Used by scripts/docs_figures.sh and scripts/docs_record_frames.sh.
"""
import argparse

from PIL import Image


def montage(frames, columns, scale, gap):
    first = frames[0]
    if any(frame.size != first.size for frame in frames):
        raise SystemExit("montage.py: the frames differ in size")
    width, height = round(first.width * scale), round(first.height * scale)
    rows = (len(frames) + columns - 1) // columns
    sheet = Image.new(first.mode, (columns * width + (columns - 1) * gap, rows * height + (rows - 1) * gap), "white")
    for i, frame in enumerate(frames):
        shown = frame if scale == 1 else frame.resize((width, height), Image.LANCZOS)
        sheet.paste(shown, ((i % columns) * (width + gap), (i // columns) * (height + gap)))
    return sheet


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--columns", type=int, default=0)
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--gap", type=int, default=0)
    parser.add_argument("out")
    parser.add_argument("frames", nargs="+")
    args = parser.parse_args()
    frames = [Image.open(path) for path in args.frames]
    sheet = montage(frames, args.columns or len(frames), args.scale, args.gap)
    dpi = frames[0].info.get("dpi")
    sheet.save(args.out, optimize=True, **({"dpi": dpi} if dpi else {}))


if __name__ == "__main__":
    main()
