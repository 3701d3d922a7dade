#!/usr/bin/env python3
"""Target tests are load-independent: the same firmware run twice on the
emulator, once alone and once with every host core busy (one spinning process
per core, the kind of load a proof job puts beside it), must print the same
console output, byte for byte and so tick for tick, because under
-icount shift=N,sleep=off virtual time follows the instruction count only.
The wall-clock times of the two runs are reported to show the load was real.

  load_independence.py --qemu QEMU --elf ELF --icount SHIFT --until REGEX [--suite NAME]
"""
import argparse
import multiprocessing
import os
import re
import subprocess
import sys
import time

import robocube_emu

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..'))


def spin(stop):
    x = 0
    while not stop.is_set():
        x = (x * 1103515245 + 12345) & 0xFFFFFFFF


def run(qemu, elf, icount, until, timeout):
    """Boots the image with the console on stdio; returns (output, wall seconds)."""
    start = time.time()
    p = robocube_emu.popen(['-serial', 'stdio'], kernel=elf, icount=icount, qemu=qemu,
                           stderr=subprocess.STDOUT)
    out = b''
    pat = re.compile(until.encode())
    try:
        os.set_blocking(p.stdout.fileno(), False)
        while time.time() - start < timeout:
            chunk = p.stdout.read(4096)
            if chunk:
                out += chunk
                if pat.search(out) and out.endswith(b'\n'):
                    break
            elif p.poll() is not None:
                break
            else:
                time.sleep(0.02)
    finally:
        p.kill()
        p.wait()
    return out.decode(errors='replace'), time.time() - start


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--qemu', required=True)
    ap.add_argument('--elf', required=True)
    ap.add_argument('--icount', required=True)
    ap.add_argument('--until', required=True, help='stop once a console line matches this')
    ap.add_argument('--timeout', type=float, default=120)
    ap.add_argument('--suite')
    a = ap.parse_args()
    quiet, t_quiet = run(a.qemu, a.elf, a.icount, a.until, a.timeout)
    stop = multiprocessing.Event()
    hogs = [multiprocessing.Process(target=spin, args=(stop,)) for _ in range(os.cpu_count() or 2)]
    for h in hogs:
        h.start()
    try:
        busy, t_busy = run(a.qemu, a.elf, a.icount, a.until, a.timeout)
    finally:
        stop.set()
        for h in hogs:
            h.join()
    passed = failed = 0
    checks = [
        ('the run alone reached %r' % a.until, re.search(a.until, quiet) is not None),
        ('the run beside %d busy processes reached it' % len(hogs), re.search(a.until, busy) is not None),
        ('console output identical (%d lines, %d bytes)' % (quiet.count('\n'), len(quiet)), quiet == busy),
    ]
    for what, ok in checks:
        print('%s: %s' % ('ok' if ok else 'FAILED', what))
        passed += ok
        failed += not ok
    if quiet != busy:
        ql, bl = quiet.splitlines(), busy.splitlines()
        for i, (x, y) in enumerate(zip(ql, bl)):
            if x != y:
                print('first difference, line %d:\n  alone: %s\n  busy:  %s' % (i + 1, x, y))
                break
    print('wall clock: %.1f s alone, %.1f s with %d spinning processes on %d cores (load average %.1f)'
          % (t_quiet, t_busy, len(hogs), os.cpu_count() or 0, os.getloadavg()[0]))
    tail = [l for l in quiet.splitlines() if l.startswith(('ran ', 'bsched thread'))]
    for l in tail:
        print('  ' + l)
    print('%d passed, %d failed' % (passed, failed))
    if a.suite:
        os.makedirs(os.path.join(ROOT, 'build/results'), exist_ok=True)
        with open(os.path.join(ROOT, 'build/results', a.suite + '.txt'), 'w') as f:
            f.write('%d passed, %d failed\n' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
