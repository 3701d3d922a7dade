"""Host fast mode: the robot program runs on the host (the same sources and
bsched.c, as a shared library through ctypes) against the same world, with a
host copy of the board's motor model instead of the emulator. For developing
behaviours: minutes of virtual time in seconds.

Two kinds of library: the ecosystem's (apps/ecosystem/host/eco_host.c, which also
reports its behaviours' contributions for the live view) and any PDL program
with an ordinary main (pdl/host/pdl_app_host.c, apps/apps.mk's
app_host_lib): the world gives it every analog input and the DUART input port
and takes motors 0..2, as the board's ports (wiring: pdl/robot.h)."""

import ctypes

from cosim import analog_inputs, input_port, sensor_inputs
from motors import MotorModel

CYCLE_S = 1.0 / 64          # the ecosystem firmware's minor cycle: 2 ticks of 128 Hz


class ProcessRuns:
    """The program's processes and how often each ran (pdl_process_table),
    read through the runtime's functions."""

    def __init__(self, lib):
        lib.pdl_process_name.restype = ctypes.c_char_p
        lib.pdl_process_runs.restype = ctypes.c_uint32
        self.lib = lib

    def read(self):
        n = self.lib.pdl_process_count()
        return {self.lib.pdl_process_name(i).decode() or f"process{i}":
                self.lib.pdl_process_runs(i) for i in range(n)}


class HostProgram:
    """The ecosystem's library (eco_host_*)."""

    def __init__(self, lib_path, seed):
        self.lib = ctypes.CDLL(lib_path)
        self.lib.eco_host_cycle.restype = ctypes.c_uint32
        self.lib.eco_host_name.restype = ctypes.c_char_p
        rc = self.lib.eco_host_init(ctypes.c_uint32(seed & 0xFFFFFFFF))
        if rc != 0:
            raise RuntimeError(f"eco_host_init: bsched_init returned {rc}")
        self.procs = self.lib.eco_host_procs()
        self.names = [self.lib.eco_host_name(i).decode() for i in range(self.procs)]
        self._in = (ctypes.c_int32 * 10)()
        self._out = (ctypes.c_int32 * (3 + 2 * self.procs))()
        self.runs = ProcessRuns(self.lib)
        self.cycle_s = CYCLE_S

    def cycle(self, inputs):
        for i, v in enumerate(inputs):
            self._in[i] = v
        mask = self.lib.eco_host_cycle(self._in, self._out)
        out = list(self._out)
        return mask, out

    def step(self, codes, wiring):
        """One cycle: (left, right) permille and the status for the view."""
        mask, out = self.cycle(sensor_inputs(codes, wiring))
        if mask == 0xFFFFFFFF:
            raise RuntimeError("the PDL host runtime refused to run a cycle")
        status = {"ran": [self.names[i] for i in range(self.procs) if mask >> i & 1],
                  "motor": (out[0], out[1]), "hunger": out[2],
                  "contrib": {self.names[i]: (out[3 + 2 * i], out[4 + 2 * i])
                              for i in range(self.procs)}}
        return (out[0], out[1]), status

    def console(self):
        return []


class AppProgram:
    """Any PDL program with an ordinary main (pdl_app_host_*)."""

    def __init__(self, lib_path):
        self.lib = ctypes.CDLL(lib_path)
        self.lib.pdl_app_host_console.restype = ctypes.c_size_t
        self.lib.pdl_period_us.restype = ctypes.c_uint32
        self._buf = ctypes.create_string_buffer(65536)
        self._pending = b""
        self.started = self.lib.pdl_app_host_start()
        self.runs = ProcessRuns(self.lib)
        self.cycle_s = self.lib.pdl_period_us() / 1e6
        self._analog = (ctypes.c_int32 * 24)()
        self._motors = (ctypes.c_int32 * 3)()

    def step(self, codes, wiring):
        for i, v in enumerate(analog_inputs(codes, wiring)):
            self._analog[i] = v
        if self.lib.pdl_app_host_cycle(self._analog, input_port(codes, wiring), self._motors) != 0:
            raise RuntimeError("the PDL host runtime refused to run a cycle")
        m = (self._motors[wiring["motor_left"]], self._motors[wiring["motor_right"]])
        return m, {"motor": m}

    def console(self):
        """New complete lines the program printed."""
        while True:
            n = self.lib.pdl_app_host_console(self._buf, len(self._buf))
            if not n:
                break
            self._pending += self._buf.raw[:n]
        *lines, self._pending = self._pending.split(b"\n")
        return [ln.decode(errors="replace") for ln in lines]


def open_program(lib_path, seed):
    """The library's program, started. Raises RuntimeError if main never
    started the cycles (its console says why)."""
    probe = ctypes.CDLL(lib_path)
    if hasattr(probe, "pdl_app_host_start"):
        prog = AppProgram(lib_path)
        if prog.started != 0:
            text = "; ".join(prog.console())
            raise RuntimeError("the program's main returned or waits without calling run_pdl()"
                               + (f" (its console: {text})" if text else ""))
        return prog
    return HostProgram(lib_path, seed)


def run_host(world, rec, lib_path, seed, seconds, step_s=0.0078125, on_step=None,
             on_console=None, on_runs=None, runs_every_s=1.0):
    prog = open_program(lib_path, seed)
    wiring = world.arena["wiring"]
    motors = [MotorModel(), MotorModel()]
    duty = [0.0, 0.0]
    next_cycle = 0.0
    t = 0.0
    status = {}
    steps = int(round(seconds / step_s))
    runs_steps = max(1, int(round(runs_every_s / step_s)))
    if on_console:
        for line in prog.console():
            on_console(line)
    for k in range(steps):
        # Cycles due in this step, at their own times (sensors as of the step start).
        while next_cycle < t + step_s - 1e-12:
            m, status = prog.step(world.sensors(), wiring)
            duty = [m[0] / 1000.0, m[1] / 1000.0]
            next_cycle += prog.cycle_s
        if not world.alive:
            duty = [0.0, 0.0]
        turned = [mo.advance(d, step_s) for mo, d in zip(motors, duty)]
        t = (k + 1) * step_s
        world.step(step_s, turned[0], turned[1], abs(duty[0]), abs(duty[1]))
        rec.last_status = status
        if on_console:
            for line in prog.console():
                on_console(line)
        if on_runs and (k + 1) % runs_steps == 0:
            on_runs(prog.runs.read())
        rec.step(int(round(t * 1e9)))
        if on_step:
            on_step(world, rec)
        if not world.alive:
            break
    if on_runs:
        on_runs(prog.runs.read())
