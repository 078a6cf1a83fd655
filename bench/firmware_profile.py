#!/usr/bin/env python3
"""A sampling profile of the firmware as it runs under QEMU (docs/firmware.md,
"Profile"): where the instructions of the real ARM image go, by function.

    bench/firmware_profile.py ELF --machine netduinoplus2 [--interval 0.01] [--top 30] [--callers REGEX]

Method and tunables: QEMU runs the image with -icount shift=0 (guest time is
instructions, so wall time spent in a function follows its instruction count
under TCG) and its monitor on a Unix socket; every --interval seconds the
monitor's `info registers` gives the program counter (R15). Each sample is
charged to the function whose symbol (arm-none-eabi-nm -S -C, sizes as
linked) holds it; inlined code counts for the function it was inlined into.
The table gives each function's share of the samples and the families they
fall in (the portable 128-bit class, libgcc's 64-bit division, Fixed32, the
quantizer, the driver). A sample is a TB start, not an exact instruction:
shares are good to a few per cent at a few thousand samples. The serial
output is thrown away: scripts/firmware.sh checks the stream.
--callers REGEX: each sample in a function whose name matches is charged to
its caller too, so a kernel's share is split by who calls it. The caller is
found on the stack: the first of the 32 words above SP that is a Thumb code
address (odd) inside another function, the return address the callee pushed
with its saved registers (R14 itself is a scratch register once the callee
has pushed it). A heuristic: a saved register that happens to hold such a
value would be charged instead; rows a caller cannot have are that noise.
"""
import argparse
import bisect
import collections
import os
import re
import socket
import subprocess
import sys
import tempfile
import time


def symbols(elf):
    out = subprocess.run(["arm-none-eabi-nm", "-n", "-S", "-C", elf], capture_output=True, text=True, check=True)
    starts, rows = [], []
    for line in out.stdout.splitlines():
        parts = line.split(" ", 3)
        if len(parts) == 4 and parts[2] in "tTwW":
            start, size = int(parts[0], 16) & ~1, int(parts[1], 16)
            starts.append(start)
            rows.append((start, size, parts[3]))
    return starts, rows


def function_at(starts, rows, address):
    i = bisect.bisect_right(starts, address) - 1
    return rows[i][2] if i >= 0 and address < rows[i][0] + max(rows[i][1], 1) else f"?{address:08x}"


def short(name):
    return name if len(name) <= 110 else name[:107] + "..."


def family(name):
    rules = [("Wide128", "portable 128-bit (foundation/int128.hpp)"),
             ("__aeabi_uldivmod|__udivmoddi4|__aeabi_ldivmod|__divmoddi4", "libgcc 64-bit division"),
             ("__aeabi_|__muldi|__ashldi|__lshrdi|__ashrdi", "libgcc other"),
             ("lattice::Fixed<|lattice::isqrt|lattice::sqrt<|lattice::log2|lattice::exp2|lattice::pow", "Fixed32 kernels"),
             ("LatticeLeaf|LatticeHashTable|lht::|Lattice", "lattice leaves and tables"),
             ("quantize::", "quantizer"),
             ("tek4125::", "Tek 4125 driver"),
             ("Bvh|BVH|bvh", "BVH"),
             ("Csg|csg|Quartic|quartic|roots|Roots", "CSG and quartic leaves"),
             ("Renderer|shade|Shading", "renderer and shading")]
    for pattern, label in rules:
        if re.search(pattern, name):
            return label
    return "other"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("elf")
    ap.add_argument("--machine", default="netduinoplus2")
    ap.add_argument("--interval", type=float, default=0.01)
    ap.add_argument("--top", type=int, default=30)
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--callers", help="split the samples of leaf functions matching this regex by caller (R14)")
    args = ap.parse_args()
    starts, rows = symbols(args.elf)
    sock_path = os.path.join(tempfile.mkdtemp(prefix="fw-profile-"), "monitor")
    qemu = subprocess.Popen(["qemu-system-arm", "-M", args.machine, "-display", "none", "-serial", "null",
                             "-semihosting-config", "enable=on,target=native", "-icount", "shift=0",
                             "-monitor", f"unix:{sock_path},server=on,wait=off", "-kernel", args.elf],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    for _ in range(200):
        if os.path.exists(sock_path):
            break
        time.sleep(0.05)
    samples = collections.Counter()
    callers = collections.Counter()  # (callee, caller) -> samples, for --callers
    begin = time.time()
    try:
        s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        s.connect(sock_path)
        s.settimeout(5)
        buffer = ""
        while qemu.poll() is None and time.time() - begin < args.timeout:
            # With --callers the guest stops while its stack is read, so the
            # words belong to the sampled moment.
            s.sendall(b"stop\ninfo registers\n" if args.callers else b"info registers\n")
            while "R15=" not in buffer or not re.search(r"R15=[0-9a-f]{8}", buffer):
                chunk = s.recv(65536).decode(errors="replace")
                if not chunk:
                    raise ConnectionError
                buffer += chunk
            sp = int(re.search(r"R13=([0-9a-f]{8})", buffer).group(1), 16)
            pc = int(re.search(r"R15=([0-9a-f]{8})", buffer).group(1), 16)
            buffer = buffer[buffer.index("R15=") + 12:]
            name = function_at(starts, rows, pc)
            samples[name] += 1
            if args.callers and re.search(args.callers, name):
                s.sendall(f"xp /32xw 0x{sp:08x}\n".encode())
                dump = ""
                while len(re.findall(r"[0-9a-f]+:(?: 0x[0-9a-f]{8}){4}", dump)) < 8:
                    chunk = s.recv(65536).decode(errors="replace")
                    if not chunk:
                        raise ConnectionError
                    dump += chunk
                words = " ".join(re.findall(r"[0-9a-f]+:((?: 0x[0-9a-f]{8}){4})", dump))
                caller = "?"
                for w in re.findall(r"0x([0-9a-f]{8})", words):
                    v = int(w, 16)
                    if v & 1 and function_at(starts, rows, v & ~1)[0] != "?" and function_at(starts, rows, v & ~1) != name:
                        caller = function_at(starts, rows, v & ~1)
                        break
                callers[(name, caller)] += 1
            if args.callers:
                s.sendall(b"cont\n")
            time.sleep(args.interval)
    except (ConnectionError, OSError, socket.timeout):
        pass
    qemu.wait()
    total = sum(samples.values())
    if total == 0:
        print("firmware_profile: no samples (the run ended too soon?)", file=sys.stderr)
        return 1
    print(f"{total} samples of {args.elf} on {args.machine}, {time.time() - begin:.0f} s wall")
    families = collections.Counter()
    for name, n in samples.items():
        families[family(name)] += n
    print("\n| family | share |\n|---|---|")
    for label, n in families.most_common():
        print(f"| {label} | {100 * n / total:.1f} % |")
    print("\n| function | share |\n|---|---|")
    for name, n in samples.most_common(args.top):
        print(f"| `{short(name)}` | {100 * n / total:.1f} % |")
    if args.callers:
        print("\n| function | caller | share of all samples |\n|---|---|---|")
        for (name, caller), n in callers.most_common(args.top):
            print(f"| `{short(name)}` | `{short(caller)}` | {100 * n / total:.1f} % |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
