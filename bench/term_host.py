#!/usr/bin/env python3
# The user's terminal for bench/term.sh: runs `lattice term ...` with a
# pseudo-terminal as its controlling terminal (rows x columns of text, a
# text area of W x H pixels), answers its device-attributes request as a
# sixel terminal with 256 registers does (xterm -ti vt340), reads everything
# it draws, and prints one line of figures:
#   seconds=S cpu=C bytes=B
# S: wall seconds from the start to the program's exit (on screen: the last
# redraw has been written to the terminal before lattice exits); C: the CPU
# seconds (user + system) lattice used, from /proc/PID/stat while it lives;
# B: bytes it wrote to the terminal. With --idle T it instead lets the
# session sit for T seconds after --settle seconds and prints
#   idle_cpu_percent=P
# from the CPU ticks lattice used over those T seconds, then ends it (SIGTERM).
#   bench/term_host.py [--rows R --columns C --width W --height H] [--idle T --settle S] [--keep FILE] -- LATTICE ARGS...
# --keep FILE writes everything lattice drew (sixels, status line, its summary) to FILE.
import argparse, fcntl, os, pty, select, signal, struct, sys, termios, time

ap = argparse.ArgumentParser()
ap.add_argument('--rows', type=int, default=40)
ap.add_argument('--columns', type=int, default=100)
ap.add_argument('--width', type=int, default=1000)
ap.add_argument('--height', type=int, default=800)
ap.add_argument('--idle', type=float, default=0)
ap.add_argument('--settle', type=float, default=2)
ap.add_argument('--keep', default='')  # write what lattice drew to this file
ap.add_argument('command', nargs=argparse.REMAINDER)
a = ap.parse_args()
command = a.command[1:] if a.command and a.command[0] == '--' else a.command

start = time.monotonic()
pid, fd = pty.fork()
if pid == 0:
    os.execv(command[0], command)
fcntl.ioctl(fd, termios.TIOCSWINSZ, struct.pack('HHHH', a.rows, a.columns, a.width, a.height))
ticks = os.sysconf('SC_CLK_TCK')


def cpu_ticks():
    try:
        with open(f'/proc/{pid}/stat') as f:
            fields = f.read().rsplit(')', 1)[1].split()
        return int(fields[11]) + int(fields[12])  # utime, stime
    except (OSError, IndexError):
        return None


written = 0
kept = []
answered = False
last_cpu = 0
idle_from = None
idle_ticks = None
seen = b''
while True:
    r, _, _ = select.select([fd], [], [], 0.05)
    if r:
        try:
            data = os.read(fd, 1 << 16)
        except OSError:
            data = b''
        if not data:
            break
        written += len(data)
        if a.keep:
            kept.append(data)
        if not answered:
            seen += data
            if b'\x1b[c' in seen:
                os.write(fd, b'\x1b[?1;0;256S\x1b[?63;1;2;4;6;9;15;22c')
                answered = True
    now = cpu_ticks()
    if now is not None:
        last_cpu = now
    if a.idle > 0:
        elapsed = time.monotonic() - start
        if idle_from is None and elapsed >= a.settle:
            idle_from = (time.monotonic(), last_cpu)
        elif idle_from is not None and idle_ticks is None and time.monotonic() - idle_from[0] >= a.idle:
            idle_ticks = (last_cpu - idle_from[1], time.monotonic() - idle_from[0])
            os.kill(pid, signal.SIGTERM)
seconds = time.monotonic() - start
if a.keep:
    with open(a.keep, 'wb') as f:
        f.write(b''.join(kept))
os.waitpid(pid, 0)
if a.idle > 0:
    used, span = idle_ticks
    print(f'idle_cpu_percent={100.0 * used / ticks / span:.2f}')
else:
    print(f'seconds={seconds:.3f} cpu={last_cpu / ticks:.2f} bytes={written}')
