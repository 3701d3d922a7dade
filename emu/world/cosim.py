"""Lockstep co-simulation: the emulated RoboCube (QEMU, real firmware) and the
world advance together in fixed steps of virtual time.

Every step: QEMU stops at the boundary (/machine/lockstep, see
emu/README.md "Lockstep") and sends one line on the lockstep chardev with the
wheel motors' duty and direction; the host runs the motor model (motors.py)
and the world over the step and answers with one line of sensor codes,
binary inputs and the wheels' encoder counts, which the device writes before
it resumes the machine by itself. (QMP only
sets the lists up: a QMP command costs about as much as a whole step.) Virtual time follows only the instruction count (-icount
shift=8,sleep=off), so the same firmware, arena and seed give the same run
bit for bit, whatever the load on the host.
"""

import os
import re
import struct
import subprocess

from robocube_emu.lockstep import LOCKSTEP, Emulator
from robocube_emu.qmp import qom_set

from motors import MotorModel

IO = "/machine/robocube-io"
# The step: one tick of the ecosystem firmware's 128 Hz kernel clock, and the
# boundaries placed TICK_LEAD_NS before each tick once the firmware has
# started its PIT (the lockstep device's origin-ns). Between a tick and the
# next boundary the firmware does its I/O: the PDL cycle (snapshot in, motor
# writes out) right after the tick and the sampler's sweep of the converters
# (6.0 ms, drivers/README.md). So the inputs of a step are in place just before
# the cycle that reads them, and all the motor writes of that cycle are seen at
# the next boundary: one step of latency each way, never a split cycle. (Runs
# are reproducible with boundaries at any phase, emu/README.md; the placement
# is for the latency.)
TICK_LEAD_NS = 200_000
STEP_NS = 7_812_500
ANALOG = ("light_left", "light_right", "ir_left", "ir_right", "battery", "comp_left",
          "comp_right")


def sensor_inputs(codes, wiring):
    """The program's inputs in eco_host_cycle order (flags 1 = active)."""
    return [codes[k] for k in ANALOG] + [1 - codes["bumper_left"], 1 - codes["bumper_right"],
                                         1 - codes["charging"]]


def analog_inputs(codes, wiring):
    """The board's 24 analog inputs as the world sets them (unwired: 0)."""
    ain = [0] * 24
    for k in ANALOG:
        ain[wiring["ain_" + k]] = codes[k]
    return ain


def input_port(codes, wiring):
    """DUART IP0-IP5 levels: pulled up (1) unless a bumper or the charger pulls low."""
    level = 0x3F
    for key, pin in (("bumper_left", "ip_bumper_left"), ("bumper_right", "ip_bumper_right"),
                     ("charging", "ip_charging")):
        if codes[key] == 0:
            level &= ~(1 << wiring[pin])
    return level


STATUS_RE = re.compile(r"^eco t=(\d+) ml=(-?\d+) mr=(-?\d+) h=(\d+) ran=([0-9a-f]+) "
                       r"ovr=(\d+) c=(\S+)$")


def parse_status(line, names):
    """Parses the firmware's status line (apps/ecosystem/ecosystem.c)."""
    m = STATUS_RE.match(line)
    if not m:
        return None
    mask = int(m.group(5), 16)
    pairs = [p.split("/") for p in m.group(7).split(",")]
    return {"ms": int(m.group(1)), "motor": (int(m.group(2)), int(m.group(3))),
            "hunger": int(m.group(4)),
            "ran": [n for i, n in enumerate(names) if mask >> i & 1],
            "overruns": int(m.group(6)),
            "contrib": {n: (int(a), int(b)) for n, (a, b) in zip(names, pairs)}}


PROCESS_TABLE = "pdl_process_table"
PDL_MAX_PROCESSES = 32


class BoardProcessRuns:
    """The PDL program's processes and how often each ran, read from the
    board's memory (pdl_process_table, pdl/pdl.h: count, runs[32], names[32],
    big-endian 32-bit words) with QMP memsave while the machine stands at a
    lockstep boundary. None when the image has no PDL runtime."""

    SIZE = 4 + 8 * PDL_MAX_PROCESSES

    @classmethod
    def open(cls, emu, elf, nm="m68k-linux-gnu-nm"):
        try:
            out = subprocess.run([nm, elf], capture_output=True, text=True, timeout=30).stdout
        except (OSError, subprocess.SubprocessError):
            return None
        for line in out.splitlines():
            words = line.split()
            if len(words) == 3 and words[2] == PROCESS_TABLE:
                return cls(emu, int(words[0], 16))
        return None

    def __init__(self, emu, address):
        self.emu, self.address, self.names = emu, address, {}
        self.path = os.path.join(emu.dir, "mem")

    def _mem(self, address, size):
        self.emu.qmp.execute("memsave", {"val": address, "size": size, "filename": self.path})
        with open(self.path, "rb") as f:
            return f.read()

    def read(self):
        words = struct.unpack(f">{1 + 2 * PDL_MAX_PROCESSES}I", self._mem(self.address, self.SIZE))
        n = min(words[0], PDL_MAX_PROCESSES)
        runs = {}
        for i in range(n):
            ptr = words[1 + PDL_MAX_PROCESSES + i]
            if (i, ptr) not in self.names:
                name = self._mem(ptr, 48).split(b"\0")[0].decode(errors="replace") if ptr else ""
                self.names[(i, ptr)] = name or f"process{i}"
            runs[self.names[(i, ptr)]] = words[1 + i]
        return runs


def run_emulated(world, rec, qemu, elf, names, seconds, step_ns=STEP_NS, on_step=None,
                 on_console=None, on_runs=None, runs_every_s=1.0):
    """Runs the lockstep loop for `seconds` of virtual time (or until the
    battery is empty). names: the program's process names, in index order
    (for the ecosystem's status line). on_runs gets the processes' run
    counts every runs_every_s of virtual time and at the end."""
    wiring = world.arena["wiring"]
    ml, mr = wiring["motor_left"], wiring["motor_right"]
    sample = [f"{LOCKSTEP}:boundary-ns"]
    for m in (ml, mr):
        sample += [f"{IO}/motor{m}:duty", f"{IO}/motor{m}:direction"]
    sample += ["/machine/sim:pit-start-ns", "/machine/sim:pit-period-ns"]
    inputs = [f"{IO}:ain{wiring['ain_' + k]}" for k in
              ("light_left", "light_right", "ir_left", "ir_right", "battery", "comp_left",
               "comp_right")] + ["/machine/duart:input-port", f"{IO}/motor{ml}:encoder",
                                 f"{IO}/motor{mr}:encoder"]
    wheels = [MotorModel(), MotorModel()]
    emu = Emulator(qemu, elf, step_ns)
    runs_steps = max(1, int(round(runs_every_s * 1e9 / step_ns)))
    try:
        reader = BoardProcessRuns.open(emu, elf) if on_runs else None
        q = emu.qmp
        q.batch([qom_set(f"{IO}/motor{ml}", "model-enabled", 0),
                 qom_set(f"{IO}/motor{mr}", "model-enabled", 0),
                 qom_set(LOCKSTEP, "sample-props", " ".join(sample)),
                 qom_set(LOCKSTEP, "input-props", " ".join(inputs))])
        codes = world.sensors()
        q.execute("qom-set", {"path": LOCKSTEP, "property": "inputs",
                              "value": [codes[k] for k in ANALOG] + [input_port(codes, wiring),
                                                                     0, 0]})
        end_ns = int(round(seconds * 1e9))
        prev_ns, aligned, k = 0, 0, 0       # aligned: stops since the origin was set
        q.execute("cont")
        while prev_ns + step_ns <= end_ns:
            f = emu.read_frame()
            k += 1
            t_ns, s = f[1], f[2:]
            dt_ns = t_ns - prev_ns
            if f[0] != k or dt_ns <= 0 or dt_ns > step_ns or (aligned > 1 and dt_ns != step_ns):
                raise RuntimeError(f"lockstep: stop {f[0]} at {t_ns} ns after {prev_ns} ns "
                                   f"(expected stop {k}, {step_ns} ns later)")
            prev_ns = t_ns
            pit_start, pit_period = s[5], s[6]
            if aligned:
                aligned += 1
            elif pit_period == step_ns:
                # The PIT runs at the step's rate: put the boundaries just before its ticks.
                q.execute("qom-set", {"path": LOCKSTEP, "property": "origin-ns",
                                      "value": pit_start + step_ns - TICK_LEAD_NS})
                aligned = 1
            # Duty and direction in effect at the boundary drive the wheels for the step.
            duty_l, duty_r = s[1] / 10000.0, s[3] / 10000.0
            if not world.alive:
                duty_l = duty_r = 0.0
            turned = [w.advance(d * direction, dt_ns / 1e9)
                      for w, d, direction in ((wheels[0], duty_l, s[2]), (wheels[1], duty_r, s[4]))]
            world.step(dt_ns / 1e9, turned[0], turned[1], duty_l * abs(s[2]), duty_r * abs(s[4]))
            codes = world.sensors()
            if reader and (k % runs_steps == 0 or prev_ns + step_ns > end_ns or not world.alive):
                on_runs(reader.read())      # the machine stands at the boundary
            emu.send_inputs([codes[c] for c in ANALOG] +
                            [input_port(codes, wiring), wheels[0].encoder, wheels[1].encoder])
            for line in emu.read_console():
                st = parse_status(line, names)
                if st:
                    rec.last_status = st
                    rec.overruns = st["overruns"]
                    rec.status_lines += 1
                elif on_console:
                    on_console(line)
            rec.step(t_ns)
            if on_step:
                on_step(world, rec)
            if not world.alive:
                break
    finally:
        err = emu.close()
    return err
