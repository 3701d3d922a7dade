"""Runs an emulator whose console is its stdio, holding back what is piped into
it until the board has written its first byte.

QEMU reads a pipe on stdin as soon as it starts, and a UART model that is not
yet enabled drops what it is given (the STM32's USART model does, as the chip
does before the firmware sets its enable bits): `printf 'help\\n' | make run`
would lose the commands to the boot. A board writes nothing before its console
is set up, so its first byte says the receiver is on; from then on stdin is
passed through as it comes. The board's output goes to stdout unchanged.

    python -m robocube_emu.console_gate CMD [ARG...]
Exit status: CMD's (2 with a usage line when CMD is missing). SIGINT and
SIGTERM are passed on to CMD.
"""
import os
import signal
import subprocess
import sys
import threading

from .launch import die_with_parent

CHUNK = 4096


def pump_stdin(child, gate):
    """Our stdin to the child's, once the gate opens; closes it at end of file."""
    gate.wait()
    try:
        while True:
            data = os.read(0, CHUNK)
            if not data:
                break
            child.stdin.write(data)
            child.stdin.flush()
    except (BrokenPipeError, OSError):
        pass
    finally:
        try:
            child.stdin.close()
        except OSError:
            pass


def main(argv):
    if not argv:
        print("usage: python -m robocube_emu.console_gate CMD [ARG...]", file=sys.stderr)
        return 2
    # The emulator dies with this process (however it ends), so that no
    # emulator is left running when a reader goes away or a timeout kills it.
    child = subprocess.Popen(argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, bufsize=0,
                             preexec_fn=die_with_parent)
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda s, f: child.send_signal(s))
    gate = threading.Event()
    threading.Thread(target=pump_stdin, args=(child, gate), daemon=True).start()
    while True:
        data = child.stdout.read(CHUNK)
        if not data:
            break
        gate.set()
        try:
            os.write(1, data)
        except BrokenPipeError:     # the reader is gone (`make run | head`): stop the board
            child.terminate()
            child.wait()
            return 0
    return child.wait()


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
