#!/usr/bin/env python3
"""The layering test (suite `layering`): dependencies between the top-level
folders point down only, and no two folders depend on each other.

It reads every #include "..." of the C and assembly sources and every import of
the Python files, resolves each to a file of this repository and so to the
top-level folder that holds it, and fails on any dependency the graph below
does not allow: an upward one, or one that closes a circle. The graph is
written here and only here. A quoted include is looked for as the compiler
does: in the including file's folder, then in the include folders (-I,
-isystem) the make files name (read from them, not listed here), and the
root; one found nowhere fails too (only FETCHED libraries are outside). Before
the tree, the check runs on three small trees of its own: one with an
unresolvable include and one with an upward include must fail, a clean one
must pass.

What is not read: tests (a folder's tests/ may use the layers above the code
they test, e.g. a kernel test image on the board), emu/hw (QEMU's own device
sources, built inside QEMU's tree: their "cpu.h" is QEMU's), and includes
with <...> (the compiler's, the C library's, cmocka's).

    assure/layering.py [--root DIR] [--results FILE]
Prints one line per violation and 'layering: N passed, M failed'; exit status
1 when any fails, 2 on bad usage.
"""
import argparse
import ast
import os
import re
import sys

# Direct dependencies each top-level folder may have; any path along them is
# allowed too (apps may use the kernel through drivers, or directly).
#   firmware:  apps -> pdl, net -> drivers -> boards -> kernel (its CPU port
#              inside it) -> bsched; bsched depends on nothing; apps may use
#              the POSIX layer (posix -> kernel)
#   host side: emu (the board model, the world and robocube_emu, the package
#              that drives the emulator) and tools (which use it) stand beside it;
#              bench measures bsched on the host and on the board; assure and
#              ci check everything.
ALLOWED = {
    "bsched": set(),
    "kernel": {"bsched"},
    "boards": {"kernel"},
    "drivers": {"boards"},
    "net": {"drivers"},
    "pdl": {"drivers"},
    "posix": {"kernel"},
    "apps": {"pdl", "net", "posix", "emu"},
    "emu": set(),
    "tools": {"bsched", "emu"},
    "bench": {"boards", "pdl", "emu"},
    "assure": {"apps", "bench"},
    "ci": set(),
}

# Quoted includes of a library that ci/setup fetches into build/ (not part of
# the repository, so no layer): the prefix and the folder the make files must
# name as an include folder for it.
FETCHED = {"mbedtls/": "build/mbedtls/include"}
SKIP_DIRS = {"build", ".git", "__pycache__", "node_modules"}
C_EXT = (".c", ".h", ".S")
INCLUDE_RE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def reachable(graph):
    """Every folder each folder may depend on (transitive closure)."""
    out = {}
    for a in graph:
        seen, todo = set(), list(graph[a])
        while todo:
            b = todo.pop()
            if b not in seen:
                seen.add(b)
                todo.extend(graph.get(b, ()))
        out[a] = seen
    return out


def skipped(rel):
    parts = rel.split("/")
    return "tests" in parts or rel.startswith("emu/hw/") or rel.startswith("emu/qemu-patches/")


def files(root):
    for d, dirs, names in os.walk(root):
        dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS and not x.startswith("."))
        for n in sorted(names):
            rel = os.path.relpath(os.path.join(d, n), root)
            if "/" in rel:
                yield rel


MAKE_VAR_RE = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*[:?]?=\s*(.*?)\s*$", re.M)
INCLUDE_OPT_RE = re.compile(r"(?:-I|-isystem)\s*([^\s'\";,]+)")
THIS_MAKEFILE = "$(abspath $(dir $(lastword $(MAKEFILE_LIST))))"


def make_files(root):
    for rel in files(root):
        base = os.path.basename(rel)
        if rel.endswith(".mk") or base == "Makefile" or base.startswith("Makefile."):
            yield rel
    if os.path.isfile(os.path.join(root, "Makefile")):
        yield "Makefile"


def include_dirs(root):
    """The folders the make files pass as -I or -isystem, relative to root, in
    no particular order: $(ROOT) and the variables set to paths under it are
    expanded (a variable set to the make file's own folder, too). A folder
    of the repository that does not exist, or a make variable that is not a
    path, is no include folder; one under build/ is (a fetched library's)."""
    texts = {}
    for rel in make_files(root):
        with open(os.path.join(root, rel), errors="replace") as f:
            texts[rel] = f.read().replace("$$(", "$(")
    shared = {"ROOT": ".", "CURDIR": "."}
    for text in texts.values():
        for name, value in MAKE_VAR_RE.findall(text):
            shared.setdefault(name, value)
    found = set()
    for rel, text in texts.items():
        values = dict(shared)
        for name, value in MAKE_VAR_RE.findall(text):
            if value == THIS_MAKEFILE:
                values[name] = os.path.dirname(rel)
        for opt in INCLUDE_OPT_RE.findall(text):
            path = opt
            while path.endswith(")") and path.count(")") > path.count("("):
                path = path[:-1]
            for _ in range(8):
                m = re.search(r"\$\(([A-Za-z_][A-Za-z0-9_]*)\)", path)
                if not m or m.group(1) not in values:
                    break
                path = path[:m.start()] + values[m.group(1)] + path[m.end():]
            if "$" in path or os.path.isabs(path):
                continue
            path = os.path.normpath(path)
            if path.startswith("build/") or os.path.isdir(os.path.join(root, path)):
                found.add(path)
    return found


def resolve_include(root, rel, name, dirs):
    """The repository file a quoted include names; FETCHED for a fetched
    library's header; None when it is nowhere."""
    for base in [os.path.dirname(rel)] + sorted(dirs - {"."}) + [""]:
        cand = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(root, cand)) and not cand.startswith("build/"):
            return cand
    for prefix, folder in FETCHED.items():
        if name.startswith(prefix) and folder in dirs:
            return "FETCHED"
    return None


def python_modules(root):
    """Module name -> the repository files that define it (X.py or X/__init__.py)."""
    mods = {}
    for rel in files(root):
        if rel.endswith(".py"):
            name = os.path.basename(rel)[:-3]
            if name == "__init__":
                name = os.path.basename(os.path.dirname(rel))
            mods.setdefault(name, []).append(rel)
    return mods


def resolve_import(rel, name, mods):
    """The file a Python import names: its own folder's first, else the only one."""
    first = name.split(".")[0]
    cands = mods.get(first, [])
    here = os.path.dirname(rel)
    for c in cands:
        if os.path.dirname(c) == here or os.path.dirname(os.path.dirname(c)) == here:
            return c
    return cands[0] if len(cands) == 1 else None


def dependencies(root):
    """(from file, to file) for every include and import that crosses top-level
    folders; (from file, None, why) for one that cannot be resolved."""
    mods = python_modules(root)
    dirs = include_dirs(root)
    for rel in files(root):
        if skipped(rel):
            continue
        targets = []
        if rel.endswith(C_EXT):
            with open(os.path.join(root, rel), errors="replace") as f:
                text = f.read()
            for n in INCLUDE_RE.findall(text):
                t = resolve_include(root, rel, n, dirs)
                if t is None:
                    yield rel, None, 'includes "%s", which is in no include folder of the make files' % n
                elif t != "FETCHED":
                    targets.append(t)
        elif rel.endswith(".py"):
            with open(os.path.join(root, rel)) as f:
                try:
                    tree = ast.parse(f.read(), rel)
                except SyntaxError as e:
                    yield rel, None, "does not parse: %s" % e
                    continue
            for node in ast.walk(tree):
                if isinstance(node, ast.Import):
                    targets += [resolve_import(rel, a.name, mods) for a in node.names]
                elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                    targets.append(resolve_import(rel, node.module, mods))
        for t in targets:
            if t is not None and t.split("/")[0] != rel.split("/")[0]:
                yield rel, t, None


def check(root):
    may = reachable(ALLOWED)
    # The graph itself must have no circle.
    failures = ["the allowed graph has a circle through %s" % a for a in ALLOWED if a in may[a]]
    edges = {}
    passed = 0
    for src, dst, err in dependencies(root):
        if err:
            failures.append("%s %s" % (src, err))
            continue
        a, b = src.split("/")[0], dst.split("/")[0]
        edges.setdefault((a, b), (src, dst))
    for (a, b), (src, dst) in sorted(edges.items()):
        if a not in ALLOWED:
            failures.append("%s -> %s: folder %s/ is not in the layering graph (assure/layering.py)" % (src, dst, a))
        elif b not in may[a]:
            kind = "circular" if a in may.get(b, set()) else "upward or sideways"
            failures.append("%s -> %s: %s dependency %s -> %s (allowed from %s: %s)"
                            % (src, dst, kind, a, b, a, ", ".join(sorted(may[a])) or "nothing"))
        else:
            passed += 1
    return passed, failures, edges


# The check on trees of its own (name, files added to the base, how the one
# failure it must report begins, None: it must pass): each tree is the three lowest
# layers, kernel/include an include folder of its Makefile.
SELF_TEST_BASE = {
    "Makefile": "CFLAGS := -I$(ROOT) -I$(ROOT)/kernel/include\n",
    "bsched/bsched.h": "",
    "kernel/include/kernel.h": '#include "bsched/bsched.h"\n',
    "boards/board.c": '#include "kernel.h"\n',
}
SELF_TESTS = [
    ("a clean tree passes", {}, None),
    ("an include found nowhere fails", {"boards/led.c": '#include "led_regs.h"\n'},
     'boards/led.c includes "led_regs.h", which is in no include folder'),
    ("an upward include fails", {"kernel/k_tick.c": '#include "boards/board.c"\n'},
     "kernel/k_tick.c -> boards/board.c: circular dependency kernel -> boards"),
]


def self_test():
    """(passed, failures) of the check on SELF_TESTS."""
    import tempfile
    passed, failures = 0, []
    for name, extra, expected in SELF_TESTS:
        with tempfile.TemporaryDirectory() as root:
            for rel, text in list(SELF_TEST_BASE.items()) + list(extra.items()):
                os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
                with open(os.path.join(root, rel), "w") as f:
                    f.write(text)
            _, bad, _ = check(root)
        if (not bad and expected is None) or (len(bad) == 1 and expected and bad[0].startswith(expected)):
            passed += 1
        else:
            failures.append("self-test: %s: %s" % (name, "; ".join(bad) or "it passed"))
    return passed, failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--results", help="write 'P passed, F failed' here")
    a = ap.parse_args()
    if not os.path.isdir(a.root):
        ap.error("--root %s: no such folder" % a.root)
    passed, failures = self_test()
    tree_passed, tree_failures, edges = check(a.root)
    passed += tree_passed
    failures += tree_failures
    for (x, y), (src, dst) in sorted(edges.items()):
        print("  %-7s -> %-7s e.g. %s -> %s" % (x, y, src, dst))
    for f in failures:
        print("FAILED: " + f)
    print("layering: %d passed, %d failed (%d folder-to-folder dependencies, %d self-tests)"
          % (passed, len(failures), len(edges), len(SELF_TESTS)))
    if a.results:
        os.makedirs(os.path.dirname(a.results), exist_ok=True)
        with open(a.results, "w") as f:
            f.write("%d passed, %d failed\n" % (passed, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
