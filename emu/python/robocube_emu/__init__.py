"""The RoboCube emulator from Python: starting qemu-system-m68k -M robocube
(launch), its QMP (qmp), a machine under qtest or running an image with its
serial ports (machine), the lockstep device (lockstep), QEMU's exec trace
(exectrace) and the shared radio medium (radio_medium). ci/setup puts this
folder's parent on the path of the checkout's environment (build/venv)."""

from .launch import ICOUNT, ROOT, command, die_with_parent, popen, qemu_binary  # noqa: F401
from .machine import Machine, QTestError, SerialPort, start  # noqa: F401
from .qmp import QMPError, QMPLink, connect, qom_get, qom_set  # noqa: F401
