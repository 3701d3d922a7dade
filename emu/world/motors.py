"""The wheels: the board's DC motor model (emu/IO.md 1.4,
emu/hw/robocube_motors.c) run by the world instead of the board.

Why the world and not the board: the board's model integrates on its own
1 ms timer, so the count at a lockstep boundary depends on where that timer
falls relative to the boundary, and any jitter in guest timing shows up as a
count early or late (measured: transient one-count differences between
otherwise identical runs). Driven from the world, the wheels integrate the
duty and direction sampled at each boundary over the step, in 1 ms sub-steps
with the same equations and parameters, and the world writes the resulting
counts back to the board (`encoder`, with the board model switched off by
`model-enabled` = 0), so the firmware's TPU still sees every quadrature
edge. The fast mode uses the same class.
"""

import math

MOTOR_STEP_S = 0.001        # the board model's step


class MotorModel:
    """tau d(speed)/dt = duty * max_speed - speed (exact exponential step),
    position += speed dt, whole counts emitted (truncated toward zero)."""

    def __init__(self, max_speed=2000.0, tau_s=0.05):
        self.max_speed, self.tau = max_speed, tau_s
        self.speed = 0.0
        self.frac = 0.0
        self.encoder = 0

    def advance(self, signed_duty, dt):
        """Runs dt seconds at signed_duty (-1..1), in equal sub-steps of at
        most 1 ms; returns the counts turned."""
        before = self.encoder
        n = max(1, math.ceil(dt / MOTOR_STEP_S - 1e-9))
        h = dt / n
        decay = 1.0 - math.exp(-h / self.tau)
        target = signed_duty * self.max_speed
        for _ in range(n):
            self.speed += (target - self.speed) * decay
            self.frac += self.speed * h
            whole = int(self.frac)
            self.frac -= whole
            self.encoder += whole
        return self.encoder - before
