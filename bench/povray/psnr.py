#!/usr/bin/env python3
"""PSNR between two 8-bit PNG pictures of the same size (bench/povray-peer.sh).

Standard library only (no Pillow on a bare machine): reads non-interlaced
8-bit greyscale/RGB/RGBA PNGs, undoes the five PNG row filters (PNG spec,
ISO/IEC 15948, sec. 9) and compares the RGB channels.

Prints: psnr_dB max_channel_diff differing_pixels_percent mean_abs_diff
"""
import math
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 6: 4}  # colour type -> samples per pixel


def read_png(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        sys.exit(f"psnr.py: cannot read {path}: {e.strerror}")
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"psnr.py: {path} is not a PNG file")
    pos, idat, header = 8, [], None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            if len(body) != 13:
                sys.exit(f"psnr.py: {path}: IHDR chunk has {len(body)} bytes, not 13")
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
        pos += 12 + length
    if header is None:
        sys.exit(f"psnr.py: {path} has no IHDR chunk")
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in CHANNELS or interlace:
        sys.exit(f"psnr.py: {path}: only 8-bit, non-interlaced grey/RGB/RGBA PNGs are supported "
                 f"(got depth {depth}, colour type {colour}, interlace {interlace})")
    bpp = CHANNELS[colour]
    try:
        raw = zlib.decompress(b"".join(idat))
    except zlib.error as e:
        sys.exit(f"psnr.py: {path}: damaged image data ({e})")
    stride = width * bpp
    if len(raw) < height * (stride + 1):
        sys.exit(f"psnr.py: {path}: image data is truncated")
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - bpp] if i >= bpp else 0
            up = previous[i]
            upleft = previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - upleft
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upleft)
                pred = left if pa <= pb and pa <= pc else (up if pb <= pc else upleft)
                line[i] = (line[i] + pred) & 255
            elif kind != 0:
                sys.exit(f"psnr.py: {path}: unknown filter type {kind} in row {y}")
        rows.append(line)
        previous = line
    rgb = bytearray()
    for line in rows:
        for x in range(width):
            px = line[x * bpp:(x + 1) * bpp]
            rgb += px[:3] if bpp >= 3 else px * 3
    return width, height, rgb


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: psnr.py A.png B.png")
    wa, ha, a = read_png(sys.argv[1])
    wb, hb, b = read_png(sys.argv[2])
    if (wa, ha) != (wb, hb):
        sys.exit(f"psnr.py: sizes differ: {wa}x{ha} against {wb}x{hb}")
    squares = total = biggest = differing = 0
    for p in range(wa * ha):
        d = [abs(a[3 * p + c] - b[3 * p + c]) for c in range(3)]
        squares += sum(x * x for x in d)
        total += sum(d)
        biggest = max(biggest, max(d))
        differing += any(d)
    n = 3 * wa * ha
    mse = squares / n
    psnr = "inf" if mse == 0 else f"{10 * math.log10(255 * 255 / mse):.2f}"
    print(f"{psnr} {biggest} {100 * differing / (wa * ha):.2f} {total / n:.3f}")


if __name__ == "__main__":
    main()
