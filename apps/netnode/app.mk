# Network demo and test node: the net/ stack on the radio (DUART channel A).
# Its configuration (station, peers, mode, message count) sits in a block the
# host patches per board (tools/netpeer/netnode.py), so one image serves all.
# The radio channel the network runs on.
netnode_NEEDS := console tick radio
netnode_RUN_ARGS := -global mc68681-duart.radio-medium=on
# Its main starts the board itself (board_start ... k_start).
netnode_BOOT := self
# make run APP=netnode: three boards on the radio medium (emu/radio_medium.py),
# each sending 5 messages to the other two; every board's console lines as they
# come ("station N: ...": what it sent, what it received from each station, its
# link statistics), then the totals and the medium's counts.
netnode_RUNNER = $(PYTHON) $(ROOT)/tools/netpeer/soak.py --elf $(call app_elf,netnode) \
                 --boards 3 --no-host --messages 5 --loss 0 --linger 10 --live

# Its suites. net-target: net/tests/target/ puts boards on the medium (2 and 3
# stations, the host peer both ways, a faulty medium, a station that leaves,
# the medium's faults and the board model's radio mode), with net/'s sample
# tools (net/net.mk) for the host side. net-soak: three short soaks (frame
# faults; byte errors with FEC; 8 host peers and a board sending at once). The
# long runs on this image (make net-soak, net-interop, net-bench) are in net/net.mk.
CHECKS += net-target net-soak
EMU_CHECKS += net-target net-soak
.PHONY: check-net-target check-net-soak
check-net-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode $(NET_BUILD)/tests/xdr_sample \
	    $(NET_BUILD)/tests/fec_sample $(NET_BUILD)/tests/wire_constants
	@NETNODE_ELF=$(NETNODE_ELF) $(ROOT)/ci/pytest-suite net-target --durations=0 \
	    $(ROOT)/net/tests/target

# The short soaks of make check: (1) 2 boards and the host peer, 10 % frame
# loss, 10 % corrupted frames, 3 messages per pair (18 messages); (2) with
# FEC: 3 boards and the host peer, 10 % byte errors per
# character, 10 % frame loss, all sending at once, 3 messages per pair (36);
# (3) fan-in: 8 host peers and the board all sending to each other at once,
# 3 messages per pair (48; the long one is make net-soak-fan-in).
# Not niced: beside the proof lane's two busy cores a niced soak got a few
# per cent of a core (20-50 lock-step rounds a second, 5-6 minutes for the
# first soak alone). Every timer runs in the boards' time, so a slow host
# costs only wall time; --timeout is the guard against a hang.
NET_SOAK_CHECKS := "--boards 2 --messages 3 --loss 0.1 --corrupt 0.1 --seed 1" \
                   "--boards 3 --messages 3 --loss 0.1 --byte-errors 0.1 --fec --seed 1" \
                   "--boards 1 --hosts 8 --messages 3 --seed 1"
check-net-soak:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@p=0; f=0; for args in $(NET_SOAK_CHECKS); do \
	    out=$$($(PYTHON) tools/netpeer/soak.py --elf $(NETNODE_ELF) $$args \
	        --timeout 600); rc=$$?; echo "$$out" | tail -2; \
	    if [ $$rc -eq 0 ]; then p=$$((p + 1)); else f=$$((f + 1)); fi; \
	done; $(call record,net-soak,$$p,$$f); [ $$f -eq 0 ]
