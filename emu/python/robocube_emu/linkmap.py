"""The input sections of a firmware image's GNU ld map: what a size or
footprint figure of an image for the board is counted from."""

import re


def input_sections(map_path, kinds=("text", "rodata")):
    """(section, address, size, object) for every input section of the given
    kinds the link kept, from a GNU ld map (objects in archives read
    'lib.a(obj.o)')."""
    text = open(map_path).read()
    body = text.split("Linker script and memory map", 1)[1]
    names = "|".join(kinds)
    pending = None
    for line in body.splitlines():
        m = re.match(rf"^ (\.(?:{names})\S*)\s*$", line)
        if m:
            pending = m.group(1)
            continue
        m = re.match(rf"^ (\.(?:{names})\S*)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+(\S+\.o\)?)\s*$", line)
        if m and (m.group(1) or pending):
            yield (m.group(1) or pending), int(m.group(2), 16), int(m.group(3), 16), m.group(4)
        pending = None
