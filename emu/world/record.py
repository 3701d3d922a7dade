"""What a run leaves behind: the trajectory (and its sha256), the battery
curve, the summary, and the picture (matplotlib, headless)."""

import hashlib
import struct


class Recorder:
    """Logs the world after every step. The sha256 covers, per step, the
    virtual time in ns and the pose and charge as IEEE doubles, so two runs
    have the same hash only if their trajectories are identical bit for bit."""

    def __init__(self, world, every=10, trace=None):
        self.world = world
        self.trace = trace          # a text file: one line per step (t_ns x y th soc)
        self.sha = hashlib.sha256()
        self.every = every          # keep every n-th step for the picture
        self.n = 0
        self.t, self.x, self.y, self.soc, self.charging = [], [], [], [], []
        self.last_status = {}       # the robot program's latest report
        self.overruns = 0
        self.status_lines = 0
        self.runs = {}              # each process's runs so far (the program's counts)

    def step(self, t_ns):
        w = self.world
        self.sha.update(struct.pack("<qdddd", t_ns, w.x, w.y, w.th, w.soc))
        if self.trace:
            # float(): after a collision the pose may be a numpy float64, whose
            # repr is "np.float64(...)"; a Python float's repr is the plain
            # shortest decimal that reads back to the same double.
            self.trace.write(f"{t_ns} {float(w.x)!r} {float(w.y)!r} {float(w.th)!r} "
                             f"{float(w.soc)!r}\n")
        if self.n % self.every == 0:
            self.t.append(w.t)
            self.x.append(w.x)
            self.y.append(w.y)
            self.soc.append(w.soc)
            self.charging.append(w.charging)
        self.n += 1

    def digest(self):
        return self.sha.hexdigest()

    def summary(self):
        w = self.world
        w.finish()
        late_walls = [t for t in w.wall_collision_times if t >= 60.0]
        return {
            "virtual_s": round(w.t, 3),
            "survived_s": round(w.death_time if w.death_time is not None else w.t, 3),
            "alive": w.alive,
            "recharges": w.recharges,
            "collisions": dict(w.collisions),
            "wall_collisions_after_60s": len(late_walls),
            "distance_m": round(w.distance, 3),
            "competitor_hits": w.competitor_hits,
            "final_charge": round(w.soc, 4),
            "overruns": self.overruns,
            "process_runs": dict(self.runs),
            "trajectory_sha256": self.digest(),
        }


def summary_lines(s, mode, program="ecosystem"):
    c = s["collisions"]
    runs = " ".join(f"{name} {n}" for name, n in s.get("process_runs", {}).items()) or "-"
    return [
        f"{program} ({mode}): {s['virtual_s']:.1f} s of virtual time",
        f"  survived:        {s['survived_s']:.1f} s ({'alive' if s['alive'] else 'battery empty'}),"
        f" final charge {100 * s['final_charge']:.0f} %",
        f"  recharges:       {s['recharges']}",
        f"  collisions:      walls {c['wall']} ({s['wall_collisions_after_60s']} after the first minute),"
        f" obstacles {c['obstacle']}, competitors {c['competitor']}",
        f"  distance:        {s['distance_m']:.1f} m",
        f"  competitor hits: {s['competitor_hits']}",
        f"  overruns:        {s['overruns']}",
        f"  process runs:    {runs}",
    ]


def draw_arena(ax, world):
    import matplotlib.patches as patches
    a = world.arena
    w, h = a["size"]
    for (x0, y0, x1, y1), kind in zip(world.seg, world.seg_kind):
        ax.plot([x0, x1], [y0, y1], color="black" if kind == "wall" else "dimgray", lw=2)
    for (cx, cy, r), kind in zip(world.circ, world.circ_kind):
        color = "dimgray" if kind == "obstacle" else "orange"
        ax.add_patch(patches.Circle((cx, cy), r, color=color, alpha=0.8))
    for o in a.get("obstacles", []):
        if "box" in o:
            x0, y0, x1, y1 = o["box"]
            ax.add_patch(patches.Rectangle((x0, y0), x1 - x0, y1 - y0, color="dimgray", alpha=0.8))
    sx, sy, sr = world.station
    ax.add_patch(patches.Circle((sx, sy), sr, color="gold", alpha=0.35))
    ax.plot([sx], [sy], marker="*", color="goldenrod", ms=14)
    ax.set_xlim(-0.05, w + 0.05)
    ax.set_ylim(-0.05, h + 0.05)
    ax.set_aspect("equal")


def save_picture(rec, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw={"width_ratios": [1.25, 1]})
    draw_arena(ax, rec.world)
    sc = ax.scatter(rec.x, rec.y, c=rec.t, s=2, cmap="viridis")
    ax.plot([rec.world.x], [rec.world.y], marker="o", color="red", ms=7)
    fig.colorbar(sc, ax=ax, label="virtual time (s)", shrink=0.8)
    ax.set_title("trajectory (station: gold, competitors: orange)")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    bx.plot(rec.t, [100 * s for s in rec.soc], color="tab:green")
    ch = [100 if c else 0 for c in rec.charging]
    bx.fill_between(rec.t, 0, ch, color="gold", alpha=0.3, step="post", label="charging")
    bx.set_ylim(0, 105)
    bx.set_xlabel("virtual time (s)")
    bx.set_ylabel("battery charge (%)")
    bx.set_title("battery")
    bx.legend(loc="lower left")
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
