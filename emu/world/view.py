"""What a run shows while it runs: a live terminal view (rich) when stdout is
a terminal, plain progress lines otherwise."""

import math
import time

ARROWS = "→↗↑↖←↙↓↘"


def arena_text(world, trail, cols=56, rows=20):
    """The arena as characters: walls #, obstacles o, station S (light *),
    competitors C (lamp on) / c (off), the robot's trail . and the robot as
    an arrow along its heading."""
    w, h = world.arena["size"]
    grid = [[" "] * cols for _ in range(rows)]

    def cell(x, y):
        c = min(cols - 1, max(0, int(x / w * cols)))
        r = min(rows - 1, max(0, int((h - y) / h * rows)))
        return r, c

    for x, y in trail:
        r, c = cell(x, y)
        grid[r][c] = "·"
    sx, sy, sr = world.station
    for r in range(rows):
        for c in range(cols):
            x, y = (c + 0.5) * w / cols, h - (r + 0.5) * h / rows
            if math.hypot(x - sx, y - sy) <= sr and grid[r][c] == " ":
                grid[r][c] = "S"
            for (cx, cy, cr), kind in zip(world.circ, world.circ_kind):
                if kind == "obstacle" and math.hypot(x - cx, y - cy) <= cr + 0.02:
                    grid[r][c] = "o"
            for o in world.arena.get("obstacles", []):
                if "box" in o:
                    x0, y0, x1, y1 = o["box"]
                    if x0 <= x <= x1 and y0 <= y <= y1:
                        grid[r][c] = "o"
    r, c = cell(sx, sy)
    grid[r][c] = "*"
    for comp in world.competitors:
        r, c = cell(comp["x"], comp["y"])
        grid[r][c] = "C" if comp.get("on", True) else "c"
    r, c = cell(world.x, world.y)
    grid[r][c] = ARROWS[int(round(world.th / (math.pi / 4))) % 8]
    border = "#" * (cols + 2)
    return "\n".join([border] + ["#" + "".join(row) + "#" for row in grid] + [border])


def runs_delta(now, before):
    """Each process's runs between two readings of the run counts."""
    return {name: n - before.get(name, 0) for name, n in now.items()}


def runs_text(runs):
    return " ".join(f"{name}={n}" for name, n in runs.items()) or "-"


class PlainProgress:
    """One line every `every` virtual seconds: the world, the counts the
    summary gives (recharges counted the same way), and how often each
    process ran over the interval (from the program's run counts)."""

    def __init__(self, every=10.0, out=None):
        self.every = every
        self.out = out or (lambda line: print(line, flush=True))
        self.next = every
        self.runs_before = {}

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def update(self, world, rec):
        if world.t + 1e-9 >= self.next:
            self.next += self.every
            ran = runs_delta(rec.runs, self.runs_before)
            self.runs_before = dict(rec.runs)
            self.out(f"t={world.t:6.1f}s pos=({world.x:4.2f},{world.y:4.2f}) "
                     f"battery={100 * world.soc:3.0f}%{' charging' if world.charging else ''} "
                     f"recharges={world.recharges_counted()} hits={world.competitor_hits} "
                     f"walls={world.collisions['wall']} overruns={rec.overruns} "
                     f"runs in last {self.every:g}s: {runs_text(ran)}")


class LiveView:
    """The rich live view, refreshed at most `fps` times per wall second."""

    def __init__(self, title, fps=8.0):
        from rich.console import Console
        from rich.live import Live
        self.console = Console()
        self.live = Live(console=self.console, auto_refresh=False, transient=False)
        self.title = title
        self.period = 1.0 / fps
        self.last = 0.0
        self.trail = []
        self.wall_start = time.monotonic()
        self.runs_before, self.runs_last_second = {}, {}

    def console_line(self, line):
        """A line of the robot's console, printed above the live view."""
        self.console.print(line, markup=False, highlight=False)

    def __enter__(self):
        self.live.__enter__()
        return self

    def __exit__(self, *exc):
        return self.live.__exit__(*exc)

    def update(self, world, rec, force=False):
        if rec.runs != self.runs_before:       # a new reading (a final repeat changes nothing)
            self.runs_last_second = runs_delta(rec.runs, self.runs_before)
            self.runs_before = rec.runs
        if rec.n % 10 == 0:
            self.trail.append((world.x, world.y))
            self.trail = self.trail[-400:]
        now = time.monotonic()
        if not force and now - self.last < self.period:
            return
        self.last = now
        self.live.update(self._render(world, rec), refresh=True)

    def _render(self, world, rec):
        from rich.columns import Columns
        from rich.console import Group
        from rich.panel import Panel
        from rich.table import Table
        from rich.text import Text

        arena = Panel(Text(arena_text(world, self.trail)), title=self.title)
        st = rec.last_status
        info = Table.grid(padding=(0, 1))
        info.add_column(style="bold")
        info.add_column()
        wall = time.monotonic() - self.wall_start
        info.add_row("virtual time", f"{world.t:7.2f} s  ({world.t / wall if wall else 0:.1f}x real time)")
        bar = int(round(20 * world.soc))
        colour = "green" if world.soc > 0.5 else "yellow" if world.soc > 0.25 else "red"
        info.add_row("battery", Text("█" * bar + "░" * (20 - bar), style=colour)
                     .append(f" {100 * world.soc:3.0f} %{'  charging' if world.charging else ''}"))
        info.add_row("station", f"{world.station_available_w():.0f} W available")
        info.add_row("competitors", " ".join("on" if c.get("on", True) else "off"
                                             for c in world.competitors))
        # What the program reports: the ecosystem's status line has all of
        # it, another program's host library the motors, a board image none.
        if "hunger" in st:
            info.add_row("hunger", f"{st['hunger'] / 10:.0f} %")
        if "motor" in st:
            info.add_row("motors L/R", f"{st['motor'][0]:5d} {st['motor'][1]:5d} permille")
        if "ran" in st:
            info.add_row("ran this cycle", " ".join(st["ran"]) or "-")
        if not st and not rec.runs:
            info.add_row("program", "no status from the robot yet")
        info.add_row("runs (last second)", runs_text(self.runs_last_second))
        info.add_row("overruns", str(rec.overruns))
        info.add_row("recharges", str(world.recharges_counted()))
        info.add_row("collisions", f"walls {world.collisions['wall']}, obstacles "
                     f"{world.collisions['obstacle']}, competitors {world.collisions['competitor']}")
        info.add_row("competitor hits", str(world.competitor_hits))
        info.add_row("distance", f"{world.distance:.1f} m")
        if not st.get("contrib"):
            return Columns([arena, Panel(info, title="robot")])
        contrib = Table(title="behaviour contributions (last run)", show_edge=False)
        contrib.add_column("process")
        contrib.add_column("speed", justify="right")
        contrib.add_column("turn", justify="right")
        for name, (sp, tu) in st.get("contrib", {}).items():
            style = "bold" if name in st.get("ran", []) else "dim"
            contrib.add_row(Text(name, style=style), f"{sp:+d}", f"{tu:+d}")
        return Columns([arena, Group(Panel(info, title="robot"), contrib)])
