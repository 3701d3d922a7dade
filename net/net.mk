# The radio network stack (net/), its host peer (tools/netpeer) and the medium
# (emu/radio_medium.py).
#   make check-net-unit     cmocka tests of every layer, under ASan/UBSan
#   make check-net-target   boards on the medium: 2 and 3 stations, the host
#                           peer both ways, a faulty medium, a station that leaves
#   make net-soak BOARDS=N MESSAGES=M LOSS=P CORRUPT=Q SEED=S
#   make check-net-soak     a short soak (2 boards + host peer, 10 % loss and corruption)
#   make net-bench          goodput and latency figures (net/README.md)
NET_BUILD      := $(BUILD)/net
NET_UNIT_NAMES := frame xdr link mac
NET_UNIT_TESTS := $(patsubst %,$(NET_BUILD)/tests/test_%,$(NET_UNIT_NAMES))
NET_SANITIZE   ?= -fsanitize=address,undefined -fno-sanitize-recover=all
NET_HOST_FLAGS := $(HOST_CFLAGS) -I$(ROOT) $(NET_SANITIZE)
net_test_srcs_frame := net/frame.c net/crc16.c
net_test_srcs_xdr   := net/xdr.c
net_test_srcs_link  := net/link.c net/packet.c
net_test_srcs_mac   := net/mac.c
net_test_libs_xdr   := -I/usr/include/tirpc -ltirpc

ALL += $(NET_UNIT_TESTS)
CHECKS += net-unit net-target net-soak
HOST_UNIT_CHECKS += net-unit

.PHONY: check-net-unit check-net-target check-net-soak net-soak net-bench net-target-slow

$(NET_BUILD)/tests/test_%: net/tests/test_%.c $(wildcard net/*.h) $(wildcard net/*.c)
	@mkdir -p $(@D)
	$(HOST_CC) $(NET_HOST_FLAGS) -o $@ $< $(net_test_srcs_$*) -lcmocka $(net_test_libs_$*)

check-net-unit:
	@$(SETUP) base net
	@$(MAKE) --no-print-directory $(NET_UNIT_TESTS)
	@p=0; f=0; rc=0; \
	for t in $(NET_UNIT_TESTS); do \
	    out=$$($$t 2>&1); r=$$?; echo "$$out"; [ $$r -eq 0 ] || rc=1; \
	    tp=$$(echo "$$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | tail -1); \
	    tf=$$(echo "$$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | tail -1); \
	    if [ -z "$$tp$$tf" ]; then tf=1; fi; \
	    p=$$((p + $${tp:-0})); f=$$((f + $${tf:-0})); \
	done; \
	$(call record,net-unit,$$p,$$f); [ $$rc -eq 0 ]

NETNODE_ELF := $(call app_elf,netnode)

check-net-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@NETNODE_ELF=$(NETNODE_ELF) $(ROOT)/ci/pytest-suite net-target -m "not slow" --durations=0 \
	    $(ROOT)/net/tests/target

# A station that leaves mid-transfer: minutes of retries, not in make check.
net-target-slow:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@NETNODE_ELF=$(NETNODE_ELF) $(PYTHON) -m pytest -q -p no:cacheprovider -m slow $(ROOT)/net/tests/target

BOARDS   ?= 2
MESSAGES ?= 5
LOSS     ?= 0.1
CORRUPT  ?= 0.1
SEED     ?= 1
net-soak:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@$(PYTHON) tools/netpeer/soak.py --elf $(NETNODE_ELF) --boards $(BOARDS) \
	    --messages $(MESSAGES) --loss $(LOSS) --corrupt $(CORRUPT) --seed $(SEED)

# The short soak of make check: 2 boards and the host peer, 10 % frame loss,
# 10 % corrupted frames, 3 messages per pair (18 messages).
check-net-soak:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@out=$$($(PYTHON) tools/netpeer/soak.py --elf $(NETNODE_ELF) --boards 2 --messages 3 \
	    --loss 0.1 --corrupt 0.1 --seed 1 --timeout 150); rc=$$?; echo "$$out"; \
	if [ $$rc -eq 0 ]; then $(call record,net-soak,1,0); else $(call record,net-soak,0,1); fi; \
	[ $$rc -eq 0 ]

net-bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@$(PYTHON) tools/netpeer/bench.py --elf $(NETNODE_ELF)
