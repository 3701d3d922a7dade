# Network demo and test node: the net/ stack on the radio (DUART channel A).
# Its configuration (station, peers, mode, message count) sits in a block the
# host patches per board (tools/netpeer/netnode.py), so one image serves all.
netnode_RUN_ARGS := -global mc68681-duart.radio-medium=on
# Its main starts the board itself (board_start ... k_start).
netnode_BOOT := self
