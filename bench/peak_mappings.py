#!/usr/bin/env python3
"""Where a command's peak resident memory is: its mappings at the largest sample.

   python3 bench/peak_mappings.py COMMAND...

Runs COMMAND (its output discarded), reads /proc/PID/smaps every millisecond
and keeps the sample whose Rss adds up highest; prints that total split into
the executable's pages (file-backed mappings: code, read-only data) and the
rest, then each mapping's Rss and anonymous share by name and permissions, so
the code pages (r-xp) show apart from the read-only data (r--p) of the same
file. Used by bench/memory.sh and bench/plate7-memory.sh --mappings. A sample
can miss a peak shorter than the period; /usr/bin/time's figure is the
kernel's own high-water mark.
"""
import re
import subprocess
import sys
import time

proc = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
best_total, best = 0, ""
while proc.poll() is None:
    try:
        with open(f"/proc/{proc.pid}/smaps") as f:
            smaps = f.read()
    except OSError:
        break
    total = sum(int(k) for k in re.findall(r"^Rss:\s+(\d+)", smaps, re.M))
    if total > best_total:
        best_total, best = total, smaps
    time.sleep(0.001)
if proc.wait() != 0:
    sys.exit(f"peak_mappings.py: {' '.join(sys.argv[1:])} failed")

rss, anon, name = {}, {}, None
for line in best.splitlines():
    if re.match(r"^[0-9a-f]+-[0-9a-f]+ ", line):
        fields = line.split()
        name = (fields[5] if len(fields) > 5 else "[anonymous]") + " " + fields[1]
    elif line.startswith("Rss:"):
        rss[name] = rss.get(name, 0) + int(line.split()[1])
    elif line.startswith("Anonymous:"):
        anon[name] = anon.get(name, 0) + int(line.split()[1])
code = sum(v - anon.get(k, 0) for k, v in rss.items() if k.startswith("/"))
print(f"    sampled peak {best_total} KiB = executable's pages {code} KiB + the rest {best_total - code} KiB")
for k, v in sorted(rss.items(), key=lambda kv: -kv[1])[:12]:
    if v:
        print(f"    {v:>6} KiB  (anonymous {anon.get(k, 0):>5})  {k}")
