#!/usr/bin/env python3
"""Worst-case stack of every firmware thread and of the interrupt path.

For each image in apps/*, built with -fstack-usage -fcallgraph-info=su
(make stack builds them into build/assure/stack), this reads every .ci file
(GCC's call graph with each function's frame size), adds the assembly routines
and libgcc helpers that have no .ci (fixed sizes below), and walks the graph:

- a direct call adds the callee's frame plus the 4-byte return address;
- an indirect call (`__indirect_call`) may reach any function whose address
  the image takes (found from the relocations of the objects: a reference that
  is not the target of jsr/bsr/jmp), except thread entries, which only
  k_thread_start calls; so the bound is conservative;
- recursion (a cycle in the graph) makes the bound unknown: the check fails.

Threads come from the sources: every k_thread_create or board_spawn(..., ENTRY, ARG,
STACK, SIZE, ...) and k_bsched_start(..., STACK, SIZE) (its thread runs k_bsched_main),
plus the kernel's own idle and reporter threads; sizes from K_STACK_DEFINE and
the #defines. A thread's worst case is the trampoline, its entry's deepest
path, and IRQ_NESTING interrupt frames on top (the CPU32 takes interrupts on
the running thread's supervisor stack). It must fit in the stack it is given
minus the kernel's guard words.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..'))
CROSS = 'm68k-linux-gnu-'
RET = 4                      # return address of a jsr/bsr
# Routines without a .ci file: assembly (kernel/arch/cpu32/*.S) and libgcc.
ASM_FRAMES = {
    'k_arch_switch': 2 + 11 * 4,          # SR + d2-d7/a2-a6
    'k_isr_entry': 8 + 4 * 4 + 4,         # format-0 exception frame + d0-d1/a0-a1 + vector argument
    'k_arch_thread_trampoline': 0,
}
LIBGCC_FRAME = 32            # libgcc's m68k arithmetic helpers are leaves with small frames
# Interrupt levels that can nest on one stack (PIT and DUART on the reference board).
IRQ_NESTING_DEFAULT = 2


def parse_ci(paths):
    frames, edges, dynamic = {}, {}, set()
    for p in paths:
        for line in open(p, errors='replace'):
            m = re.match(r'node: \{ title: "([^"]+)" label: "[^"\\]*\\n[^"\\]*\\n(\d+) bytes \(([^)]*)\)"', line)
            if m:
                name, size, kind = m.group(1), int(m.group(2)), m.group(3)
                frames[name] = max(frames.get(name, 0), size)
                if kind == 'dynamic':
                    dynamic.add(name)
                continue
            m = re.match(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"', line)
            if m:
                edges.setdefault(m.group(1), set()).add(m.group(2))
    # Static functions are titled "file:name": one name, the largest frame, all edges.
    for title in list(frames):
        if ':' in title:
            plain = title.rsplit(':', 1)[1]
            frames[plain] = max(frames.get(plain, 0), frames[title])
            if title in dynamic:
                dynamic.add(plain)
    plain_edges = {}
    for src, targets in edges.items():
        plain = src.rsplit(':', 1)[1] if ':' in src else src
        plain_edges.setdefault(plain, set()).update(t.rsplit(':', 1)[1] if ':' in t else t for t in targets)
    return frames, plain_edges, dynamic


def address_taken(objs, edges):
    """Functions whose address is taken: a relocation to a function that is not
    the target of jsr/bsr/jmp/bra and not a callee GCC's call graph already has
    for the referencing function (at -Os GCC loads a callee it calls repeatedly
    into a register: `lea f,%a2` ... `jsr (%a2)` is a direct call)."""
    taken = set()
    for o in objs:
        out = subprocess.run([CROSS + 'objdump', '-dr', o], capture_output=True, text=True).stdout
        prev, func = '', None
        for line in out.splitlines():
            h = re.match(r'[0-9a-f]+ <([^>]+)>:$', line)
            if h:
                func = h.group(1)
                continue
            m = re.match(r'\s+[0-9a-f]+: R_68K_\w+\s+(\S+)', line)
            if m:
                sym = re.sub(r'\+0x[0-9a-f]+$', '', m.group(1))
                sym = re.sub(r'^\.text\.', '', sym)
                if not re.search(r"\s(jsr|bsr[lwsb]?|jbsr|jmp|jra|bra[lwsb]?)\s", prev) and \
                        sym not in edges.get(func, ()):
                    taken.add(sym)
            elif line.strip() and not re.match(r'\s+[0-9a-f]+:\s+([0-9a-f]{4}\s*)+$', line):
                prev = line       # an instruction (not the continuation of one's bytes)
        data = subprocess.run([CROSS + 'objdump', '-r', '-j', '.data', '-j', '.rodata', o],
                              capture_output=True, text=True).stdout
        for m in re.finditer(r'R_68K_32\s+(\S+)', data):
            taken.add(re.sub(r'^\.text\.', '', re.sub(r'\+0x[0-9a-f]+$', '', m.group(1))))
    return taken


def elf_functions(elf):
    out = subprocess.run([CROSS + 'nm', elf], capture_output=True, text=True).stdout
    return {l.split()[-1] for l in out.splitlines() if re.match(r'\S+ [tTW] ', l)}


def c_defines(sources):
    defs = {}
    for p in sources:
        for m in re.finditer(r'#\s*define\s+(\w+)\s+\(?([\w\s*+()/-]+?)\)?\s*(?:/\*.*)?$',
                             open(p, errors='replace').read(), re.M):
            defs.setdefault(m.group(1), m.group(2).strip())
    return defs


def evaluate(expr, defs, depth=0):
    expr = re.sub(r'\b(\d+)[uUlL]+\b', r'\1', expr)
    for _ in range(10):
        new = re.sub(r'\b([A-Za-z_]\w*)\b', lambda m: '(%s)' % defs[m.group(1)] if m.group(1) in defs else m.group(1), expr)
        new = re.sub(r'\b(\d+)[uUlL]+\b', r'\1', new)
        if new == expr:
            break
        expr = new
    expr = re.sub(r'K_STACK_WORDS\s*\(([^()]*(?:\([^()]*\))*[^()]*)\)', r'((\1 + 3) // 4)', expr)
    try:
        return int(eval(expr, {'__builtins__': {}}))
    except Exception:
        return None


def find_threads(sources, defs, linked):
    text = {p: re.sub(r'/\*.*?\*/', '', open(p, errors='replace').read(), flags=re.S) for p in sources}
    stacks = {}
    for p, t in text.items():
        for m in re.finditer(r'K_STACK_DEFINE\(\s*(\w+)\s*,\s*([^)]+?)\s*\)', t):
            stacks[m.group(1)] = evaluate(m.group(2), defs)
        for m in re.finditer(r'uint32_t\s+(\w+)\s*\[\s*(K_STACK_WORDS\([^;]*?\))\s*\]', t):
            words = evaluate(m.group(2), defs)
            stacks.setdefault(m.group(1), None if words is None else words * 4)

    def size_of(expr):
        m = re.match(r'sizeof\s*\(?\s*(?:\w+\s*(?:->|\.)\s*)?(\w+)\s*\)?$', expr.strip())
        if m and m.group(1) in stacks:
            return stacks[m.group(1)]
        return evaluate(expr, defs)

    threads = []
    for p, t in text.items():
        for m in re.finditer(r'\b(?:k_thread_create|board_spawn)\s*\(([^;]*?)\)\s*[;!=)]', t, re.S):
            args = [a.strip() for a in re.split(r',(?![^(]*\))', m.group(1))]
            if len(args) == 7 and re.match(r'\w+$', args[2]) and args[2] != 'entry':
                threads.append((args[1].strip('"'), args[2], size_of(args[5]), os.path.relpath(p, ROOT)))
        for m in re.finditer(r'\bk_bsched_start\s*\(([^;]*?)\)\s*;', t, re.S):
            args = [a.strip() for a in re.split(r',(?![^(]*\))', m.group(1))]
            if len(args) == 7:
                threads.append(('bsched', 'k_bsched_main', size_of(args[6]), os.path.relpath(p, ROOT)))
        for m in re.finditer(r'\bk_thread_setup\s*\(\s*&k_kernel\.idle\s*,\s*"(\w+)"\s*,\s*(\w+)\s*,[^,]*,\s*\w+\s*,\s*([^;]*?)\s*,\s*\(', t, re.S):
            words = evaluate(m.group(3), defs)
            threads.append((m.group(1), m.group(2), None if words is None else words * 4, os.path.relpath(p, ROOT)))
    return [th for th in threads if th[1] in linked]


def load_indirect(path):
    """`caller | f g`: f, g and every unclassified callback; `caller = f g`: only f, g."""
    table, closed = {}, set()
    for line in open(path):
        m = re.match(r'\s*([\w@]+)\s*([|=])(.*)$', line)
        if not m or line.startswith('#'):
            continue
        table[m.group(1)] = set(m.group(3).split())
        if m.group(2) == '=':
            closed.add(m.group(1))
    return table, closed


class Graph:
    def __init__(self, frames, edges, dynamic, taken, entries, tables):
        table, closed = tables
        self.frames, self.edges, self.dynamic = frames, edges, dynamic
        self.indirect = sorted(f for f in taken if f in frames and f not in entries)
        # caller@ancestor: the targets when the call chain passed through ancestor
        # (the callback a formatter calls is the one its wrapper passed in).
        self.contexts = {k.split('@', 1)[1] for k in table if '@' in k}
        classified = set().union(*table.values()) if table else set()
        unclassified = [f for f in self.indirect if f not in classified]
        self.targets = {c: sorted((set() if c in closed else set(unclassified)) | (t & set(self.indirect)))
                        for c, t in table.items()}
        self.default_targets = unclassified
        self.memo, self.unknown, self.recursive = {}, set(), set()

    def depth(self, f, stack=()):
        """Deepest stack use below f's caller: f's frame and its deepest callee."""
        ctx = next((a for a in reversed(stack) if a in self.contexts), None)
        key = (f, ctx)
        if key in self.memo:
            return self.memo[key]
        # Recursion is f entered again in the same context: the same function
        # under another wrapper (bsched_run_cycle inside a PDL cycle that the
        # kernel's bsched_run_cycle runs) resolves its indirect calls to other
        # targets, so it is a bounded nesting, not a cycle.
        for i, g in enumerate(stack):
            if g == f and next((a for a in reversed(stack[:i]) if a in self.contexts), None) == ctx:
                self.recursive.add(' -> '.join(stack[i:] + (f,)))
                return 0, ()
        if f in ASM_FRAMES:
            own = ASM_FRAMES[f]
        elif f in self.frames:
            own = self.frames[f]
        else:
            self.unknown.add(f)
            own = LIBGCC_FRAME
        callees = set(self.edges.get(f, ()))
        if f == 'k_arch_thread_trampoline':
            callees.add('k_thread_start')
        if f == 'k_isr_entry':
            callees.add('k_isr_run')
        best, path = 0, ()
        for c in sorted(callees):
            if c == '__indirect_call':
                targets = self.targets.get('%s@%s' % (f, ctx), self.targets.get(f, self.default_targets))
            else:
                targets = [c]
            for t in targets:
                d, p = self.depth(t, stack + (f,))
                if d + RET > best:
                    best, path = d + RET, p
        self.memo[key] = (own + best, (f,) + path)
        return self.memo[key]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True, help='the firmware build tree (BUILD/firmware)')
    ap.add_argument('--apps', required=True)
    ap.add_argument('--irq-nesting', type=int, default=IRQ_NESTING_DEFAULT)
    ap.add_argument('--gate', choices=['thread', 'full'], default='thread',
                    help='fail when the thread alone (thread) or with nested interrupts (full) can overflow')
    ap.add_argument('--suite')
    a = ap.parse_args()
    headers = glob.glob(os.path.join(ROOT, 'kernel/include/*.h')) + glob.glob(os.path.join(ROOT, 'kernel/*.h'))
    ok = bad = known = at_risk = 0
    known_list = {}
    kp = os.path.join(ROOT, 'assure', 'stack-known.txt')
    if os.path.exists(kp):
        for line in open(kp):
            if line.strip() and not line.startswith('#') and '|' in line:
                k, why = line.split('|', 1)
                known_list[' '.join(k.split())] = why.strip()
    for app in a.apps.split():
        elf = os.path.join(a.build, app, app + '.elf')
        if not os.path.exists(elf):
            print('%s: no image %s' % (app, elf)); bad += 1; continue
        cis = glob.glob(os.path.join(a.build, 'obj', '**', '*.ci'), recursive=True) + \
            glob.glob(os.path.join(a.build, app, '**', '*.ci'), recursive=True)
        objs = glob.glob(os.path.join(a.build, 'obj', '**', '*.o'), recursive=True) + \
            glob.glob(os.path.join(a.build, app, 'obj', '**', '*.o'), recursive=True)
        if not cis:
            print('%s: no .ci files (build with FW_STACK_INFO=1)' % app); bad += 1; continue
        frames, edges, dynamic = parse_ci(cis)
        linked = elf_functions(elf)
        sources = sorted(set(glob.glob(os.path.join(ROOT, 'apps', app, '*.c')) +
                             glob.glob(os.path.join(ROOT, 'kernel', '*.c')) +
                             [f for d in ('drivers', 'net', 'pdl') for f in glob.glob(os.path.join(ROOT, d, '*.c'))]))
        defs = c_defines(headers + sources + glob.glob(os.path.join(ROOT, 'apps', app, '*.h')))
        threads = find_threads(sources + headers, defs, linked)
        sized = {t[1] for t in threads if t[2] is not None}
        threads = [t for t in threads if t[2] is not None or t[1] not in sized]
        taken = address_taken(objs, edges) & linked
        g = Graph(frames, edges, dynamic, taken, {t[1] for t in threads},
                  load_indirect(os.path.join(ROOT, 'assure', 'stack-indirect.txt')))
        isr, isr_path = g.depth('k_isr_entry') if 'k_isr_entry' in linked else (0, ())
        guard = evaluate('K_STACK_GUARD_WORDS', defs) or 0
        print('== %s: %d functions with frames, %d address-taken (indirect-call targets), '
              'interrupt path %d bytes' % (app, len(frames), len(g.indirect), isr))
        print('   interrupt path: %s' % ' > '.join(isr_path))
        print('   indirect-call targets: %s' % ', '.join(g.indirect))
        for name, entry, size, where in threads:
            d, path = g.depth(entry)
            tramp = ASM_FRAMES['k_arch_thread_trampoline'] + RET + g.frames.get('k_thread_start', 0) + RET
            own = tramp + d
            worst = own + a.irq_nesting * isr
            avail = None if size is None else size - 4 * guard
            gate = worst if a.gate == 'full' else own
            if avail is None:
                verdict = 'FAILED (stack size not found)'
                bad += 1
            elif worst <= avail:
                verdict = 'ok, margin %d bytes (%d %%)' % (avail - worst, 100 * (avail - worst) // avail)
                ok += 1
            elif gate <= avail:
                verdict = ('ok for its own calls (margin %d bytes); AT RISK with %d nested interrupts '
                           '(over by %d bytes)' % (avail - own, a.irq_nesting, worst - avail))
                ok += 1
                at_risk += 1
            elif '%s %s' % (app, name) in known_list:
                verdict = 'KNOWN FINDING (not counted): bound exceeds the stack by %d bytes' % (worst - avail)
                known += 1
            else:
                verdict = 'FAILED: can overflow by %d bytes' % (worst - avail)
                bad += 1
            print('   thread %-14s entry %-20s stack %5s B (%s), worst case %5d B = %d thread + %d x %d interrupt: %s'
                  % (name, entry, size, where, worst, tramp + d, a.irq_nesting, isr, verdict))
            print('       deepest: %s' % ' > '.join(path))
        if g.recursive:
            print('   FAILED: recursion, no bound: %s' % '; '.join(sorted(g.recursive)))
            bad += 1
        else:
            print('   ok: no recursion on any path (the bound exists)')
            ok += 1
        dyn = sorted(f for f in g.dynamic if f in g.memo)
        if dyn:
            print('   FAILED: unbounded dynamic frames: %s' % ', '.join(dyn))
            bad += 1
        else:
            print('   ok: every frame static or dynamic,bounded')
            ok += 1
        big = sorted(((g.frames[f], f) for f in g.frames if ':' not in f and f in linked), reverse=True)[:8]
        print('   largest frames: %s' % ', '.join('%s %d' % (f, n) for n, f in big))
        if g.unknown:
            print('   no .ci (assumed %d bytes each, libgcc/asm): %s' % (LIBGCC_FRAME, ', '.join(sorted(g.unknown))))
    if at_risk:
        print('%d threads fit their own calls but not the conservative interrupt bound (AT RISK, '
              'reported; --gate full fails on them)' % at_risk)
    if known:
        print('%d threads over their stack by the conservative bound, listed in assure/stack-known.txt' % known)
    print('%d passed, %d failed' % (ok, bad))
    if a.suite:
        os.makedirs(os.path.join(ROOT, 'build/results'), exist_ok=True)
        with open(os.path.join(ROOT, 'build/results', a.suite + '.txt'), 'w') as f:
            f.write('%d passed, %d failed\n' % (ok, bad))
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
