#!/usr/bin/env python3
"""Mutation testing of bsched/bsched.c.

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
# A mutant that makes a test program hang is killed by a timeout: 20x the time the
# program took on the original bsched.c, at least UNIT_TIMEOUT s (both measured on the
# same, possibly loaded, machine, so the margin holds under load). The original gets
# BASELINE_TIMEOUT s.
UNIT_TIMEOUT = 20
BASELINE_TIMEOUT = 600
TIMEOUTS = {}


def write_mutant(work, m):
    d = os.path.join(work, m['hash'])
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, 'bsched.c')
    try:
        same = open(path).read() == m['text']
    except OSError:
        same = False
    if not same:                      # an unchanged file keeps its time: builds are reused
        with open(path, 'w') as f:
            f.write(m['text'])
    return d, path


def newest_input(prog):
    """Newest modification time of what a test program is built from, besides the mutant."""
    name, path, incs, extra = prog
    files = [path] + extra
    for inc in incs + ['-I' + os.path.join(ROOT, 'bsched')]:
        d = inc[2:]
        files += [os.path.join(d, f) for f in os.listdir(d) if f.endswith('.h')]
    return max(os.path.getmtime(f) for f in files)


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
        t0 = time.time()
        try:
            r = subprocess.run([exe], capture_output=True, text=True, env=env, timeout=BASELINE_TIMEOUT)
            ok, why = r.returncode == 0, 'exit %d: %s' % (r.returncode, (r.stdout + r.stderr)[-300:])
        except subprocess.TimeoutExpired:
            ok, why = False, 'timeout %d s' % BASELINE_TIMEOUT
        if not ok:
            print('mutants: left out %s: fails on the original bsched.c (%s)' % (prog[0], why))
            continue
        TIMEOUTS[prog[0]] = max(UNIT_TIMEOUT, 20 * (time.time() - t0))
        TESTS.append(prog)
    print('mutants: unit stage runs %s' % ', '.join('%s (timeout %.0f s)' % (p[0], TIMEOUTS[p[0]]) for p in TESTS))


def stage_compile(work, m):
    """Builds every test program against the mutant."""
    d, path = write_mutant(work, m)
    for prog in TESTS:
        exe = os.path.join(d, prog[0])
        if os.path.exists(exe) and os.path.getmtime(exe) > max(os.path.getmtime(path), newest_input(prog)):
            continue                  # built from this very mutant and these sources before
        r = build_test(prog, path, exe)
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
                               timeout=TIMEOUTS[name], env=env)
        except subprocess.TimeoutExpired:
            return True, '%s: timeout %d s' % (name, TIMEOUTS[name])
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
        try:
            res = open(os.path.join(out, 'result.txt')).read().strip()
        except OSError:
            # The harness did not run (a build or set-up failure): no verdict, not a kill.
            return 'error', '%s: no result (make exited %d): %s' % (
                harness, r.returncode, ' '.join((r.stdout + r.stderr).split())[-200:])
        if not res.startswith('PASS'):
            log = os.path.join(out, 'cbmc.log')
            failed = []
            if os.path.exists(log):
                failed = re.findall(r'^\[([^\]]+)\] .*: FAILURE$', open(log).read(), re.M)
            return True, '%s: %s' % (harness, ', '.join(failed[:3]) or res[:120])
    return False, ''


def make_vars(*names):
    """Values of make variables of the top Makefile (WP_FLAGS, WHY3CONFIG, ...)."""
    rule = 'print-vars: ; @' + ' && '.join('echo "$(%s)"' % n for n in names)
    r = subprocess.run(['make', '--no-print-directory', '-s', '-C', ROOT, '--eval', rule, 'print-vars'],
                       capture_output=True, text=True)
    values = r.stdout.split('\n')
    return [v.strip() for v in values[:len(names)]]


# A WP goal line: [wp] [Prover] Goal NAME : STATUS (...); after [Failed], one line per prover.
WP_GOAL = re.compile(r'^\[wp\] \[(?P<prover>[^\]]+)\] Goal (?P<goal>\S+)(?: : (?P<status>[A-Za-z ]+?))?(?: \(.*)?$')
WP_ATTEMPT = re.compile(r'^  (?P<prover>[A-Za-z][^:]*): (?P<status>[A-Za-z ]+?)(?: \(.*)?$')


def wp_failures(text):
    """Goals WP did not prove, each with what every prover said:
    [(goal, ['CVC4 1.8: Step limit', ...])]."""
    failed, cur = [], None
    for line in text.splitlines():
        m = WP_GOAL.match(line)
        if m:
            cur = None
            if m.group('prover') == 'Failed' or (m.group('status') or 'Valid') != 'Valid':
                cur = (m.group('goal'), [] if m.group('prover') == 'Failed'
                       else ['%s: %s' % (m.group('prover'), m.group('status'))])
                failed.append(cur)
            continue
        a = WP_ATTEMPT.match(line)
        if a and cur is not None:
            cur[1].append('%s: %s' % (a.group('prover'), a.group('status')))
    return failed


WP_PAR = 2   # provers at a time in the WP stage (--proof-jobs)

# What the WP stage takes from make (wp.mk): its flags, provers and both step limits (part
# of the cache key), and where why3.conf lies (not: why3-config.sh, which writes it, is in
# the digest of the stage's inputs).
WP_VERDICT_VARS = ('WP_FLAGS', 'WP_PROVERS', 'WP_STEPS_Z3')
WP_STAGE_VARS = WP_VERDICT_VARS + ('WHY3CONFIG',)


# Functions make prove leaves out (-wp-skip-fct in wp.mk): WP says nothing about them.
WP_NOT_PROVEN = {'bsched_run_cycle'}


def stage_wp(work, m):
    """WP on the mutated function alone, with make prove's flags (step limits
    included). A goal that some prover lost only by the wall-clock timeout is a
    kill that depends on the machine's speed: it is reported as such ('timeout')."""
    if m['func'] in WP_NOT_PROVEN:
        return False, 'not in the WP proof (bsched/proofs/README.md, Not proven)'
    d, path = write_mutant(work, m)
    log = os.path.join(d, 'wp.log')
    flags, provers, steps_z3, why3config = make_vars(*WP_STAGE_VARS)
    cmd = ' '.join(LOCK) + ' frama-c %s -wp-prover %s -wp-par %d -wp-fct %s %s > %s 2>&1' % (
        flags, provers, WP_PAR, m['func'], path, log)
    # Z3's step limit reaches it through the environment (prover-steps.sh); make exports it
    # to its recipes, but this script may be run by hand: it is set here either way.
    subprocess.run(cmd, shell=True, cwd=ROOT,
                   env=dict(os.environ, WHY3CONFIG=why3config, WP_STEPS_Z3=steps_z3))
    text = open(log).read()
    g = re.search(r'Proved goals:\s*(\d+)\s*/\s*(\d+)', text)
    if not g:
        return True, 'frama-c rejects it: ' + ' '.join(text.splitlines()[-2:])[:150]
    if g.group(1) == g.group(2):
        return False, 'WP %s/%s' % (g.group(1), g.group(2))
    failed = wp_failures(text)
    # The kill is load-independent if some goal failed with no prover stopped by the clock.
    timeouts = [f for f in failed if any(a.endswith('Timeout') for a in f[1])]
    steady = [f for f in failed if f not in timeouts]
    first = failed[0] if failed else ('?', [])
    why = 'WP %s/%s goals of %s; not proven: %s (%s)%s' % (
        g.group(1), g.group(2), m['func'], first[0].replace('typed_', ''), ', '.join(first[1]),
        ' and %d more' % (len(failed) - 1) if len(failed) > 1 else '')
    if timeouts and not steady:
        why += '; every one hit the wall-clock timeout (load-dependent)'
    elif timeouts:
        why += '; %d of them hit the wall-clock backstop, the others not' % len(timeouts)
    return True, why


# The proof stages' verdicts are kept in CACHE, one file per stage and digest of
# everything the verdict depends on: the mutant's text, the stage's settings (CBMC
# bounds, WP flags) and every file of the specification and of the stage's own folder
# (bsched/proofs/cbmc or bsched/proofs/wp). A re-run
# (after the unit stage is re-done, say) then costs nothing for an unchanged mutant.
CACHE = os.path.join(ROOT, 'build', 'mutants', 'cache')


PROOF_INPUTS = {'cbmc': ('bsched/spec', 'bsched/proofs/cbmc'), 'wp': ('bsched/spec', 'bsched/proofs/wp')}
# wp.mk reaches the WP stage only through the make variables it sets (WP_VERDICT_VARS, part
# of the stage's settings): its other lines (make prove's runs and hints) change no verdict.
PROOF_INPUTS_SKIP = {'wp': ('wp.mk',)}


def proof_inputs_digest(stage):
    h = hashlib.sha1()
    for d in PROOF_INPUTS[stage]:
        for base, _, files in sorted(os.walk(os.path.join(ROOT, d))):
            for f in sorted(files):
                if f in PROOF_INPUTS_SKIP.get(stage, ()):
                    continue
                if f.endswith(('.c', '.h', '.mk', '.sh', '.drv', 'Makefile', '.common')):
                    h.update(f.encode())
                    h.update(open(os.path.join(base, f), 'rb').read())
    h.update(open(os.path.join(ROOT, 'bsched', 'bsched.h'), 'rb').read())
    return h.hexdigest()


def cached(stage, fn, settings):
    """fn wrapped with the verdict cache: fn(work, m) -> (killed, why)."""
    inputs = proof_inputs_digest(stage)

    def run(work, m):
        key = hashlib.sha1((stage + '\0' + settings() + '\0' + inputs + '\0' + m['text']).encode()).hexdigest()
        path = os.path.join(CACHE, '%s-%s.json' % (stage, key))
        if os.path.exists(path):
            r = json.load(open(path))
            return r['killed'], r['why'] + ' (cached)'
        killed, why = fn(work, m)
        if killed != 'error' and 'load-dependent' not in why and 'timeout' not in why:
            # (no verdict, or one that depends on the clock: not kept)
            os.makedirs(CACHE, exist_ok=True)
            with open(path, 'w') as f:
                json.dump({'killed': killed, 'why': why, 'key': m['key']}, f)
        return killed, why
    return run


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
    ap.add_argument('--proof-jobs', type=int, default=2,
                    help='CBMC: mutants at a time; WP: one mutant at a time, this many provers (-wp-par)')
    ap.add_argument('--out', default=os.path.join(ROOT, 'build/mutants'))
    ap.add_argument('--suite', help='write build/results/SUITE.txt')
    ap.add_argument('--only-survivors-of', metavar='REPORT',
                    help='re-run only the mutants a previous report lists as survivors')
    ap.add_argument('--match', metavar='REGEX', help='only the mutants whose key matches REGEX')
    ap.add_argument('--keys-from', metavar='FILE',
                    help='only the mutants with an entry in FILE (key || reason), e.g. the survivors')
    a = ap.parse_args()
    a.out = os.path.abspath(a.out)    # the CBMC stage runs make -C in each harness folder
    global WP_PAR
    WP_PAR = a.proof_jobs
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
    if a.match:
        muts = [m for m in muts if re.search(a.match, m['key'])]
    if a.keys_from:
        keys = {l.rpartition(' || ')[0].strip() for l in open(a.keys_from)
                if ' || ' in l and not l.startswith('#')}
        muts = [m for m in muts if m['key'] in keys]
    stages = a.stages.split(',')
    work = os.path.join(a.out, 'work')
    os.makedirs(work, exist_ok=True)   # kept: builds of unchanged mutants are reused
    t0 = time.time()
    baseline(work)
    if not TESTS:
        print('mutants: no test program builds and passes on the original bsched.c')
        return 1
    results = {}

    def first(m):
        if 'unit' not in stages:          # a proof-only run (--keys-from the survivors)
            return m, None, ''
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
    # Each proof stage gets what the cheaper ones left (one heavy lock for all), smaller
    # functions first. CBMC (one process a mutant) runs PROOF_JOBS mutants side by side;
    # WP runs one mutant at a time with PROOF_JOBS provers: two mutants side by side would
    # put twice as many provers on the cores, and a goal that a prover loses only to the
    # wall-clock backstop is no verdict (it was so for two bsched_init mutants). With
    # MUTANTS_STAGE_DEADLINE (epoch seconds) a stage starts no new mutant after it, and those
    # left are reported as not run (the cache keeps what was done: a re-run goes on from there).
    deadline = float(os.environ.get('MUTANTS_STAGE_DEADLINE', '0'))
    not_run = {}
    errors = {}
    size = {}
    for t in tokenize(src):
        size[t.func] = size.get(t.func, 0) + 1
    for st, fn in (('cbmc', cached('cbmc', stage_cbmc, lambda: json.dumps(CBMC_RUNS))),
                   ('wp', cached('wp', stage_wp, lambda: ' '.join(make_vars(*WP_VERDICT_VARS))))):
        if st not in stages:
            continue
        t1 = time.time()
        todo = sorted([r[0] for r in results.values() if r[1] is None and r[0]['key'] not in not_run],
                      key=lambda m: (size.get(m['func'], 0), m['line']))

        def one(m, st=st, fn=fn):
            if deadline and time.time() > deadline:
                return m, None, None
            killed, w = fn(work, m)
            print('mutants: %-4s %-8s line %4d %s: %s' % (st, 'ERROR' if killed == 'error' else
                                                       'killed' if killed else 'survived',
                                                       m['line'], m['key'][:90], w[:160]), flush=True)
            return m, killed, w
        with cf.ThreadPoolExecutor(1 if st == 'wp' else a.proof_jobs) as ex:
            for m, killed, w in ex.map(one, todo):
                if killed is None:
                    not_run[m['key']] = st
                elif killed == 'error':
                    errors[m['key']] = (st, w)
                    not_run[m['key']] = st
                elif killed:
                    results[m['key']] = (m, st, w)
        timing[st] = time.time() - t1
    for key, (st, w) in errors.items():
        print('mutants: ERROR in stage %s (no verdict): %s: %s' % (st, key, w))
    if not_run:
        print('mutants: %d mutants not run through every proof stage (%d errors, the rest '
              'MUTANTS_STAGE_DEADLINE)' % (len(not_run), len(errors)))
    eq = load_equivalent()
    compiled = [r for r in results.values() if r[1] != 'uncompilable']
    killed = [r for r in compiled if r[1] is not None]
    survivors = [r for r in compiled if r[1] is None]
    # Every survivor of the unit tests needs an entry (make check's sample runs the unit
    # stage only), also those a proof stage kills: the entry says which one.
    unit_survivors = [r for r in compiled if r[1] in (None, 'cbmc', 'wp')]
    unexplained = [r for r in unit_survivors if r[0]['key'] not in eq]
    proof_stages = [st for st in ('cbmc', 'wp') if st in stages]
    # With every proof stage run, each entry's claim is checked against what they said:
    # "killed by cbmc" / "killed by wp" (the first stage that kills it), else it survives.
    mismatched = []
    if proof_stages == ['cbmc', 'wp']:
        for m, by, why in unit_survivors:
            reason = eq.get(m['key'])
            if reason is None or m['key'] in not_run:
                continue
            # "killed by cbmc or wp": a proof stage kills it, which one first not yet measured
            claim = re.search(r'killed by (cbmc or wp|cbmc|wp)\b', reason, re.I)
            expect = claim.group(1).lower() if claim else None
            if not (expect == by or (expect == 'cbmc or wp' and by in ('cbmc', 'wp'))):
                mismatched.append((m, by, why, expect))
    by_stage = {}
    for r in killed:
        by_stage[r[1]] = by_stage.get(r[1], 0) + 1
    # Killed / tried per stage: each stage gets what the cheaper ones left.
    per_stage = []
    left = len(compiled)
    for st in stages:
        skipped = sum(1 for v in not_run.values() if v == st)
        per_stage.append({'stage': st, 'tried': left - skipped, 'killed': by_stage.get(st, 0),
                          'not_run': skipped, 'seconds': round(timing.get(st, 0.0))})
        left -= by_stage.get(st, 0) + skipped
    os.makedirs(a.out, exist_ok=True)
    report = {'source': 'bsched/bsched.c', 'generated': len(results),
              'uncompilable': len(results) - len(compiled), 'compiled': len(compiled),
              'killed': len(killed), 'killed_by': by_stage, 'per_stage': per_stage,
              'survivors_equivalent': len([r for r in survivors if r[0]['key'] in eq]),
              'survivors_unexplained': len(unexplained), 'entries_mismatched': len(mismatched),
              'not_run': not_run,
              'seconds': timing, 'stages': stages,
              'mutants': [{'key': m['key'], 'line': m['line'], 'hash': m['hash'], 'op': m['op'],
                           'killed_by': by, 'why': why, 'entry': eq.get(m['key'])}
                          for m, by, why in results.values()]}
    name = 'sample' if a.sample else 'partial' if a.only_survivors_of or a.match or a.keys_from else 'full'
    with open(os.path.join(a.out, 'report-%s.json' % name), 'w') as f:
        json.dump(report, f, indent=1)
    for m, by, why in sorted(unit_survivors, key=lambda r: r[0]['line']):
        entry = eq.get(m['key'])
        if entry is None:
            tag = 'SURVIVED' if by is None else 'NO ENTRY'
            entry = 'no test, proof or reason kills it' if by is None else \
                'killed by %s only (%s): add an entry "killed by %s: ..." for the unit-only sample' % (by, why, by)
        else:
            tag = 'EQUIVALENT' if by is None else 'KILLED-' + by.upper()
        print('%-11s line %4d %s\n            %s' % (tag, m['line'], m['key'], entry))
        if by is not None:
            print('            measured: %s' % why)
    for m, by, why, expect in mismatched:
        print('MISMATCH   line %4d %s\n            the entry says %s, measured %s%s' % (
            m['line'], m['key'], 'killed by ' + expect if expect else 'it survives every stage',
            'killed by ' + by if by else 'it survives every stage', ': ' + why if why else ''))
    print('mutants of bsched.c: %d generated, %d do not compile, %d compiled' %
          (len(results), report['uncompilable'], len(compiled)))
    for st in per_stage:
        print('  stage %-5s killed %3d of %3d (%d s)%s' % (st['stage'], st['killed'], st['tried'], st['seconds'],
                                                       ', %d not run' % st['not_run'] if st['not_run'] else ''))
    print('killed %d / %d (%s); survivors: %d with an entry (assure/mutants-equivalent.txt), '
          '%d without; %d entries contradicted by the proof stages' %
          (len(killed), len(compiled), ', '.join('%s %d' % kv for kv in sorted(by_stage.items())),
           report['survivors_equivalent'], len(unexplained), len(mismatched)))
    print('time: ' + ', '.join('%s %.0f s' % kv for kv in timing.items()))
    bad = len(unexplained) + len(mismatched) + len(not_run)
    if a.suite:
        os.makedirs(os.path.join(ROOT, 'build/results'), exist_ok=True)
        with open(os.path.join(ROOT, 'build/results', a.suite + '.txt'), 'w') as f:
            f.write('%d passed, %d failed\n' % (len(compiled) - bad, bad))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
