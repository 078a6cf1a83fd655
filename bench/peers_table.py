#!/usr/bin/env python3
"""The markdown table of bench/peers.sh from its raw timings.

    peers_table.py RAW.tsv PSNR.tsv NOTES.tsv

RAW: scene, threads, program, run, whole-process wall seconds, whole-process
CPU seconds (user + system, "-" without GNU time), trace seconds.
PSNR: scene, program, dB against ours --full. NOTES: scene, program, why a
peer did not trace the scene. Each cell is the median over the runs, with the
runs' min-max beside it; "x lattice" is the median divided by lattice mode's
median for the same scene and thread count (below 1: faster than lattice mode).
"""
import statistics
import sys
from collections import defaultdict

NAMES = {
    "lattice": "Lattice, lattice mode",
    "full": "Lattice `--full`",
    "povray": "POV-Ray, spheres + cylinders",
    "povray-sweep": "POV-Ray, `sphere_sweep`",
    "embree": "Embree, round linear curves",
}
ORDER = list(NAMES)


def read_tsv(path):
    with open(path) as f:
        return [line.rstrip("\n").split("\t") for line in f if line.strip()]


def cell(values):
    return f"{statistics.median(values):.3f}", f"{min(values):.3f}-{max(values):.3f}"


def ratio(values, base):
    if not values or not base:
        return "-"
    return f"{statistics.median(values) / statistics.median(base):.2f}"


def main(raw_path, psnr_path, notes_path):
    times = defaultdict(lambda: ([], [], []))
    scenes, threads = [], []
    for scene, thr, program, _run, whole, cpu, trace in read_tsv(raw_path):
        times[(scene, int(thr), program)][0].append(float(whole))
        times[(scene, int(thr), program)][1].append(float(trace))
        if cpu != "-":
            times[(scene, int(thr), program)][2].append(float(cpu))
        if scene not in scenes:
            scenes.append(scene)
        if int(thr) not in threads:
            threads.append(int(thr))
    psnr = {(s, p): v for s, p, v in read_tsv(psnr_path)}
    notes = {(s, p): n for s, p, n in read_tsv(notes_path)}

    print("| scene | thr | program | whole s, median | min-max | x lattice | whole CPU s | x lattice "
          "| trace s, median | min-max | x lattice | PSNR vs `--full` |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for scene in scenes:
        for thr in threads:
            base = times.get((scene, thr, "lattice"))
            for program in ORDER:
                key = (scene, thr, program)
                if key not in times:
                    if (scene, program) in notes and thr == threads[0]:
                        print(f"| {scene} | | {NAMES[program]} | not traced: {notes[(scene, program)]} "
                              "| | | | | | | | |")
                    continue
                whole, trace, cpu = times[key]
                wm, wr = cell(whole)
                tm, tr = cell(trace)
                cm = f"{statistics.median(cpu):.3f}" if cpu else "-"
                wx = ratio(whole, base[0] if base else [])
                tx = ratio(trace, base[1] if base else [])
                cx = ratio(cpu, base[2] if base else [])
                quality = "reference" if program == "full" else psnr.get((scene, program), "-")
                if quality not in ("reference", "-", "inf"):
                    quality = f"{float(quality):.1f} dB"
                print(f"| {scene} | {thr} | {NAMES[program]} | {wm} | {wr} | {wx} | {cm} | {cx} | {tm} | {tr} | {tx} "
                      f"| {quality} |")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
