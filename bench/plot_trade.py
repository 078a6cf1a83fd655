#!/usr/bin/env python3
"""Turns bench/trade.sh's results into docs: for each scene a Markdown table
(between the markers <!-- trade:SCENE:begin --> and <!-- trade:SCENE:end -->
in docs/trade.md) and an SVG plot docs/images/trade-SCENE.svg of image error
(PSNR against the double-precision full ray trace) against render time, the
Pareto front marked. Standard library only, so it runs wherever python3 does.

    plot_trade.py --results DIR --docs DOCS [--runs N] [--size S] SCENE...
"""
import argparse
import csv
import html
import math
import os
import re
import sys
import tempfile

GROUP_COLOURS = {
    "reference": "#000000",
    "arithmetic": "#d62728",
    "lattice": "#1f77b4",
    "lht precision": "#17becf",
    "lht form": "#bcbd22",
    "lattice lookup": "#ff7f0e",
    "palette": "#2ca02c",
    "quantizer mode": "#9467bd",
}


def write_atomically(path, text):
    """Write to a temporary file in the same folder, then rename over path."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=folder, prefix=".trade-")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(tmp, 0o644)  # mkstemp makes it private; docs are for everyone
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def read_rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    if not rows:
        sys.exit(f"plot_trade.py: {path} has no rows; re-run bench/trade.sh")
    for r in rows:
        r["ratio"] = float(r["ratio"])
        r["psnr"] = math.inf if r["psnr_db"] == "inf" else float(r["psnr_db"])
    return rows


def pareto(rows):
    """Rows no other row beats on both time (lower) and PSNR (higher)."""
    front, best = [], -math.inf
    for r in sorted(rows, key=lambda r: (r["ratio"], -r["psnr"])):
        if r["psnr"] > best:
            front.append(r)
            best = r["psnr"]
    return front


def markdown_table(rows, front):
    on_front = {id(r) for r in front}
    lines = [
        "| knob | setting | CPU s | time ratio | peak RSS MiB | table bytes | raster s | PSNR dB | max err | SSIM | Pareto |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|:-:|",
    ]
    for r in rows:
        lines.append(
            "| {} | {} | {} | {:.3f} | {:.1f} | {} | {} | {} | {} | {} | {} |".format(
                r["group"], r["setting"], r["cpu_s"], r["ratio"], int(r["peak_kib"]) / 1024.0,
                r["table_bytes"] if r["table_bytes"] != "0" else "-",
                r["raster_s"] if r["raster_s"] != "0" else "-",
                r["psnr_db"], r["max_err"], r["ssim"], "yes" if id(r) in on_front else ""))
    return "\n".join(lines)


def svg_plot(scene, rows, front):
    w, h, left, right, top, bottom = 760, 480, 70, 200, 40, 50
    finite = [r["psnr"] for r in rows if math.isfinite(r["psnr"])] or [0.0]
    cap = max(finite) + 4.0  # where the exact reference (PSNR infinite) is drawn
    ys = [r["psnr"] if math.isfinite(r["psnr"]) else cap for r in rows]
    ymin, ymax = math.floor(min(ys) - 1), math.ceil(cap + 1)
    ratios = [max(r["ratio"], 1e-3) for r in rows]
    xmin, xmax = math.log10(min(ratios)) - 0.05, math.log10(max(ratios)) + 0.05

    def px(ratio):
        return left + (math.log10(max(ratio, 1e-3)) - xmin) / (xmax - xmin) * (w - left - right)

    def py(psnr):
        v = psnr if math.isfinite(psnr) else cap
        return top + (ymax - v) / (ymax - ymin) * (h - top - bottom)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{left}" y="20" font-size="14">{html.escape(scene)}: error against time '
           '(reference = double-precision full ray trace)</text>']
    # Axes, log-spaced ticks on x, 5 dB ticks on y.
    x0, x1, y0, y1 = left, w - right, top, h - bottom
    out.append(f'<rect x="{x0}" y="{y0}" width="{x1 - x0}" height="{y1 - y0}" fill="none" stroke="#888"/>')
    for t in (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10):
        if xmin <= math.log10(t) <= xmax:
            x = px(t)
            out.append(f'<line x1="{x:.1f}" y1="{y0}" x2="{x:.1f}" y2="{y1}" stroke="#eee"/>')
            out.append(f'<text x="{x:.1f}" y="{y1 + 15}" text-anchor="middle">{t:g}</text>')
    for v in range(int(ymin) - int(ymin) % 5, int(ymax) + 1, 5):
        if ymin <= v <= ymax:
            y = py(v)
            out.append(f'<line x1="{x0}" y1="{y:.1f}" x2="{x1}" y2="{y:.1f}" stroke="#eee"/>')
            out.append(f'<text x="{x0 - 6}" y="{y + 4:.1f}" text-anchor="end">{v}</text>')
    out.append(f'<text x="{(x0 + x1) / 2}" y="{h - 12}" text-anchor="middle">CPU time / reference CPU time (log)</text>')
    out.append(f'<text x="18" y="{(y0 + y1) / 2}" text-anchor="middle" '
               f'transform="rotate(-90 18 {(y0 + y1) / 2})">PSNR dB (higher is better)</text>')
    out.append(f'<text x="{x0 + 4}" y="{py(cap) - 6:.1f}" fill="#555">exact (PSNR infinite)</text>')
    # The Pareto front as a line through its points, then every point.
    pts = " ".join(f"{px(r['ratio']):.1f},{py(r['psnr']):.1f}" for r in front)
    out.append(f'<polyline points="{pts}" fill="none" stroke="#ff7f0e" stroke-width="2" stroke-dasharray="5,3"/>')
    on_front = {id(r) for r in front}
    # Neighbours on the front are often close in time: alternate their labels above and below.
    label_dy = {id(r): (-6 if k % 2 == 0 else 14) for k, r in enumerate(front)}
    for r in rows:
        colour = GROUP_COLOURS.get(r["group"], "#7f7f7f")
        x, y = px(r["ratio"]), py(r["psnr"])
        radius = 5 if id(r) in on_front else 3.5
        stroke = ' stroke="#ff7f0e" stroke-width="2"' if id(r) in on_front else ""
        out.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{radius}" fill="{colour}"{stroke}>'
                   f'<title>{html.escape(r["group"] + ": " + r["setting"])}</title></circle>')
        if id(r) in on_front:
            out.append(f'<text x="{x + 7:.1f}" y="{y + label_dy[id(r)]:.1f}" font-size="10">'
                       f'{html.escape(r["setting"])}</text>')
    # Legend.
    ly = top + 10
    for group, colour in GROUP_COLOURS.items():
        out.append(f'<circle cx="{w - right + 20}" cy="{ly}" r="4" fill="{colour}"/>')
        out.append(f'<text x="{w - right + 30}" y="{ly + 4}">{html.escape(group)}</text>')
        ly += 18
    out.append(f'<line x1="{w - right + 12}" y1="{ly}" x2="{w - right + 28}" y2="{ly}" stroke="#ff7f0e" '
               'stroke-width="2" stroke-dasharray="5,3"/>')
    out.append(f'<text x="{w - right + 30}" y="{ly + 4}">Pareto front</text>')
    out.append("</svg>\n")
    return "\n".join(out)


def replace_block(text, scene, block):
    pattern = re.compile(rf"(<!-- trade:{re.escape(scene)}:begin -->\n).*?(<!-- trade:{re.escape(scene)}:end -->)",
                         re.S)
    if not pattern.search(text):
        return text + f"\n<!-- trade:{scene}:begin -->\n{block}\n<!-- trade:{scene}:end -->\n"
    return pattern.sub(lambda m: m.group(1) + block + "\n" + m.group(2), text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", required=True, help="folder with SCENE.tsv from bench/trade.sh")
    ap.add_argument("--docs", required=True, help="the docs folder holding trade.md")
    ap.add_argument("--runs", default="?")
    ap.add_argument("--size", default="scene")
    ap.add_argument("scenes", nargs="+")
    args = ap.parse_args()
    doc_path = os.path.join(args.docs, "trade.md")
    if not os.path.exists(doc_path):
        sys.exit(f"plot_trade.py: {doc_path} does not exist")
    os.makedirs(os.path.join(args.docs, "images"), exist_ok=True)
    with open(doc_path, encoding="utf-8") as f:
        doc = f.read()
    for scene in args.scenes:
        tsv = os.path.join(args.results, scene + ".tsv")
        if not os.path.exists(tsv):
            sys.exit(f"plot_trade.py: {tsv} is missing; run bench/trade.sh first")
        rows = read_rows(tsv)
        front = pareto(rows)
        write_atomically(os.path.join(args.docs, "images", f"trade-{scene}.svg"), svg_plot(scene, rows, front))
        block = (f"Median of {args.runs} runs, size {args.size}; `bench/trade.sh` regenerates this table.\n\n"
                 f"{markdown_table(rows, front)}\n\n![{scene}: error against time](images/trade-{scene}.svg)")
        doc = replace_block(doc, scene, block)
    write_atomically(doc_path, doc)
    print(f"plot_trade.py: updated {doc_path} and its plots", file=sys.stderr)


if __name__ == "__main__":
    main()
