#!/usr/bin/env python3
"""Turns bench/wire_bench's results into docs: the SVG plot
docs/images/wire-trade.svg of PSNR against the Tek 4125 stream's seconds at
9600 and 38400 baud (one x axis in bytes, labelled in seconds at both rates),
one mark per form set, palette size, dithering and lambda; and the Markdown
table between <!-- wire:table:begin --> and <!-- wire:table:end --> in
docs/trade.md. Standard library only.

    plot_wire.py --results DIR --docs DOCS
"""
import argparse
import csv
import html
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_trade import write_atomically  # noqa: E402  (one atomic writer for both plots)

PROFILE_COLOURS = {"strict": "#1f77b4", "compact": "#d62728"}


def read(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def svg(rows):
    w, h, left, right, top, bottom = 820, 520, 70, 190, 40, 70
    xs = [int(r["bytes"]) for r in rows]
    ys = [float(r["psnr"]) for r in rows]
    xmin, xmax = math.log10(min(xs)) - 0.03, math.log10(max(xs)) + 0.03
    ymin, ymax = math.floor(min(ys)) - 1, math.ceil(max(ys)) + 1

    def px(b):
        return left + (math.log10(b) - xmin) / (xmax - xmin) * (w - left - right)

    def py(v):
        return top + (ymax - v) / (ymax - ymin) * (h - top - bottom)

    x0, x1, y0, y1 = left, w - right, top, h - bottom
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{left}" y="20" font-size="14">Plate 6 on a Tek 4125: PSNR against time on the wire '
           '(8N1)</text>',
           f'<rect x="{x0}" y="{y0}" width="{x1 - x0}" height="{y1 - y0}" fill="none" stroke="#888"/>']
    for s in (5, 10, 20, 30, 45, 60, 90, 120, 180):  # seconds at 9600 baud: 960 bytes a second
        b = s * 960
        if xmin <= math.log10(b) <= xmax:
            x = px(b)
            out.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y1}" stroke="#eee"/>')
            out.append(f'<text x="{x:.1f}" y="{y1 + 15}" text-anchor="middle">{s}</text>')
            out.append(f'<text x="{x:.1f}" y="{y1 + 30}" text-anchor="middle" fill="#777">{s / 4:g}</text>')
    out.append(f'<text x="{x0 - 6}" y="{y1 + 15}" text-anchor="end">9600 baud, s</text>')
    out.append(f'<text x="{x0 - 6}" y="{y1 + 30}" text-anchor="end" fill="#777">38400 baud, s</text>')
    for b, label in ((57600, "60 s at 9600"), (76800, "20 s at 38400")):
        if xmin <= math.log10(b) <= xmax:
            x = px(b)
            out.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y1}" stroke="#2ca02c" stroke-dasharray="4,3"/>')
            out.append(f'<text x="{x + 3:.1f}" y="{y0 + 12}" fill="#2ca02c">{label}</text>')
    for v in range(int(ymin) - int(ymin) % 5, int(ymax) + 1, 5):
        if ymin <= v <= ymax:
            y = py(v)
            out.append(f'<line x1="{x0}" y1="{y:.1f}" x2="{x1}" y2="{y:.1f}" stroke="#eee"/>')
            out.append(f'<text x="{x0 - 6}" y="{y + 4:.1f}" text-anchor="end">{v}</text>')
    out.append(f'<text x="18" y="{(y0 + y1) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 18 {(y0 + y1) / 2})">PSNR dB against the truecolour render</text>')
    out.append(f'<text x="{(x0 + x1) / 2}" y="{h - 10}" text-anchor="middle">stream length (log), as seconds</text>')
    for r in rows:
        colour = PROFILE_COLOURS.get(r["profile"], "#7f7f7f")
        x, y = px(int(r["bytes"])), py(float(r["psnr"]))
        tip = html.escape(f'{r["profile"]} {r["colours"]} colours, dither {r["dither"]}, lambda {r["lambda"]}: '
                          f'{r["bytes"]} B, {r["psnr"]} dB')
        if r["dither"] == "none":
            out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3.5" fill="{colour}"><title>{tip}</title></circle>')
        else:
            out.append(f'<rect x="{x - 3:.1f}" y="{y - 3:.1f}" width="6" height="6" fill="none" stroke="{colour}">'
                       f'<title>{tip}</title></rect>')
    ly = top + 10
    for name, colour in PROFILE_COLOURS.items():
        out.append(f'<circle cx="{w - right + 20}" cy="{ly}" r="4" fill="{colour}"/>')
        out.append(f'<text x="{w - right + 30}" y="{ly + 4}">{name}, no dither</text>')
        ly += 18
        out.append(f'<rect x="{w - right + 17}" y="{ly - 3}" width="6" height="6" fill="none" stroke="{colour}"/>')
        out.append(f'<text x="{w - right + 30}" y="{ly + 4}">{name}, Floyd-Steinberg</text>')
        ly += 18
    out.append(f'<text x="{w - right + 12}" y="{ly + 8}" fill="#555">each mark: a palette size</text>')
    out.append(f'<text x="{w - right + 12}" y="{ly + 22}" fill="#555">and a lambda (0 .. 128000)</text>')
    out.append("</svg>\n")
    return "\n".join(out)


def table(rows):
    lines = ["| profile | colours | dither | lambda | bytes | 9600 baud s | 38400 baud s | PSNR dB | SSIM |",
             "|---|---:|---|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f'| {r["profile"]} | {r["colours"]} | {r["dither"]} | {r["lambda"]} | {int(r["bytes"]):,} | '
                     f'{r["s9600"]} | {r["s38400"]} | {r["psnr"]} | {r["ssim"]} |')
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--results", required=True)
    p.add_argument("--docs", required=True)
    a = p.parse_args()
    rows = read(os.path.join(a.results, "wire.tsv"))
    write_atomically(os.path.join(a.docs, "images", "wire-trade.svg"), svg(rows))
    path = os.path.join(a.docs, "trade.md")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    pattern = re.compile(r"(<!-- wire:table:begin -->\n).*?(<!-- wire:table:end -->)", re.S)
    if not pattern.search(text):
        raise SystemExit("plot_wire.py: docs/trade.md has no <!-- wire:table:begin --> ... end --> block")
    text = pattern.sub(lambda m: m.group(1) + table(rows) + m.group(2), text)
    write_atomically(path, text)


if __name__ == "__main__":
    main()
