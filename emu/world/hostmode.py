"""Host fast mode: the robot program runs on the host (the same
eco_program.c and bsched.c, as a shared library through ctypes) against the
same world, with a host copy of the board's motor model instead of the
emulator. For developing behaviours: minutes of virtual time in seconds."""

import ctypes

from cosim import sensor_inputs
from motors import MotorModel

CYCLE_S = 1.0 / 64          # the firmware's minor cycle: 2 ticks of 128 Hz


class HostProgram:
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

    def cycle(self, inputs):
        for i, v in enumerate(inputs):
            self._in[i] = v
        mask = self.lib.eco_host_cycle(self._in, self._out)
        out = list(self._out)
        return mask, out


def run_host(world, rec, lib_path, seed, seconds, step_s=0.0078125, on_step=None):
    prog = HostProgram(lib_path, seed)
    wiring = world.arena["wiring"]
    motors = [MotorModel(), MotorModel()]
    duty = [0.0, 0.0]
    next_cycle = 0.0
    t = 0.0
    status = {}
    steps = int(round(seconds / step_s))
    for k in range(steps):
        # Cycles due in this step, at their own times (sensors as of the step start).
        while next_cycle < t + step_s - 1e-12:
            mask, out = prog.cycle(sensor_inputs(world.sensors(), wiring))
            if mask == 0xFFFFFFFF:
                raise RuntimeError("the PDL host runtime refused to run a cycle")
            duty = [out[0] / 1000.0, out[1] / 1000.0]
            status = {"ran": [prog.names[i] for i in range(prog.procs) if mask >> i & 1],
                      "motor": (out[0], out[1]), "hunger": out[2],
                      "contrib": {prog.names[i]: (out[3 + 2 * i], out[4 + 2 * i])
                                  for i in range(prog.procs)}}
            next_cycle += CYCLE_S
        if not world.alive:
            duty = [0.0, 0.0]
        turned = [m.advance(d, step_s) for m, d in zip(motors, duty)]
        t = (k + 1) * step_s
        world.step(step_s, turned[0], turned[1], abs(duty[0]), abs(duty[1]))
        rec.last_status = status
        rec.step(int(round(t * 1e9)))
        if on_step:
            on_step(world, rec)
        if not world.alive:
            break
