"""Tests of the bsched-plan CLI: output formats and bad input."""
import json
import os
import subprocess

import pytest

PLAN = os.environ.get("BSCHED_PLAN", os.path.join(os.path.dirname(__file__), "../../build/bin/bsched-plan"))

TABLE1_PV = ["1", "1", "1", "2", "2", "3", "4", "4", "4"]
TABLE2 = [  # the paper's Table 2 as input indices (p1.1 = 0 ... p4.3 = 8)
    [0, 2, 5], [1, 3], [0, 2, 8], [1, 4], [0, 2, 6], [1, 3], [0, 2], [1, 4],
    [0, 2, 5], [1, 3], [0, 2], [1, 4], [0, 2, 7], [1, 3], [0, 2], [1, 4],
]


def run(*args):
    return subprocess.run([PLAN, *args], capture_output=True, text=True, timeout=60)


def test_json_table1_and_table2():
    r = run("--json", *TABLE1_PV)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    doc = json.loads(r.stdout)  # exactly one JSON object, nothing else
    assert doc["wait"] == [0, 1, 0, 1, 3, 0, 4, 12, 2]
    assert doc["perfect"] == 3
    assert doc["major_cycle"] == TABLE2


def test_json_option_after_values():
    r = run(*TABLE1_PV, "--json")
    assert r.returncode == 0
    assert json.loads(r.stdout)["major_cycle"] == TABLE2


def test_text_tables_name_processes_like_the_paper():
    r = run(*TABLE1_PV)
    assert r.returncode == 0
    out = r.stdout
    assert "p4.2" in out and "12" in out
    rows = [line.split(None, 1) for line in out.splitlines() if line[:1].isdigit()]
    # Table 2 rows: "cycle  pX.Y, ..."
    assert rows[0] == ["0", "p1.1, p1.3, p3.1"]
    assert rows[2] == ["2", "p1.1, p1.3, p4.3"]
    assert rows[15] == ["15", "p1.2, p2.2"]
    assert "perfect = 3" in out
    assert "2.3125" in out


def test_json_major_cycle_is_balanced_for_a_larger_set():
    pv = [str((i * 5) % 7) for i in range(40)]
    doc = json.loads(run("--json", *pv).stdout)
    maxpv = max(map(int, pv))
    assert len(doc["major_cycle"]) == 2 ** maxpv
    area = sum(2 ** (maxpv - int(p)) for p in pv)
    lo, hi = area // 2 ** maxpv, -(-area // 2 ** maxpv)
    assert doc["perfect"] == hi
    for t, cycle in enumerate(doc["major_cycle"]):
        assert lo <= len(cycle) <= hi
        for i in cycle:
            assert t % 2 ** int(pv[i]) == doc["wait"][i]


@pytest.mark.parametrize("args, names", [
    ([], "no priority values"),
    (["1", "x"], "'x'"),
    (["1", "2.5"], "'2.5'"),
    (["1", ""], "''"),
    (["-1"], "'-1'"),
    (["1", "32"], "'32'"),
    (["99999999999999999999"], "'99999999999999999999'"),
    (["21"], "'21'"),
    (["--verbose", "1"], "'--verbose'"),
    (["--js", "1"], "'--js'"),
])
def test_bad_input_exits_2_with_one_line_naming_the_argument(args, names):
    r = run(*args)
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("bsched-plan: ")
    assert names in lines[0]


def test_too_many_processes():
    r = run(*(["3"] * 65536))
    assert r.returncode == 2
    assert r.stdout == ""
    assert "too many processes" in r.stderr
    assert len(r.stderr.splitlines()) == 1


def test_largest_listed_pv_and_capacity():
    r = run("--json", "20")
    assert r.returncode == 0
    doc = json.loads(r.stdout)
    assert len(doc["major_cycle"]) == 2 ** 20
    r = run("--json", *(["0"] * 65535))
    assert r.returncode == 0
    doc = json.loads(r.stdout)
    assert doc["perfect"] == 65535 and len(doc["major_cycle"][0]) == 65535


# ---------- --svg FILE: the major cycle as a chart ----------

import xml.etree.ElementTree as ET

SVG_NS = "{http://www.w3.org/2000/svg}"


def svg_of(tmp_path, *pvs, extra=()):
    out = tmp_path / "plan.svg"
    r = run("--svg", str(out), *extra, *pvs)
    assert r.returncode == 0, r.stderr
    root = ET.parse(out).getroot()  # well-formed XML, or this raises
    assert root.tag == SVG_NS + "svg"
    return root, r


def marks(root):
    runs = {}
    for rect in root.iter(SVG_NS + "rect"):
        if rect.get("class") == "run":
            runs.setdefault(int(rect.get("data-cycle")), []).append(int(rect.get("data-process")))
    return runs


def loads(root):
    return {int(r.get("data-cycle")): int(r.get("data-load")) for r in root.iter(SVG_NS + "rect")
            if (r.get("class") or "").startswith("load")}


def texts(root):
    return ["".join(t.itertext()) for t in root.iter(SVG_NS + "text")]


def test_svg_table2_marks_match_json(tmp_path):
    root, r = svg_of(tmp_path, *TABLE1_PV, extra=("--json",))
    doc = json.loads(r.stdout)  # --json still goes to stdout, unchanged
    assert doc["major_cycle"] == TABLE2
    got = marks(root)
    assert [got.get(t, []) for t in range(16)] == TABLE2  # in execution order, too
    assert loads(root) == {t: len(TABLE2[t]) for t in range(16)}
    assert any("perfect = 3" in t for t in texts(root))
    # cycles at the perfect load are marked as such
    perfect_bars = [r for r in root.iter(SVG_NS + "rect") if r.get("class") == "load perfect"]
    assert sorted(int(r.get("data-cycle")) for r in perfect_bars) == [t for t in range(16) if len(TABLE2[t]) == 3]
    assert not any(t.startswith("left out") for t in texts(root))
    # processes are labelled like the paper, in execution order
    labels = [t for t in texts(root) if t.startswith("p") and "." in t]
    assert labels == ["p1.1", "p1.2", "p1.3", "p2.1", "p2.2", "p3.1", "p4.1", "p4.2", "p4.3"]


def test_svg_larger_set_matches_json(tmp_path):
    pvs = [str(3 + (i * 7) % 8) for i in range(300)]
    root, _ = svg_of(tmp_path, *pvs)
    doc = json.loads(run("--json", *pvs).stdout)
    got = marks(root)
    assert len(doc["major_cycle"]) == 1024
    assert [got.get(t, []) for t in range(1024)] == doc["major_cycle"]
    assert loads(root) == {t: len(c) for t, c in enumerate(doc["major_cycle"])}


def test_svg_says_what_it_left_out(tmp_path):
    pvs = ["11"] * 3 + ["2"] * 600
    root, _ = svg_of(tmp_path, *pvs)
    doc = json.loads(run("--json", *pvs).stdout)
    left_out = [t for t in texts(root) if t.startswith("left out")]
    assert len(left_out) == 1
    assert "minor cycles 1024..2047 (1024 of 2048 shown)" in left_out[0]
    assert "rows of 91 processes after the first 512" in left_out[0]
    got = marks(root)
    assert max(got) <= 1023
    shown = set(doc["order"][:512])
    for t in range(1024):
        assert got.get(t, []) == [i for i in doc["major_cycle"][t] if i in shown]
    # the loads still count every process
    assert loads(root) == {t: len(doc["major_cycle"][t]) for t in range(1024)}


@pytest.mark.parametrize("args", [["--svg"], ["1", "2", "--svg"], ["--svg", ""]])
def test_svg_without_file_is_an_error(args):
    r = run(*args)
    assert r.returncode == 2
    assert r.stdout == ""
    assert "--svg" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_svg_unwritable_file_is_an_error_and_writes_nothing(tmp_path):
    target = tmp_path / "no-such-dir" / "plan.svg"
    r = run("--svg", str(target), "1", "2")
    assert r.returncode == 2
    assert r.stdout == ""
    assert "cannot write" in r.stderr
    assert not target.exists()


# ---------- --svg FILE never replaces anything but a regular file ----------

def leftovers(folder):
    return sorted(p.name for p in folder.iterdir() if p.name.startswith(".bsched-plan-"))


def test_svg_follows_no_link_planted_at_a_temporary_name(tmp_path):
    # A fixed temporary name (FILE.tmp) opened with fopen("w") would follow a
    # link planted there and write the chart into whatever it points to.
    victim = tmp_path / "victim"
    victim.write_text("keep me\n")
    target = tmp_path / "plan.svg"
    (tmp_path / "plan.svg.tmp").symlink_to(victim)
    r = run("--svg", str(target), "1", "2")
    assert r.returncode == 0, r.stderr
    assert victim.read_text() == "keep me\n"
    assert (tmp_path / "plan.svg.tmp").is_symlink()
    assert ET.parse(target).getroot().tag == SVG_NS + "svg"
    assert not target.is_symlink()
    assert leftovers(tmp_path) == []


@pytest.mark.parametrize("kind", ["symlink", "fifo", "folder", "dangling symlink"])
def test_svg_refuses_to_replace_what_is_not_a_regular_file(tmp_path, kind):
    victim = tmp_path / "victim"
    victim.write_text("keep me\n")
    target = tmp_path / "plan.svg"
    if kind == "symlink":
        target.symlink_to(victim)
    elif kind == "dangling symlink":
        target.symlink_to(tmp_path / "nowhere")
    elif kind == "fifo":
        os.mkfifo(target)
    else:
        target.mkdir()
    before = os.lstat(target)
    r = run("--svg", str(target), "1", "2")
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"bsched-plan: cannot write '{target}': ")
    assert "refusing to replace" in lines[0]
    after = os.lstat(target)
    assert (after.st_ino, after.st_mode) == (before.st_ino, before.st_mode)
    assert victim.read_text() == "keep me\n"
    assert not (tmp_path / "nowhere").exists()
    assert leftovers(tmp_path) == []


def test_svg_replaces_a_regular_file_whole(tmp_path):
    target = tmp_path / "plan.svg"
    target.write_text("old chart\n")
    root, _ = svg_of(tmp_path, *TABLE1_PV)
    assert marks(root)[0] == TABLE2[0]
    assert leftovers(tmp_path) == []
    assert os.stat(target).st_mode & 0o777 == 0o666 & ~current_umask()


def current_umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_help_prints_usage_and_exits_0():
    for flag in ("--help", "-h"):
        r = run(flag)
        assert r.returncode == 0, r.stderr
        assert r.stderr == ""
        assert r.stdout.startswith("usage: bsched-plan [--json] [--svg FILE] PV [PV ...]")
        assert "--svg FILE" in r.stdout and "--json" in r.stdout


def test_text_tables_of_16000_processes_take_linear_time(tmp_path):
    # Table 2 names every process of every minor cycle; naming one must not
    # cost a walk over the processes before it (that took 57 s of CPU here).
    import resource
    pv = [str(i % 12) for i in range(16000)]
    out = tmp_path / "tables.txt"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(out, "w") as f:
        try:
            r = subprocess.run([PLAN, *pv], stdout=f, stderr=subprocess.PIPE, text=True, timeout=60)
        except subprocess.TimeoutExpired:
            pytest.fail("16000 processes: no Table 2 in 60 s")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    assert r.returncode == 0, r.stderr
    assert cpu < 8.0, f"{cpu:.1f} s of CPU"
    lines = out.read_text().splitlines()
    out.unlink()
    table1 = [ln.split() for ln in lines[2:16002]]
    assert table1[0][:2] == ["p0.1", "0"] and table1[-1][:2] == ["p3.1334", "3"]
    cycles = [ln for ln in lines if ln[:1].isdigit()]
    assert len(cycles) == 2048
    # cycle 0 runs every process whose wait is 0: class 0's 1334 members among them
    first = cycles[0].split(None, 1)[1].split(", ")
    assert [n for n in first if n.startswith("p0.")] == [f"p0.{j}" for j in range(1, 1335)]
