"""The radio medium's message codes and select bits (robocube_emu.radio_medium,
the one Python definition; the host peer imports them from there) against the
board model's, where the C defines them: the RADIO_MSG_* and RADIO_OP_* lines
of emu/hw/mc68681_duart.c, read from the source."""
import re
from pathlib import Path

from robocube_emu import radio_medium

DUART_C = Path(__file__).resolve().parents[1] / "hw" / "mc68681_duart.c"
DEFINE = re.compile(r"^#define\s+(RADIO_(?:MSG|OP)_\w+)\s+(0x[0-9A-Fa-f]+|\d+)\b", re.M)

PYTHON = {
    "RADIO_MSG_DATA": radio_medium.MSG_DATA,
    "RADIO_MSG_CONTROL": radio_medium.MSG_CONTROL,
    "RADIO_MSG_CARRIER": radio_medium.MSG_CONTROL,    # the same code, medium -> board
    "RADIO_MSG_HELLO": radio_medium.MSG_HELLO,
    "RADIO_MSG_SYNC": radio_medium.MSG_SYNC,
    "RADIO_OP_RX": radio_medium.SEL_RX,
    "RADIO_OP_TX": radio_medium.SEL_TX,
}


def c_constants(text):
    return {name: int(value, 0) for name, value in DEFINE.findall(text)}


def test_medium_codes_equal_the_board_models():
    c = c_constants(DUART_C.read_text())
    assert set(c) == set(PYTHON)          # every code the C defines is checked, and no other
    assert {k: (PYTHON[k], c[k]) for k in c if PYTHON[k] != c[k]} == {}


def test_a_changed_code_is_seen():
    """The reader finds a difference: the C with one code changed."""
    text = DUART_C.read_text().replace("#define RADIO_MSG_SYNC    0x03",
                                       "#define RADIO_MSG_SYNC    0x07")
    assert c_constants(text)["RADIO_MSG_SYNC"] == 7 != radio_medium.MSG_SYNC
