# Network demo and test node: the net/ stack on the radio (DUART channel A).
# Its configuration (station, peers, mode, message count) sits in a block the
# host patches per board (tools/netpeer/netnode.py), so one image serves all.
netnode_RUN_ARGS := -global mc68681-duart.radio-medium=on
# Its main starts the board itself (board_start ... k_start).
netnode_BOOT := self
# make run APP=netnode: three boards on the radio medium (emu/radio_medium.py),
# each sending 5 messages to the other two; every board's console lines as they
# come ("station N: ...": what it sent, what it received from each station, its
# link statistics), then the totals and the medium's counts.
netnode_RUNNER = $(PYTHON) $(ROOT)/tools/netpeer/soak.py --elf $(call app_elf,netnode) \
                 --boards 3 --no-host --messages 5 --loss 0 --linger 10 --live
