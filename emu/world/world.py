"""The ecosystem world: a 2-D arena, a differential-drive robot, its sensors
and its energy (see emu/world/README.md for the model and its choices).

Plain kinematics, not a physics engine: the robot's motion comes from its
wheel encoders (the board's motor model, or the host motor model in fast
mode), so there is no dynamics to solve, only "a disc may not pass through
walls". Pose integration and collision resolution are a few closed-form
steps in IEEE double arithmetic, so a run is bit-for-bit reproducible on any
machine and the same world serves the emulator and the host fast mode.

Units: metres, radians, seconds, watts, joules. Sensor outputs are the
8-bit codes the board's analog inputs take (0..255) and active-low binary
inputs, as wired in the arena file's "wiring" section.
"""

import json
import math
import os

import numpy as np


class ArenaError(ValueError):
    pass


SCHEMA_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "arena.schema.json")


def _schema_validator():
    import jsonschema
    with open(SCHEMA_PATH) as f:
        schema = json.load(f)
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema)


def _finite(text):
    """json's parse_float: a number too large for a double reads as inf, which
    no arena quantity may be."""
    v = float(text)
    if not math.isfinite(v):
        raise ValueError(f"{text} is too large for a number")
    return v


def _no_constant(name):
    raise ValueError(f"{name} is not a number")


def _where(error):
    return "/".join(str(p) for p in error.absolute_path) or "the top level"


def load_arena(path):
    """Reads and checks an arena file (JSON) against arena.schema.json, then
    what a schema cannot say (the robot starts inside the pen, segments and
    boxes are not degenerate); raises ArenaError with one line naming the
    first problem."""
    try:
        with open(path) as f:
            a = json.load(f, parse_float=_finite, parse_constant=_no_constant)
    except OSError as e:
        raise ArenaError(f"{path}: {e.strerror}") from None
    except json.JSONDecodeError as e:
        raise ArenaError(f"{path}: not valid JSON ({e})") from None
    except (ValueError, RecursionError) as e:       # NaN, Infinity, 1e999, nesting
        raise ArenaError(f"{path}: not valid JSON ({e})") from None
    import jsonschema
    error = jsonschema.exceptions.best_match(_schema_validator().iter_errors(a))
    if error is not None:
        raise ArenaError(f"{path}: {_where(error)}: {error.message}")
    w, h = a["size"]
    for i, (x0, y0, x1, y1) in enumerate(a.get("walls", [])):
        if x0 == x1 and y0 == y1:
            raise ArenaError(f"{path}: walls/{i}: a wall of zero length")
    for i, o in enumerate(a.get("obstacles", [])):
        if "box" in o:
            x0, y0, x1, y1 = o["box"]
            if not (x0 < x1 and y0 < y1):
                raise ArenaError(f"{path}: obstacles/{i}/box: needs x0 < x1 and y0 < y1")
    x, y, _ = a["robot"]["start"]
    r = a["robot"]["radius"]
    if not (r < x < w - r and r < y < h - r):
        raise ArenaError(f"{path}: the robot's start is not inside the arena")
    a["_path"] = path
    return a


class World:
    """One arena and one robot. step() advances by dt from the wheels' encoder
    deltas and the motor duties; sensors() gives the analog codes and binary
    inputs the robot's ports see now."""

    def __init__(self, arena, seed):
        self.arena = arena
        self.rng = np.random.Generator(np.random.PCG64(seed))
        rb = arena["robot"]
        self.r = float(rb["radius"])
        self.axle = float(rb["axle_m"])
        self.counts_per_m = float(rb["counts_per_m"])
        self.bat = rb["battery"]
        self.x, self.y, self.th = (float(v) for v in rb["start"])
        self.soc = float(self.bat["start_soc"])
        self.t = 0.0
        self.alive = True
        self.death_time = None
        self.charging = False
        self.distance = 0.0
        self.recharges = 0          # charging sessions that added >= 10 % of capacity
        self._session_gain = 0.0
        self.collisions = {"wall": 0, "obstacle": 0, "competitor": 0}
        self.wall_collision_times = []
        self.competitor_hits = 0
        self._contacts = set()
        self.bumpers = (False, False)
        st = arena["station"]
        self.station = (float(st["x"]), float(st["y"]), float(st["radius"]))
        self.station_power = float(st["power_w"])
        self.competitors = [dict(c, off_until=0.0) for c in arena.get("competitors", [])]
        self._build_geometry()

    # ---- geometry -------------------------------------------------------
    def _build_geometry(self):
        w, h = self.arena["size"]
        segs = [(0, 0, w, 0, "wall"), (w, 0, w, h, "wall"), (w, h, 0, h, "wall"),
                (0, h, 0, 0, "wall")]
        for s in self.arena.get("walls", []):
            segs.append((*s, "wall"))
        circles = []
        for o in self.arena.get("obstacles", []):
            if "circle" in o:
                circles.append((*o["circle"], "obstacle"))
            else:
                x0, y0, x1, y1 = o["box"]
                segs += [(x0, y0, x1, y0, "obstacle"), (x1, y0, x1, y1, "obstacle"),
                         (x1, y1, x0, y1, "obstacle"), (x0, y1, x0, y0, "obstacle")]
        for i, c in enumerate(self.competitors):
            circles.append((c["x"], c["y"], c["radius"], f"competitor{i}"))
        self.seg = np.array([s[:4] for s in segs], dtype=float)
        self.seg_kind = [s[4] for s in segs]
        self.circ = np.array([c[:3] for c in circles], dtype=float).reshape(-1, 3)
        self.circ_kind = [c[3] for c in circles]
        # Obstacles only (not walls, not competitors): what shadows a light.
        self._shadow_seg = self.seg[[k == "obstacle" for k in self.seg_kind]]
        self._shadow_circ = self.circ[[k == "obstacle" for k in self.circ_kind]]

    def raycast(self, ox, oy, dx, dy, max_range):
        """Distance along the unit ray to the first wall, obstacle or competitor
        (max_range if nothing is nearer)."""
        best = max_range
        if len(self.seg):
            ax, ay, bx, by = self.seg.T
            ex, ey = bx - ax, by - ay
            den = dx * ey - dy * ex
            with np.errstate(divide="ignore", invalid="ignore"):
                t = ((ax - ox) * ey - (ay - oy) * ex) / den
                u = ((ax - ox) * dy - (ay - oy) * dx) / den
            ok = (np.abs(den) > 1e-12) & (t >= 0) & (u >= 0) & (u <= 1)
            if ok.any():
                best = min(best, float(t[ok].min()))
        if len(self.circ):
            cx, cy, cr = self.circ.T
            fx, fy = ox - cx, oy - cy
            b = fx * dx + fy * dy
            c = fx * fx + fy * fy - cr * cr
            disc = b * b - c
            hit = disc >= 0
            if hit.any():
                t = -b[hit] - np.sqrt(disc[hit])
                t = t[t >= 0]
                if len(t):
                    best = min(best, float(t.min()))
        return best

    def _shadowed(self, px, py, qx, qy):
        """True if an obstacle lies on the straight line from p to q."""
        dx, dy = qx - px, qy - py
        length = math.hypot(dx, dy)
        if length == 0:
            return False
        dx, dy = dx / length, dy / length
        seg, circ = self.seg, self.circ
        self.seg, self.circ = self._shadow_seg, self._shadow_circ
        try:
            return self.raycast(px, py, dx, dy, length) < length
        finally:
            self.seg, self.circ = seg, circ

    def _resolve_collisions(self):
        """Pushes the robot's disc out of walls, obstacles and competitors;
        returns the set of (kind, bearing) contacts."""
        contacts = []
        for _ in range(3):
            moved = False
            for (ax, ay, bx, by), kind in zip(self.seg, self.seg_kind):
                ex, ey = bx - ax, by - ay
                u = ((self.x - ax) * ex + (self.y - ay) * ey) / (ex * ex + ey * ey)
                u = min(1.0, max(0.0, u))
                qx, qy = ax + u * ex, ay + u * ey
                d = math.hypot(self.x - qx, self.y - qy)
                if d < self.r:
                    nx, ny = ((self.x - qx) / d, (self.y - qy) / d) if d > 0 else (0.0, 0.0)
                    self.x += nx * (self.r - d)
                    self.y += ny * (self.r - d)
                    contacts.append((kind, math.atan2(qy - self.y, qx - self.x)))
                    moved = True
            for (cx, cy, cr), kind in zip(self.circ, self.circ_kind):
                d = math.hypot(self.x - cx, self.y - cy)
                if d < self.r + cr:
                    nx, ny = ((self.x - cx) / d, (self.y - cy) / d) if d > 0 else (1.0, 0.0)
                    self.x += nx * (self.r + cr - d)
                    self.y += ny * (self.r + cr - d)
                    contacts.append((kind, math.atan2(cy - self.y, cx - self.x)))
                    moved = True
            if not moved:
                break
        return contacts

    # ---- time step ------------------------------------------------------
    def step(self, dt, d_counts_left, d_counts_right, duty_left, duty_right):
        """Advances the world by dt seconds. d_counts_*: encoder counts the
        wheels turned during the step (forward positive); duty_*: motor
        duties 0..1 during the step (for the energy balance)."""
        self.t += dt
        self._update_competitors()
        if self.alive:
            self._move(d_counts_left / self.counts_per_m, d_counts_right / self.counts_per_m)
        self._energy(dt, duty_left, duty_right)

    def _move(self, dl, dr):
        ds = 0.5 * (dl + dr)
        dth = (dr - dl) / self.axle
        mid = self.th + 0.5 * dth
        x0, y0 = self.x, self.y
        self.x += ds * math.cos(mid)
        self.y += ds * math.sin(mid)
        self.th = math.remainder(self.th + dth, 2 * math.pi)
        contacts = self._resolve_collisions()
        self.distance += math.hypot(self.x - x0, self.y - y0)
        kinds = {k for k, _ in contacts}
        for kind in kinds - self._contacts:        # new contacts only
            if kind.startswith("competitor"):
                self.collisions["competitor"] += 1
                c = self.competitors[int(kind[len("competitor"):])]
                if self.t >= c["off_until"]:
                    self.competitor_hits += 1
                    c["off_until"] = self.t + c["off_s"]
            else:
                self.collisions[kind] += 1
                if kind == "wall":
                    self.wall_collision_times.append(self.t)
        self._contacts = kinds
        left = right = False
        for _, bearing in contacts:
            rel = math.remainder(bearing - self.th, 2 * math.pi)
            if abs(rel) <= math.radians(100):        # front half (and a bit): a bumper
                if rel >= -math.radians(10):
                    left = True
                if rel <= math.radians(10):
                    right = True
        self.bumpers = (left, right)

    def _update_competitors(self):
        for c in self.competitors:
            c["on"] = self.t >= c["off_until"]

    def station_available_w(self):
        draw = sum(c["draw_w"] for c in self.competitors if c.get("on", True))
        return max(0.0, self.station_power - draw)

    def in_station(self):
        sx, sy, sr = self.station
        return math.hypot(self.x - sx, self.y - sy) <= sr

    def _energy(self, dt, duty_left, duty_right):
        b = self.bat
        cap = float(b["capacity_j"])
        if not self.alive:
            return
        power = b["idle_w"] + b["motor_w"] * (abs(duty_left) + abs(duty_right))
        self.charging = self.in_station() and self.soc < 1.0
        gain = self.station_available_w() * dt if self.charging else 0.0
        self.soc = min(1.0, self.soc + (gain - power * dt) / cap)
        if self.charging:
            self._session_gain += gain / cap
        else:
            if self._session_gain >= 0.10:
                self.recharges += 1
            self._session_gain = 0.0
        if self.soc <= 0.0:
            self.soc = 0.0
            self.alive = False
            self.death_time = self.t

    def recharges_counted(self):
        """Recharges so far as the summary counts them: with a charging
        session under way that has added 10 % already."""
        return self.recharges + (1 if self._session_gain >= 0.10 else 0)

    def finish(self):
        """Counts a charging session still under way at the end of the run."""
        if self._session_gain >= 0.10:
            self.recharges += 1
            self._session_gain = 0.0

    # ---- sensors --------------------------------------------------------
    def battery_volts(self):
        b = self.bat
        v = b["v_empty"] + (b["v_full"] - b["v_empty"]) * self.soc
        return v + (b["v_charge_boost"] if self.charging else 0.0)

    def _light(self, angle, lights):
        ls = self.arena["robot"]["light_sensors"]
        a = self.th + angle
        px, py = self.x + self.r * math.cos(a), self.y + self.r * math.sin(a)
        half = math.radians(ls["halfwidth_deg"])
        total = 0.0
        for lx, ly, power in lights:
            vx, vy = lx - px, ly - py
            d = math.hypot(vx, vy)
            off = abs(math.remainder(math.atan2(vy, vx) - a, 2 * math.pi)) if d > 1e-9 else 0.0
            if off >= half:
                continue
            i = power * math.cos(off * (math.pi / 2) / half) / (1.0 + d / ls["falloff_m"])
            if self._shadowed(px, py, lx, ly):
                i *= ls["shadow"]
            total += i
        return ls["ambient"] + ls["gain"] * total

    def _ir(self, angle):
        ir = self.arena["robot"]["ir_sensors"]
        a = self.th + angle
        dx, dy = math.cos(a), math.sin(a)
        rng = float(ir["range_m"])
        d = self.raycast(self.x + self.r * dx, self.y + self.r * dy, dx, dy, rng)
        # Sharp GP2D12-like: rises steeply as the target nears; 12 at range.
        return 12.0 + 24.0 * (1.0 / (d + 0.04) - 1.0 / (rng + 0.04))

    def sensors(self):
        """The robot's inputs now, with seeded noise: a dict of analog codes
        (0..255) and binary input levels (active low: 0 = pressed/charging)."""
        rb = self.arena["robot"]
        la = math.radians(rb["light_sensors"]["angle_deg"])
        ia = math.radians(rb["ir_sensors"]["angle_deg"])
        sx, sy, _ = self.station
        station_light = [(sx, sy, float(self.arena["station"]["light_intensity"]))]
        comp_light = [(c["x"], c["y"], 0.6) for c in self.competitors if c.get("on", True)]
        raw = {
            "light_left": self._light(+la, station_light),
            "light_right": self._light(-la, station_light),
            "ir_left": self._ir(+ia),
            "ir_right": self._ir(-ia),
            "battery": self.battery_volts() * 255.0 / self.bat["adc_v_full_scale"],
            "comp_left": self._light(+la, comp_light),
            "comp_right": self._light(-la, comp_light),
        }
        noise = self.rng.normal(0.0, rb["noise_codes"], len(raw))
        codes = {k: int(min(255, max(0, round(v + n)))) for (k, v), n in zip(raw.items(), noise)}
        codes["bumper_left"] = 0 if self.bumpers[0] else 1
        codes["bumper_right"] = 0 if self.bumpers[1] else 1
        codes["charging"] = 0 if self.charging else 1
        return codes

    def state(self):
        return {"t": self.t, "x": self.x, "y": self.y, "th": self.th, "soc": self.soc,
                "charging": self.charging, "alive": self.alive,
                "competitors_on": [c.get("on", True) for c in self.competitors]}
