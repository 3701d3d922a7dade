"""The package's QMP client (robocube_emu.qmp.QMPLink) on a machine under qtest:
a pipelined batch returns its answers in order, and a refused command in the
middle of a batch raises only after every answer of the batch has been read,
so the connection stays in step for the next command."""
import pytest

from robocube_emu import QMPError, qom_get, qom_set

DUART = "/machine/duart"


def test_batch_answers_in_order(machine):
    q = machine.qmp
    a, b = q.batch([qom_get(DUART, "received-b"), ("query-status", None)])
    assert a == 0
    assert b["status"] == "running"            # qtest: the machine runs, the test owns the clock


def test_error_mid_batch_keeps_the_link_in_step(machine):
    q = machine.qmp
    with pytest.raises(QMPError, match="nosuch"):
        q.batch([qom_get(DUART, "received-b"), qom_set(DUART, "nosuch", 1),
                 ("query-status", None)])
    # The next answer read is this command's, not the batch's leftover.
    assert q.execute("qom-get", {"path": DUART, "property": "received-b"}) == 0
    assert q.command("query-status")["status"] == "running"
