#!/usr/bin/env python3
"""Mutation testing of bsched/bsched.c (issue 15).

Generates mutants of the C code (never of the ACSL in comments, never of the
BSCHED_MUTANT_NO_REVERSE variant), skips those that do not compile, and runs
the cheapest killers first:

  1. unit    bsched/tests/test_bsched.c under ASan+UBSan (timeout = killed)
  2. cbmc    small-bound CBMC harnesses (errors, init, major_cycle, step)
  3. wp      Frama-C WP on the mutated function alone (its contract is what
             its callers rely on, so a mutant that still meets it is caught,
             if at all, by the other stages)

A mutant is identified by a key that survives edits elsewhere in the file:
function, operator, the mutated line's text before and after, and the
occurrence of that line text in the function. Survivors are compared with
assure/mutants-equivalent.txt (key | reason): a survivor that is not listed
there fails the run.

Why our own generator and not universalmutator: it mutates comments (our
ACSL contracts) and cannot tell code from the NO_REVERSE variant; a 300-line
tokenizer that knows both is easier to audit than filtering its output.

  mutants.py list                     print every mutant (key, line)
  mutants.py run [--sample N] [--stages unit,cbmc,wp] [--jobs J]
"""
import argparse
import concurrent.futures as cf
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..'))
SRC = os.path.join(ROOT, 'bsched', 'bsched.c')
EQUIV = os.path.join(ROOT, 'assure', 'mutants-equivalent.txt')

TYPE_WORDS = {'uint8_t', 'uint16_t', 'uint32_t', 'int32_t', 'int', 'size_t', 'const',
              'struct', 'unsigned', 'static', 'char', 'void', 'long', 'short'}
REL = ['<', '<=', '>', '>=', '==', '!=']
ARITH = ['+', '-', '*', '/', '%']
# Binary operator precedence (higher binds tighter), for operand swaps.
PREC = {'*': 10, '/': 10, '%': 10, '+': 9, '-': 9, '<<': 8, '>>': 8,
        '<': 7, '<=': 7, '>': 7, '>=': 7, '==': 6, '!=': 6, '&': 5, '^': 4,
        '|': 3, '&&': 2, '||': 1}
NON_COMMUTATIVE = {'-', '/', '%', '<<', '>>', '<', '<=', '>', '>='}

TOKEN_RE = re.compile(r'''
    (?P<ws>\s+)
  | (?P<comment>/\*.*?\*/|//[^\n]*)
  | (?P<pp>\#[^\n]*)
  | (?P<num>0[xX][0-9a-fA-F]+[uUlL]*|\d+[uUlL]*)
  | (?P<id>[A-Za-z_]\w*)
  | (?P<str>"(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*')
  | (?P<op>->|\+\+|--|<<=|>>=|<<|>>|<=|>=|==|!=|&&|\|\||[-+*/%&|^]=|[-+*/%<>=!~&|^?:;,.(){}\[\]])
''', re.S | re.X)


class Tok:
    __slots__ = ('kind', 'text', 'start', 'end', 'func', 'depth', 'pdepth')

    def __init__(self, kind, text, start, end):
        self.kind, self.text, self.start, self.end = kind, text, start, end
        self.func, self.depth, self.pdepth = None, 0, 0


def tokenize(src):
    """Code tokens with their function, brace depth and paren depth. Skips
    comments (the ACSL), preprocessor lines, and the lines between
    #ifdef BSCHED_MUTANT_NO_REVERSE and its #else/#endif."""
    skip = []          # (start, end) byte ranges that are not mutated
    pos = 0
    in_mutant = None
    for line in src.splitlines(keepends=True):
        s = line.strip()
        if s.startswith('#'):
            skip.append((pos, pos + len(line)))
            if s.startswith('#ifdef BSCHED_MUTANT'):
                in_mutant = pos
            elif in_mutant is not None and (s.startswith('#else') or s.startswith('#endif')):
                skip.append((in_mutant, pos + len(line)))
                in_mutant = None
        pos += len(line)
    toks = []
    i = 0
    while i < len(src):
        m = TOKEN_RE.match(src, i)
        if not m:
            raise SystemExit('mutants.py: cannot tokenize at offset %d: %r' % (i, src[i:i + 20]))
        i = m.end()
        kind = m.lastgroup
        if kind in ('ws', 'comment', 'pp'):
            continue
        if any(a <= m.start() < b for a, b in skip):
            continue
        toks.append(Tok(kind, m.group(), m.start(), m.end()))
    # Functions: at brace depth 0, `name ( ... ) {` opens the body of `name`.
    depth = pdepth = 0
    func = None
    for k, t in enumerate(toks):
        if t.text == '{':
            if depth == 0:
                j = k - 1
                if toks[j].text == ')':
                    lvl = 0
                    while j >= 0:
                        if toks[j].text == ')':
                            lvl += 1
                        elif toks[j].text == '(':
                            lvl -= 1
                            if lvl == 0:
                                break
                        j -= 1
                    func = toks[j - 1].text if j > 0 and toks[j - 1].kind == 'id' else None
            depth += 1
        elif t.text == '}':
            depth -= 1
            if depth == 0:
                t.func, t.depth = func, 1
                func = None
                continue
        elif t.text == '(':
            pdepth += 1
        elif t.text == ')':
            pdepth -= 1
        t.func, t.depth, t.pdepth = func, depth, pdepth
    return toks


def is_operand_end(t):
    return t.kind in ('id', 'num') or t.text in (')', ']')


def match_paren(toks, k, step):
    """Index of the bracket matching toks[k] going in direction step (+1/-1)."""
    open_, close = ('(', ')') if toks[k].text in '()' else ('[', ']')
    lvl = 0
    j = k
    while 0 <= j < len(toks):
        if toks[j].text == (open_ if step > 0 else close):
            lvl += 1
        elif toks[j].text == (close if step > 0 else open_):
            lvl -= 1
            if lvl == 0:
                return j
        j += step
    return None


def operand_left(toks, k):
    """Start index of the primary expression ending just before toks[k]."""
    j = k - 1
    while j >= 0:
        t = toks[j]
        if t.text in (')', ']'):
            j = match_paren(toks, j, -1)
            if j is None:
                return None
            if toks[j].text == '[' or (j > 0 and toks[j - 1].kind == 'id' and toks[j - 1].text not in
                                       ('if', 'while', 'for', 'return', 'sizeof')):
                j -= 1          # a subscript or a call: the name before it belongs to it
                continue
            break
        if t.kind in ('id', 'num'):
            if j > 0 and toks[j - 1].text in ('->', '.'):
                j -= 2
                continue
            break
        return None
    # A cast directly before: (type)
    if j >= 3 and toks[j - 1].text == ')' and toks[j - 2].text in TYPE_WORDS and toks[j - 3].text == '(':
        j -= 3
    return j


def operand_right(toks, k):
    """End index (inclusive) of the primary expression starting just after toks[k]."""
    j = k + 1
    if j + 2 < len(toks) and toks[j].text == '(' and toks[j + 1].text in TYPE_WORDS and toks[j + 2].text == ')':
        j += 3
    if j >= len(toks):
        return None
    if toks[j].text == '(':
        j = match_paren(toks, j, +1)
    elif toks[j].kind not in ('id', 'num'):
        return None
    while j is not None and j + 1 < len(toks):
        n = toks[j + 1]
        if n.text in ('->', '.') and j + 2 < len(toks):
            j += 2
        elif n.text in ('[', '(') and toks[j].kind == 'id' or n.text == '[':
            j = match_paren(toks, j + 1, +1)
        else:
            break
    return j


def line_of(src, off):
    a = src.rfind('\n', 0, off) + 1
    b = src.find('\n', off)
    return a, (len(src) if b < 0 else b)


def generate(src):
    toks = tokenize(src)
    out = []

    def add(op, start, end, repl, t):
        out.append({'op': op, 'start': start, 'end': end, 'repl': repl, 'func': t.func})

    for k, t in enumerate(toks):
        if t.func is None or t.depth < 1:
            continue
        prev = toks[k - 1] if k else None
        binary = prev is not None and is_operand_end(prev)
        if t.text in REL:
            for r in REL:
                if r != t.text:
                    add('ror', t.start, t.end, r, t)
        elif t.text in ARITH and binary:
            for r in ARITH:
                if r != t.text:
                    add('aor', t.start, t.end, r, t)
        elif t.text in ('<<', '>>'):
            add('sor', t.start, t.end, '>>' if t.text == '<<' else '<<', t)
        elif t.text in ('&&', '||'):
            add('lcr', t.start, t.end, '||' if t.text == '&&' else '&&', t)
        elif t.text in ('++', '--'):
            add('incr', t.start, t.end, '--' if t.text == '++' else '++', t)
        elif t.text in ('+=', '-='):
            add('asr', t.start, t.end, '-=' if t.text == '+=' else '+=', t)
        elif t.kind == 'num':
            m = re.match(r'(0[xX][0-9a-fA-F]+|\d+)(\w*)$', t.text)
            v = int(m.group(1), 0)
            add('const+1', t.start, t.end, '%d%s' % (v + 1, m.group(2)), t)
            if v > 0:
                add('const-1', t.start, t.end, '%d%s' % (v - 1, m.group(2)), t)
        # Negated conditions of if / while / for.
        if t.text in ('if', 'while') and k + 1 < len(toks) and toks[k + 1].text == '(':
            e = match_paren(toks, k + 1, +1)
            a, b = toks[k + 2].start, toks[e - 1].end
            add('neg', a, b, '!(' + src[a:b] + ')', t)
        if t.text == 'for' and toks[k + 1].text == '(':
            e = match_paren(toks, k + 1, +1)
            semis = [j for j in range(k + 2, e) if toks[j].text == ';' and toks[j].pdepth == toks[k + 1].pdepth + 0]
            if len(semis) == 2 and semis[1] > semis[0] + 1:
                a, b = toks[semis[0] + 1].start, toks[semis[1] - 1].end
                add('neg', a, b, '!(' + src[a:b] + ')', t)
        # Operand swaps of non-commutative binary operators.
        if t.text in NON_COMMUTATIVE and binary:
            lo, hi = operand_left(toks, k), operand_right(toks, k)
            if lo is not None and hi is not None:
                before = toks[lo - 1].text if lo > 0 else ';'
                after = toks[hi + 1].text if hi + 1 < len(toks) else ';'
                p = PREC[t.text]
                # Swap only when the neighbours bind less tightly than t.
                if PREC.get(before, 0) < p and PREC.get(after, 0) < p and \
                        before not in ('!', '~', '-', '*', '&') or before in ('(', ',', '=', 'return'):
                    if PREC.get(after, 0) < p:
                        ls, le = toks[lo].start, toks[k - 1].end
                        rs, re_ = toks[k + 1].start, toks[hi].end
                        add('swap', ls, re_, src[rs:re_] + ' ' + t.text + ' ' + src[ls:le], t)
        # Deleted statements: expression statements in function bodies.
        if (prev is None or prev.text in (';', '{', '}')) and t.pdepth == 0 and \
                t.text not in TYPE_WORDS and t.text not in ('for', 'if', 'while', 'else', '{', '}', ';', 'do'):
            j = k
            while j < len(toks) and not (toks[j].text == ';' and toks[j].pdepth == 0):
                j += 1
            if j < len(toks) and toks[j].func == t.func:
                add('del', t.start, toks[j].end, ';', t)
    # Keys that survive edits elsewhere: function, operator, line before/after,
    # and the occurrence of that (function, line text) pair.
    mutants = []
    seen_text = set()
    occ = {}
    for m in out:
        a, b = line_of(src, m['start'])
        a2, b2 = line_of(src, m['end'] - 1 if m['end'] > m['start'] else m['start'])
        before_line = ' '.join(src[a:max(b, b2)].split())
        mutated = src[:m['start']] + m['repl'] + src[m['end']:]
        after_line = ' '.join(mutated[a:max(b, b2) + len(m['repl']) - (m['end'] - m['start'])].split())
        if mutated in seen_text or mutated == src:
            continue
        seen_text.add(mutated)
        base = '%s | %s | %s -> %s' % (m['func'], m['op'], before_line, after_line)
        occ[base] = occ.get(base, 0) + 1
        key = base if occ[base] == 1 else '%s #%d' % (base, occ[base])
        mutants.append({'key': key, 'func': m['func'], 'op': m['op'],
                        'line': src.count('\n', 0, m['start']) + 1,
                        'hash': hashlib.sha1(key.encode()).hexdigest()[:10],
                        'text': mutated})
    return mutants


# ---------------------------------------------------------------- stages

HOST_CC = os.environ.get('HOST_CC', 'cc')
SAN_FLAGS = ['-fsanitize=address,undefined', '-fno-sanitize-recover=all', '-fno-omit-frame-pointer']
UNIT_TIMEOUT = 20


def write_mutant(work, m):
    d = os.path.join(work, m['hash'])
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, 'bsched.c')
    with open(path, 'w') as f:
        f.write(m['text'])
    return d, path


def test_programs():
    """Every bsched/tests/test_*.c (each a cmocka program), with the sources it needs
    besides bsched.c: for each header it includes that lives under bsched/ (bsched.h
    aside), that header's directory (-I) and the .c file of the same name beside it.
    A program that does not build or pass against the original bsched.c is left out
    (and said so)."""
    tdir = os.path.join(ROOT, 'bsched', 'tests')
    headers = {}
    for d, _, files in os.walk(os.path.join(ROOT, 'bsched')):
        for f in files:
            if f.endswith('.h'):
                headers.setdefault(f, d)
    progs = []
    for f in sorted(os.listdir(tdir)):
        if not (f.startswith('test_') and f.endswith('.c')):
            continue
        path = os.path.join(tdir, f)
        incs, extra = [], []
        for h in re.findall(r'#include\s+"([^"]+)"', open(path).read()):
            base = os.path.basename(h)
            if base == 'bsched.h' or base not in headers:
                continue
            d = headers[base]
            incs.append('-I' + d)
            c = os.path.join(d, base[:-2] + '.c')
            if os.path.exists(c) and os.path.abspath(c) != SRC:
                extra.append(c)
        progs.append((f[:-2], path, incs, extra))
    return progs


def build_test(prog, bsched_c, exe):
    name, path, incs, extra = prog
    cmd = [HOST_CC, '-std=c99', '-O1', '-g', '-w', '-Werror=return-type',
           '-Werror=implicit-function-declaration', '-I' + os.path.join(ROOT, 'bsched')] + incs + \
          ['-DBSCHED_MAX_PROCS=4096'] + SAN_FLAGS + ['-o', exe, path] + extra + [bsched_c, '-lcmocka']
    return subprocess.run(cmd, capture_output=True, text=True)


TESTS = []


def baseline(work):
    """The test programs that build and pass on the original bsched.c."""
    d = os.path.join(work, 'original')
    os.makedirs(d, exist_ok=True)
    env = dict(os.environ, ASAN_OPTIONS='detect_leaks=0')
    for prog in test_programs():
        exe = os.path.join(d, prog[0])
        r = build_test(prog, SRC, exe)
        if r.returncode != 0:
            print('mutants: left out %s: does not build against the original (%s)' % (prog[0], r.stderr[-200:]))
            continue
        try:
            ok = subprocess.run([exe], capture_output=True, env=env, timeout=UNIT_TIMEOUT).returncode == 0
        except subprocess.TimeoutExpired:
            ok = False
        if not ok:
            print('mutants: left out %s: fails on the original bsched.c' % prog[0])
            continue
        TESTS.append(prog)
    print('mutants: unit stage runs %s' % ', '.join(p[0] for p in TESTS))


def stage_compile(work, m):
    """Builds every test program against the mutant."""
    d, path = write_mutant(work, m)
    for prog in TESTS:
        r = build_test(prog, path, os.path.join(d, prog[0]))
        if r.returncode != 0:
            return False, r.stderr[-400:]
    return True, ''


def stage_unit(work, m):
    d = os.path.join(work, m['hash'])
    env = dict(os.environ, ASAN_OPTIONS='detect_leaks=0', UBSAN_OPTIONS='halt_on_error=1')
    for prog in TESTS:
        name = prog[0]
        try:
            r = subprocess.run([os.path.join(d, name)], capture_output=True, text=True,
                               timeout=UNIT_TIMEOUT, env=env)
        except subprocess.TimeoutExpired:
            return True, '%s: timeout %d s' % (name, UNIT_TIMEOUT)
        if r.returncode == 0:
            continue
        failed = re.findall(r'\[  FAILED  \] (\w+)', r.stdout)
        san = re.search(r'(runtime error: [^\n]*|ERROR: AddressSanitizer: [\w-]+)', r.stderr + r.stdout)
        why = ', '.join(sorted(set(f for f in failed if f != 'test'))) or \
            (san.group(1) if san else 'exit %d' % r.returncode)
        return True, '%s: %s' % (name, why)
    return False, ''


# CBMC and WP runs take the machine's shared lock, unless the caller holds it
# already for the whole proof stage (MUTANTS_LOCKED=1: one wait, not one per run).
LOCK = [] if os.environ.get('MUTANTS_LOCKED') else ['flock', '/tmp/bsched-heavy.lock']

# Small bounds: each run takes seconds, and all harness properties are checked.
CBMC_RUNS = [
    ('errors', {'N': '4'}),
    ('init', {'N': '4', 'P': '3', 'ORDERS': 'any'}),
    ('major_cycle', {'N': '4', 'P': '3'}),
    ('step', {'N': '5', 'P': '3'}),
]


def stage_cbmc(work, m):
    d, path = write_mutant(work, m)
    for harness, bounds in CBMC_RUNS:
        hdir = os.path.join(ROOT, 'bsched/proofs/cbmc', harness)
        out = os.path.join(d, 'cbmc-' + harness)
        args = ['make', '--no-print-directory', '-C', hdir, 'OUT=' + out,
                'SOURCES=%s/%s_harness.c %s' % (hdir, harness, path)] + \
               ['%s=%s' % kv for kv in bounds.items()]
        r = subprocess.run(LOCK + args, capture_output=True, text=True)
        res = ''
        try:
            res = open(os.path.join(out, 'result.txt')).read().strip()
        except OSError:
            res = 'no result (make exited %d)' % r.returncode
        if not res.startswith('PASS'):
            log = os.path.join(out, 'cbmc.log')
            failed = []
            if os.path.exists(log):
                failed = re.findall(r'^\[([^\]]+)\] .*: FAILURE$', open(log).read(), re.M)
            return True, '%s: %s' % (harness, ', '.join(failed[:3]) or res[:120])
    return False, ''


def wp_flags():
    r = subprocess.run(['make', '--no-print-directory', '-s', '-C', ROOT,
                        '--eval', 'print-wp-flags: ; @echo $(WP_FLAGS)', 'print-wp-flags'],
                       capture_output=True, text=True)
    return r.stdout.strip()


def stage_wp(work, m):
    d, path = write_mutant(work, m)
    log = os.path.join(d, 'wp.log')
    cmd = ' '.join(LOCK) + ' frama-c %s -wp-par 2 -wp-fct %s %s > %s 2>&1' % (
        wp_flags(), m['func'], path, log)
    tools = os.environ.get('BSCHED_TOOLS') or os.path.join(
        os.environ.get('XDG_CACHE_HOME') or os.path.expanduser('~/.cache'), 'bsched')
    env = dict(os.environ, WHY3CONFIG=os.path.join(tools, 'why3', 'why3.conf'))
    subprocess.run(cmd, shell=True, cwd=ROOT, env=env)
    text = open(log).read()
    g = re.search(r'Proved goals:\s*(\d+)\s*/\s*(\d+)', text)
    if not g:
        return True, 'frama-c rejects it: ' + ' '.join(text.splitlines()[-2:])[:150]
    if g.group(1) != g.group(2):
        return True, 'WP %s/%s goals of %s' % (g.group(1), g.group(2), m['func'])
    return False, 'WP %s/%s' % (g.group(1), g.group(2))


def load_equivalent():
    eq = {}
    if os.path.exists(EQUIV):
        for line in open(EQUIV):
            if line.startswith('#') or not line.strip():
                continue
            key, _, reason = line.rstrip('\n').rpartition(' || ')
            eq[key.strip()] = reason.strip()
    return eq


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('cmd', choices=['list', 'run', 'tests'])
    ap.add_argument('--sample', type=int, default=0, help='only N mutants, a fixed sample by key hash')
    ap.add_argument('--stages', default='unit,cbmc,wp')
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--out', default=os.path.join(ROOT, 'build/mutants'))
    ap.add_argument('--suite', help='write build/results/SUITE.txt')
    ap.add_argument('--only-survivors-of', metavar='REPORT',
                    help='re-run only the mutants a previous report lists as survivors')
    a = ap.parse_args()
    if a.cmd == 'tests':   # the unit test programs and what they need (assure/bigendian.sh)
        for name, path, incs, extra in test_programs():
            print('%s|%s|%s|%s' % (name, os.path.relpath(path, ROOT), ' '.join(incs),
                                   ' '.join(os.path.relpath(e, ROOT) for e in extra)))
        return 0
    src = open(SRC).read()
    muts = generate(src)
    if a.cmd == 'list':
        for m in muts:
            print('%4d %s %s' % (m['line'], m['hash'], m['key']))
        print('%d mutants' % len(muts), file=sys.stderr)
        return 0
    if a.sample:
        muts = sorted(muts, key=lambda m: m['hash'])[:a.sample]
    if a.only_survivors_of:
        prev = json.load(open(a.only_survivors_of))
        keep = {r['key'] for r in prev['mutants'] if r['killed_by'] is None}
        muts = [m for m in muts if m['key'] in keep]
    stages = a.stages.split(',')
    work = os.path.join(a.out, 'work')
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    t0 = time.time()
    baseline(work)
    if not TESTS:
        print('mutants: no test program builds and passes on the original bsched.c')
        return 1
    results = {}

    def first(m):
        ok, err = stage_compile(work, m)
        if not ok:
            return m, 'uncompilable', err
        if 'unit' in stages:
            killed, why = stage_unit(work, m)
            if killed:
                return m, 'unit', why
        return m, None, ''

    with cf.ThreadPoolExecutor(a.jobs) as ex:
        for m, by, why in ex.map(first, muts):
            results[m['key']] = (m, by, why)
    timing = {'unit': time.time() - t0}
    global LOCK
    if LOCK and any(r[1] is None for r in results.values()) and ('cbmc' in stages or 'wp' in stages):
        import fcntl
        lock = open('/tmp/bsched-heavy.lock', 'a')
        t1 = time.time()
        deadline = float(os.environ.get('MUTANTS_LOCK_DEADLINE', '0'))  # epoch seconds, 0: wait
        while True:                        # held until exit: one wait for all proof runs
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | (fcntl.LOCK_NB if deadline else 0))
                break
            except BlockingIOError:
                if time.time() > deadline:
                    print('mutants: the heavy lock was not free before the deadline; proof stages skipped')
                    stages = [st for st in stages if st not in ('cbmc', 'wp')]
                    break
                time.sleep(5)
        timing['lock wait'] = time.time() - t1
        LOCK = []
    for st, fn in (('cbmc', stage_cbmc), ('wp', stage_wp)):
        if st not in stages:
            continue
        t1 = time.time()
        for key, (m, by, why) in results.items():
            if by is None:
                killed, w = fn(work, m)
                if killed:
                    results[key] = (m, st, w)
        timing[st] = time.time() - t1
    eq = load_equivalent()
    compiled = [r for r in results.values() if r[1] != 'uncompilable']
    killed = [r for r in compiled if r[1] is not None]
    survivors = [r for r in compiled if r[1] is None]
    unexplained = [r for r in survivors if r[0]['key'] not in eq]
    by_stage = {}
    for r in killed:
        by_stage[r[1]] = by_stage.get(r[1], 0) + 1
    os.makedirs(a.out, exist_ok=True)
    report = {'source': 'bsched/bsched.c', 'generated': len(results),
              'uncompilable': len(results) - len(compiled), 'compiled': len(compiled),
              'killed': len(killed), 'killed_by': by_stage,
              'survivors_equivalent': len(survivors) - len(unexplained),
              'survivors_unexplained': len(unexplained), 'seconds': timing, 'stages': stages,
              'mutants': [{'key': m['key'], 'line': m['line'], 'hash': m['hash'], 'op': m['op'],
                           'killed_by': by, 'why': why,
                           'equivalent': eq.get(m['key']) if by is None else None}
                          for m, by, why in results.values()]}
    name = 'sample' if a.sample else 'partial' if a.only_survivors_of else 'full'
    with open(os.path.join(a.out, 'report-%s.json' % name), 'w') as f:
        json.dump(report, f, indent=1)
    for m, by, why in sorted(results.values(), key=lambda r: r[0]['line']):
        if by is None:
            tag = 'EQUIVALENT' if m['key'] in eq else 'SURVIVED'
            print('%-10s line %4d %s\n           %s' % (tag, m['line'], m['key'],
                                                     eq.get(m['key'], 'no test, proof or reason kills it')))
    print('mutants of bsched.c: %d generated, %d do not compile, %d compiled' %
          (len(results), report['uncompilable'], len(compiled)))
    print('killed %d / %d (%s); survivors: %d equivalent (assure/mutants-equivalent.txt), %d unexplained' %
          (len(killed), len(compiled), ', '.join('%s %d' % kv for kv in sorted(by_stage.items())),
           report['survivors_equivalent'], len(unexplained)))
    print('time: ' + ', '.join('%s %.0f s' % kv for kv in timing.items()))
    if a.suite:
        os.makedirs(os.path.join(ROOT, 'build/results'), exist_ok=True)
        with open(os.path.join(ROOT, 'build/results', a.suite + '.txt'), 'w') as f:
            f.write('%d passed, %d failed\n' % (len(compiled) - len(unexplained), len(unexplained)))
    return 1 if unexplained else 0


if __name__ == '__main__':
    sys.exit(main())
