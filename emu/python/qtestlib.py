"""The former name of robocube_emu.machine, kept so that tests written against
it still import; new code imports robocube_emu."""

from robocube_emu.launch import die_with_parent as _die_with_parent  # noqa: F401
from robocube_emu.launch import qemu_binary  # noqa: F401
from robocube_emu.machine import (SERIAL_NAMES, SYPCR, Machine, QTestError,  # noqa: F401
                                  SerialPort, start)
from robocube_emu.qmp import QMPError, connect as qmp_connect  # noqa: F401
