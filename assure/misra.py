#!/usr/bin/env python3
"""MISRA C:2012 with cppcheck's MISRA addon, gated on a deviation list.

  misra.py --deviations assure/misra-deviations.txt FILE...   gate (exit 1 on an unrecorded one)
  misra.py --count DIR...                                     counts per rule, no gate

Each finding is keyed by rule, file and function (the function whose body holds
the line, '-' at file scope), never by line number, so the list survives edits.
A deviation line is `rule | file | function | reason`; function may be `*`.
Rule texts are not shipped with cppcheck (they are MISRA's copyright), so rules
are named by number; ASSURANCE.md gives their headlines.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

# The same C tokenizer as the mutants (comments and ACSL skipped); mutants.py is
# beside this script, and a script's folder is first on its path.
from mutants import tokenize

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..'))


def function_of_lines(path):
    src = open(path, encoding='utf-8', errors='replace').read()
    funcs = {}
    for t in tokenize(src):
        if t.func:
            line = src.count('\n', 0, t.start) + 1
            funcs.setdefault(line, t.func)
    return funcs


def run_cppcheck(files, includes, defines):
    cmd = ['cppcheck', '--addon=misra', '--std=c99', '--quiet', '--inline-suppr',
           '--template={file}:{line}:{id}'] + ['-I' + i for i in includes] + \
          ['-D' + d for d in defines] + files
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    found = []
    for line in r.stderr.splitlines():
        m = re.match(r'(.+?):(\d+):(misra-c2012-[\d.]+)$', line)
        if m:
            found.append((os.path.relpath(os.path.join(ROOT, m.group(1)), ROOT), int(m.group(2)),
                          m.group(3).replace('misra-c2012-', '')))
        elif line.strip() and 'misra' not in line and 'Checking' not in line:
            print('cppcheck: ' + line, file=sys.stderr)
    return found


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('paths', nargs='+')
    ap.add_argument('--deviations')
    ap.add_argument('--count', action='store_true')
    ap.add_argument('-I', dest='includes', action='append', default=[])
    ap.add_argument('-D', dest='defines', action='append', default=[])
    ap.add_argument('--suite')
    a = ap.parse_args()
    files = []
    for p in a.paths:
        if not os.path.exists(os.path.join(ROOT, p)):
            continue
        if os.path.isdir(os.path.join(ROOT, p)):
            files += sorted(glob.glob(os.path.join(ROOT, p, '*.c')))
        else:
            files.append(os.path.join(ROOT, p))
    files = [os.path.relpath(f, ROOT) for f in files]
    if not files:
        print('misra: no C files in %s' % ' '.join(a.paths))
        return 0
    found = run_cppcheck(files, a.includes, a.defines)
    if a.count:
        rules = {}
        for f, _, r in found:
            rules[r] = rules.get(r, 0) + 1
        print('%s: %d MISRA C:2012 findings in %d files (%s)' % (
            ' '.join(a.paths), len(found), len(files),
            ', '.join('%s x%d' % kv for kv in sorted(rules.items(), key=lambda kv: -kv[1]))))
        return 0
    devs = []
    for line in open(a.deviations):
        if line.startswith('#') or not line.strip():
            continue
        parts = [p.strip() for p in line.split('|', 3)]
        if len(parts) != 4 or not parts[3]:
            print('misra: bad deviation line (want rule | file | function | reason): ' + line.strip())
            return 2
        devs.append(parts)
    funcs = {f: function_of_lines(os.path.join(ROOT, f)) for f in set(x[0] for x in found)}
    used = set()
    unrecorded = []
    for f, line, rule in sorted(found):
        # A function's header line lies just before its body's first token.
        fn = next((funcs[f][ln] for ln in range(line, line + 4) if ln in funcs[f]), '-')
        hit = [i for i, (r, df, dfn, _) in enumerate(devs) if r == rule and df == f and dfn in (fn, '*')]
        if hit:
            used.update(hit)
            print('deviation  %-6s %s:%d (%s): %s' % (rule, f, line, fn, devs[hit[0]][3]))
        else:
            unrecorded.append((rule, f, line, fn))
    for rule, f, line, fn in unrecorded:
        print('VIOLATION  %-6s %s:%d in %s: not in %s' % (rule, f, line, fn, a.deviations))
    stale = [d for i, d in enumerate(devs) if i not in used and d[1] in files]
    for d in stale:
        print('note: deviation no longer needed: %s' % ' | '.join(d[:3]))
    print('MISRA C:2012 (cppcheck %s) on %s: %d findings, %d recorded deviations (%d entries), %d unrecorded' % (
        subprocess.run(['cppcheck', '--version'], capture_output=True, text=True).stdout.split()[-1],
        ' '.join(files), len(found), len(found) - len(unrecorded), len(used), len(unrecorded)))
    if a.suite:
        os.makedirs(os.path.join(ROOT, 'build/results'), exist_ok=True)
        with open(os.path.join(ROOT, 'build/results', a.suite + '.txt'), 'w') as fh:
            fh.write('%d passed, %d failed\n' % (len(files), len(unrecorded)))
    return 1 if unrecorded else 0


if __name__ == '__main__':
    sys.exit(main())
