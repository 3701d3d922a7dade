# The radio network stack (net/), its host peer (tools/netpeer) and the medium
# (emu/python/robocube_emu/radio_medium.py).
#   make check-net-unit     cmocka tests of every layer, under ASan/UBSan
#   make net-soak BOARDS=N HOSTS=H MESSAGES=M LOSS=P CORRUPT=Q BYTE_ERRORS=R SEED=S FEC=0|1
#   make net-soak-fan-in    the last one long: FAN_IN_MESSAGES (20) per pair
#   make net-interop        the host-peer-first tests INTEROP_RUNS (10) times
#   make net-bench          goodput and latency figures (net/README.md), with
#                           authentication and without (its cost)
# The suites of the netnode image (net-target, net-soak) are declared beside it,
# in apps/netnode/app.mk.
NET_BUILD      := $(BUILD)/net
NET_UNIT_NAMES := frame xdr link mac fec
NET_UNIT_TESTS := $(patsubst %,$(NET_BUILD)/tests/test_%,$(NET_UNIT_NAMES))
NET_SANITIZE   ?= -fsanitize=address,undefined -fno-sanitize-recover=all
NET_HOST_FLAGS := $(HOST_CFLAGS) -I$(ROOT) $(NET_SANITIZE)
net_test_srcs_frame := net/frame.c net/crc16.c
net_test_srcs_xdr   := net/xdr.c
net_test_srcs_link  := net/link.c net/packet.c
net_test_srcs_mac   := net/mac.c
net_test_srcs_fec   := net/fec.c net/rs.c net/crc16.c
net_test_libs_xdr   := -I/usr/include/tirpc -ltirpc

ALL += $(NET_UNIT_TESTS) $(NET_BUILD)/tests/xdr_sample $(NET_BUILD)/tests/fec_sample \
       $(NET_BUILD)/tests/wire_constants
CHECKS += net-unit
HOST_UNIT_CHECKS += net-unit

.PHONY: check-net-unit net-soak net-bench

$(NET_BUILD)/tests/test_%: net/tests/test_%.c $(wildcard net/*.h) $(wildcard net/*.c)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) -o $@ $< $(net_test_srcs_$*) -lcmocka $(net_test_libs_$*)

check-net-unit:
	@$(SETUP) base net
	@$(MAKE) --no-print-directory $(NET_UNIT_TESTS)
	@RESULTS=$(RESULTS) ci/cmocka-suite net-unit $(NET_UNIT_TESTS)

# XDR lengths near 2^32 with every size_t width at hand (net/tests/xdr_lengths.c):
# the 64-bit host and the 32-bit host (-m32), both under ASan/UBSan, and the
# CPU32's code generation (-mcpu=cpu32, 32-bit size_t, big-endian) run by
# qemu-user. QEMU has no CPU32 model: -cpu m68020 runs it, as the 68020's
# instruction set holds what GCC emits for the CPU32 here, and the m68k C
# library is 68020 code (the CPU model QEMU picks from the ELF's CPU32 flag
# does not run that library).
NET_XDR_WIDTH_TESTS := $(NET_BUILD)/tests/xdr_lengths $(NET_BUILD)/tests/xdr_lengths_m32 \
                       $(NET_BUILD)/tests/xdr_lengths_cpu32
NET_XDR_WIDTH_SRCS  := net/tests/xdr_lengths.c net/xdr.c
QEMU_M68K_USER ?= qemu-m68k
# Not in HOST_UNIT_CHECKS: assure/ rebuilds those with its own HOST_CFLAGS
# (--coverage, sanitizers), which the m68k build cannot take.
CHECKS += net-xdr-widths
NET_XDR_CPU32_FLAGS := -std=c99 -O2 -g -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror \
                       -mcpu=cpu32 -static -I$(ROOT)
$(NET_BUILD)/tests/xdr_lengths: $(NET_XDR_WIDTH_SRCS) net/xdr.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) -o $@ $(NET_XDR_WIDTH_SRCS)
$(NET_BUILD)/tests/xdr_lengths_m32: $(NET_XDR_WIDTH_SRCS) net/xdr.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) -m32 -o $@ $(NET_XDR_WIDTH_SRCS)
$(NET_BUILD)/tests/xdr_lengths_cpu32: $(NET_XDR_WIDTH_SRCS) net/xdr.h
	@mkdir -p $(@D)
	m68k-linux-gnu-gcc $(NET_XDR_CPU32_FLAGS) -o $@ $(NET_XDR_WIDTH_SRCS)

.PHONY: check-net-xdr-widths
check-net-xdr-widths:
	@$(SETUP) base m68k net32
	@$(MAKE) --no-print-directory $(NET_XDR_WIDTH_TESTS)
	@p=0; f=0; for t in $(NET_XDR_WIDTH_TESTS); do \
	    case $$t in *_cpu32) run="$(QEMU_M68K_USER) -cpu m68020 $$t";; *) run=$$t;; esac; \
	    out=$$(timeout 120 $$run 2>&1); r=$$?; echo "$$out" | tail -40; \
	    if [ $$r -eq 0 ] && echo "$$out" | grep -q ' 0 failed$$'; then p=$$((p + 1)); \
	    else f=$$((f + 1)); echo "$$t: FAILED (exit $$r)"; fi; \
	done; $(call record,net-xdr-widths,$$p,$$f); [ $$f -eq 0 ]

NETNODE_ELF = $(call app_elf,netnode)

# The XDR sample tool the Python comparison (test_xdr_python.py) runs.
$(NET_BUILD)/tests/xdr_sample: net/tests/xdr_sample.c net/tests/xdr_sample.h net/xdr.c net/xdr.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) -o $@ net/tests/xdr_sample.c net/xdr.c

# The FEC tool the reedsolo comparison (test_fec_python.py) runs.
$(NET_BUILD)/tests/fec_sample: net/tests/fec_sample.c net/tests/sample_hex.h net/fec.c net/fec.h net/rs.c net/rs.h net/crc16.c
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) -o $@ net/tests/fec_sample.c net/fec.c net/rs.c net/crc16.c

# The wire constants the host peer's copies are checked against (test_wire_constants.py).
$(NET_BUILD)/tests/wire_constants: net/tests/wire_constants.c $(wildcard net/*.h)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) -o $@ net/tests/wire_constants.c

# The host peer speaking first to a fresh board (the tests marked interop),
# INTEROP_RUNS times in a row: the evidence that the bug of net/README.md
# ("Fixed bugs") stays fixed. Niced, as every heavy run.
INTEROP_RUNS ?= 10
.PHONY: net-interop
net-interop:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@p=0; f=0; for i in $$(seq $(INTEROP_RUNS)); do \
	    if NETNODE_ELF=$(NETNODE_ELF) nice -n 19 $(PYTHON) -m pytest -q -p no:cacheprovider \
	        -m interop $(ROOT)/net/tests/target >$(NET_BUILD)/interop-$$i.log 2>&1; \
	    then p=$$((p + 1)); else f=$$((f + 1)); echo "run $$i failed: $(NET_BUILD)/interop-$$i.log"; fi; \
	done; echo "net-interop: $$p of $(INTEROP_RUNS) runs passed"; [ $$f -eq 0 ]

BOARDS   ?= 2
HOSTS    ?= 1
MESSAGES ?= 5
LOSS     ?= 0.1
CORRUPT  ?= 0.1
BYTE_ERRORS ?= 0
FEC      ?= 0
NET_SOAK_USAGE := make net-soak [BOARDS=1..4] [HOSTS=0..8] [MESSAGES=1..10000] [LOSS=P] [CORRUPT=P] [BYTE_ERRORS=P] [SEED=0..4294967295] [FEC=0|1] (P: 0..1)
# Checked before anything is built: one line and status 2 for a bad value.
ifneq ($(filter net-soak,$(MAKECMDGOALS)),)
$(call check_whole_number,make net-soak,BOARDS,1,4,$(NET_SOAK_USAGE))
$(call check_whole_number,make net-soak,HOSTS,0,8,$(NET_SOAK_USAGE))
$(call check_whole_number,make net-soak,MESSAGES,1,10000,$(NET_SOAK_USAGE))
$(call check_whole_number,make net-soak,SEED,0,4294967295,$(NET_SOAK_USAGE))
$(call check_fraction,make net-soak,LOSS,$(NET_SOAK_USAGE))
$(call check_fraction,make net-soak,CORRUPT,$(NET_SOAK_USAGE))
$(call check_fraction,make net-soak,BYTE_ERRORS,$(NET_SOAK_USAGE))
ifneq ($(filter-out 0 1 on off yes no,$(FEC))$(filter-out 1,$(words $(FEC))),)
$(error make net-soak: FEC='$(FEC)': use FEC=1 (Reed-Solomon frames) or FEC=0 (usage: $(NET_SOAK_USAGE)))
endif
ifeq ($(shell [ $$(( $(BOARDS) + $(HOSTS) )) -ge 2 ] && echo ok),)
$(error make net-soak: BOARDS=$(BOARDS) HOSTS=$(HOSTS): at least 2 stations are needed (usage: $(NET_SOAK_USAGE)))
endif
endif
net-soak:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@$(PYTHON) tools/netpeer/soak.py --elf $(NETNODE_ELF) --boards $(BOARDS) --hosts $(HOSTS) \
	    --messages $(MESSAGES) --loss $(LOSS) --corrupt $(CORRUPT) --byte-errors $(BYTE_ERRORS) \
	    --seed $(SEED) $(if $(filter 1 on yes,$(FEC)),--fec)

# Eight stations (host peers) and one board all sending to each other at
# once: FAN_IN_MESSAGES per pair, everything delivered in order or it fails.
FAN_IN_MESSAGES ?= 20
.PHONY: net-soak-fan-in
net-soak-fan-in:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@$(PYTHON) tools/netpeer/soak.py --elf $(NETNODE_ELF) --boards 1 --hosts 8 \
	    --messages $(FAN_IN_MESSAGES) --seed $(SEED) --timeout 1800

net-bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory firmware APP=netnode
	@nice -n 19 $(PYTHON) tools/netpeer/bench.py --elf $(NETNODE_ELF)
	@nice -n 19 $(PYTHON) tools/netpeer/bench.py --elf $(NETNODE_ELF) --fec
	@nice -n 19 $(PYTHON) tools/netpeer/bench.py --elf $(NETNODE_ELF) --no-auth
	@nice -n 19 $(PYTHON) tools/netpeer/bench.py --elf $(NETNODE_ELF) --fec --no-auth

# ---- fuzzing (libFuzzer, clang-14) and CBMC proofs ----
#   make fuzz             frame parser, XDR decoder, FEC receiver+decoder: FUZZ_RUNS (10^7)
#                         executions each (the FEC one FUZZ_RUNS / NET_FUZZ_FEC_DIV)
#   make check-net-fuzz   the same, 2 x 10^5 executions each (suite net-fuzz)
#   make check-net-cbmc   the memory-safety proofs (suite net-cbmc): frame receiver,
#                         XDR decoder (64-bit size_t, and 32-bit at the widest maxima),
#                         FEC receiver, Reed-Solomon decoder, GF(256)
NET_FUZZ_CC    ?= clang-14
NET_FUZZ_FLAGS := -std=c99 -O1 -g -I$(ROOT) -fsanitize=fuzzer,address,undefined \
                  -fno-sanitize-recover=all
# xdr32: the XDR target built with -m32, so size_t has the CPU32's 32 bits
# (clang-14's i386 libFuzzer runtime; ci/setup.d/net32.sh).
NET_FUZZERS    := frame xdr xdr32 fec
net_fuzz_srcs_frame := net/frame.c net/crc16.c
net_fuzz_srcs_xdr   := net/xdr.c
net_fuzz_srcs_fec   := net/fec.c net/rs.c net/crc16.c
FUZZ_RUNS ?= 10000000
NET_FUZZ_CHECK_RUNS ?= 200000
# A FEC input costs a Reed-Solomon decode (~0.5 ms under ASan): fewer runs.
NET_FUZZ_FEC_DIV ?= 8
# net-cbmc runs in the test lane: the proof lane is make check's wall time
# (1911 s against the test lane's 1342 s on 2026-11-29), and these 117 s of
# CBMC fit in the test lane's slack.
CHECKS += net-fuzz net-cbmc

.PHONY: fuzz check-net-fuzz check-net-cbmc
$(NET_BUILD)/fuzz/fuzz_%: net/fuzz/fuzz_%.c $(wildcard net/*.h) $(wildcard net/*.c) \
                          net/tests/xdr_sample.h
	@mkdir -p $(@D)
	$(NET_FUZZ_CC) $(NET_FUZZ_FLAGS) -o $@ $< $(net_fuzz_srcs_$*)
$(NET_BUILD)/fuzz/fuzz_xdr32: net/fuzz/fuzz_xdr.c net/xdr.c net/xdr.h net/tests/xdr_sample.h
	@mkdir -p $(@D)
	$(NET_FUZZ_CC) $(NET_FUZZ_FLAGS) -m32 -o $@ $< net/xdr.c

# $(1) = runs; prints libFuzzer's last lines; fails on any finding.
define net_fuzz_run
	@p=0; f=0; for t in $(NET_FUZZERS); do \
	    mkdir -p $(NET_BUILD)/fuzz/corpus-$$t; \
	    runs=$(1); if [ $$t = fec ]; then runs=$$(($(1) / $(NET_FUZZ_FEC_DIV))); fi; \
	    out=$$(cd $(NET_BUILD)/fuzz && ./fuzz_$$t -runs=$$runs -seed=1 corpus-$$t 2>&1); r=$$?; \
	    echo "$$out" | tail -2 | sed "s/^/fuzz_$$t: /"; \
	    if [ $$r -eq 0 ]; then p=$$((p + 1)); else f=$$((f + 1)); \
	        echo "fuzz_$$t: FINDING (crash file in $(NET_BUILD)/fuzz)"; fi; \
	done; $(2)
endef

fuzz: $(patsubst %,$(NET_BUILD)/fuzz/fuzz_%,$(NET_FUZZERS))
	$(call net_fuzz_run,$(FUZZ_RUNS),[ $$f -eq 0 ])

check-net-fuzz:
	@$(SETUP) net net32
	@$(MAKE) --no-print-directory $(patsubst %,$(NET_BUILD)/fuzz/fuzz_%,$(NET_FUZZERS))
	$(call net_fuzz_run,$(NET_FUZZ_CHECK_RUNS),$(call record,net-fuzz,$$p,$$f); [ $$f -eq 0 ])

NET_CBMC := $(BSCHED_TOOLS)/cbmc/bin/cbmc
NET_CBMC_CHECKS := --bounds-check --pointer-check --signed-overflow-check --unsigned-overflow-check
# The frame receiver: one arbitrary byte from any state within the invariant
# (an induction over sequences of any length); the CRC's 16-bit arithmetic
# is also checked for truncating conversions.
NET_CBMC_FRAME := --function harness $(NET_CBMC_CHECKS) --conversion-check --unwind 148 \
                  --unwinding-assertions -I $(ROOT) net/proofs/frame_rx_harness.c net/frame.c net/crc16.c
# The XDR decoder on every input of up to XDR_BOUND bytes.
XDR_BOUND ?= 40
NET_CBMC_XDR := --function harness $(NET_CBMC_CHECKS) --unwind $$(($(XDR_BOUND) + 6)) \
                --unwinding-assertions -DXDR_BOUND=$(XDR_BOUND) -I $(ROOT) \
                net/proofs/xdr_decode_harness.c net/xdr.c
# The XDR length arithmetic with a 32-bit size_t (--32, as on the CPU32): every
# length and count 0..UINT32_MAX with max UINT32_MAX, on any stream of up to
# XDR_LEN_BOUND bytes from any position (bounds: net/proofs/xdr_lengths_harness.c).
# One run per routine (XDR_LEN_CASE); --unwindset gives each loop the most
# iterations that many bytes allow, so the unwinding assertions also prove that
# no loop runs longer than the stream holds.
XDR_LEN_BOUND ?= 16
NET_CBMC_XDR32 = --32 --function harness $(NET_CBMC_CHECKS) \
                 --unwindset nxdr_opaque.0:$$(($(XDR_LEN_BOUND) + 1)),nxdr_opaque.1:4,nxdr_string.0:$$(($(XDR_LEN_BOUND) + 1)),nxdr_vector.0:$$(($(XDR_LEN_BOUND) / 4 + 1)) \
                 --unwinding-assertions -DXDR_LEN_BOUND=$(XDR_LEN_BOUND) \
                 -DXDR_LEN_SIZE_MAX=0xFFFFFFFFu -DXDR_LEN_CASE=$(1) -I $(ROOT) \
                 net/proofs/xdr_lengths_harness.c net/xdr.c
# The FEC receiver (interrupt half): the same induction over byte sequences.
NET_CBMC_FEC_RX := --function harness $(NET_CBMC_CHECKS) --conversion-check --unwind 260 \
                   --unwinding-assertions -I $(ROOT) net/proofs/fec_rx_harness.c net/fec.c \
                   net/rs.c net/crc16.c
# The Reed-Solomon decoder on every 28-byte codeword, GF(256) over-approximated
# (RS_GF_ABSTRACT, see rs.c) ...
NET_CBMC_RS_DECODE := --function harness $(NET_CBMC_CHECKS) --unwind 40 \
                      --unwindset gf_init.0:256,gf_init.1:256 --unwinding-assertions \
                      -DRS_GF_ABSTRACT -I $(ROOT) net/proofs/rs_decode_harness.c net/rs.c
# ... and the real GF(256) operations in bounds for every operand.
NET_CBMC_RS_GF := --function harness $(NET_CBMC_CHECKS) --unwind 256 --unwinding-assertions \
                  -I $(ROOT) net/proofs/rs_gf_harness.c
NET_CBMC_RUNS := FRAME XDR XDR32_OPAQUE XDR32_BYTES XDR32_STRING XDR32_ARRAY FEC_RX RS_DECODE RS_GF
check-net-cbmc:
	@$(SETUP) cbmc
	@p=0; f=0; for run in $(NET_CBMC_RUNS); do \
	    case $$run in \
	        FRAME) args="$(NET_CBMC_FRAME)";; XDR) args="$(NET_CBMC_XDR)";; \
        XDR32_OPAQUE) args="$(call NET_CBMC_XDR32,0)";; XDR32_BYTES) args="$(call NET_CBMC_XDR32,1)";; \
        XDR32_STRING) args="$(call NET_CBMC_XDR32,2)";; XDR32_ARRAY) args="$(call NET_CBMC_XDR32,3)";; \
	        FEC_RX) args="$(NET_CBMC_FEC_RX)";; RS_DECODE) args="$(NET_CBMC_RS_DECODE)";; \
	        RS_GF) args="$(NET_CBMC_RS_GF)";; \
	    esac; \
	    out=$$(nice -n 19 $(NET_CBMC) $$args 2>&1); \
	    echo "$$out" | grep -E "^\*\*|VERIFICATION" | sed "s/^/net-cbmc $$run: /"; \
	    if echo "$$out" | grep -q "VERIFICATION SUCCESSFUL"; then p=$$((p + 1)); else f=$$((f + 1)); fi; \
	done; $(call record,net-cbmc,$$p,$$f); [ $$f -eq 0 ]

# ---- frame authentication: net/auth.c on Mbed TLS's AES-CMAC ----
#   make check-net-auth         host unit tests (cmocka, ASan/UBSan): RFC 4493,
#                               flipped bits, replays, the counter policy, restarts
#   make check-net-auth-target  the host peer's MIC (Python cryptography) against
#                               net/auth.c byte for byte; the CPU32 build on the
#                               emulated board against both; its cost measured
#   make net-auth-bench         instructions per seal and open on the board, text size
# Mbed TLS comes from ci/setup mbedtls (build/mbedtls: the sources for the host
# tests, the CPU32 library for the board); ci/setup m68k sets it up too, since
# every image's libnet.a has net/auth.c (net.c seals and opens every frame):
# its configuration and headers go into the images' library flags
# (APP_LIB_CFLAGS), the CPU32 library into the link of every image that has
# libnet.a (APP_LIB_LINK, mk/image.mk). The network needs the board's radio
# channel: its sources are built only for a board that has one.
NET_AUTH_MBEDTLS := $(ROOT)/build/mbedtls
NET_AUTH_MBEDTLS_NAMES := aes cipher cipher_wrap cmac constant_time platform_util
NET_AUTH_CONFIG := -isystem $(NET_AUTH_MBEDTLS)/include -I$(ROOT)/net \
                   '-DMBEDTLS_CONFIG_FILE="auth_mbedtls_config.h"'
APP_LIB_CFLAGS += $(NET_AUTH_CONFIG)
APP_LIB_LINK += $(NET_AUTH_MBEDTLS)/cpu32/libmbedcrypto.a
NEEDS_radio += $(wildcard net/*.c)
# Mbed TLS for the host tests: its own sources, warnings off (they are the
# library's, not ours), the tests' sanitizers and coverage flags kept.
NET_AUTH_MBEDTLS_HOST := $(patsubst %,$(NET_BUILD)/auth/mbedtls/%.o,$(NET_AUTH_MBEDTLS_NAMES))
$(NET_BUILD)/auth/mbedtls/%.o: $(NET_AUTH_MBEDTLS)/library/%.c net/auth_mbedtls_config.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(filter-out -W% -O%,$(HOST_CFLAGS)) -O2 -w $(NET_SANITIZE) $(NET_AUTH_CONFIG) \
	    -I$(NET_AUTH_MBEDTLS)/library -c -o $@ $<
NET_AUTH_TEST   := $(NET_BUILD)/tests/test_auth
NET_AUTH_SAMPLE := $(NET_BUILD)/tests/auth_sample
$(NET_AUTH_TEST): net/tests/test_auth.c net/tests/rfc4493.h net/auth.c net/auth.h net/auth_mbedtls_config.h \
                  $(NET_AUTH_MBEDTLS_HOST)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) $(NET_AUTH_CONFIG) -o $@ net/tests/test_auth.c net/auth.c \
	    $(NET_AUTH_MBEDTLS_HOST) -lcmocka
# The tool the Python comparison (net/tests/auth/test_auth_python.py) drives.
$(NET_AUTH_SAMPLE): net/tests/auth_sample.c net/tests/sample_hex.h net/auth.c net/auth.h net/auth_mbedtls_config.h \
                    $(NET_AUTH_MBEDTLS_HOST)
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(NET_HOST_FLAGS) $(NET_AUTH_CONFIG) -o $@ net/tests/auth_sample.c net/auth.c \
	    $(NET_AUTH_MBEDTLS_HOST)

# The board image: net/auth.c and the CPU32 Mbed TLS on the firmware base
# objects (startup, polled console, kstring.c's memcpy/memset/memcmp), no
# kernel.
NET_AUTH_BOARD_DIR := $(NET_BUILD)/auth/board
NET_AUTH_BOARD_ELF := $(NET_AUTH_BOARD_DIR)/auth_board.elf
NET_AUTH_BOARD_FLAGS := $(call board_cflags,robocube) $(NET_AUTH_CONFIG)
$(NET_AUTH_BOARD_DIR)/%.o: net/%.c net/auth.h net/auth_mbedtls_config.h
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(NET_AUTH_BOARD_FLAGS) -c -o $@ $<
$(NET_AUTH_BOARD_DIR)/auth_board.o: net/tests/auth/auth_board.c net/tests/rfc4493.h net/auth.h
	@mkdir -p $(@D)
	$(call quiet,CC,$<)$(CROSS_CC) $(NET_AUTH_BOARD_FLAGS) -c -o $@ $<
$(NET_AUTH_BOARD_ELF): $(NET_AUTH_BOARD_DIR)/auth_board.o $(NET_AUTH_BOARD_DIR)/auth.o \
                       $(call board_base_objs,robocube) $(BOARD_robocube_LDSCRIPT) \
                       $(NET_AUTH_MBEDTLS)/cpu32/libmbedcrypto.a $(CPU32_RT)
	$(call quiet,LD,$@)$(CROSS_CC) $(call board_ldflags,robocube) -Wl,-Map=$(@:.elf=.map) -o $@ \
	    $(call board_base_objs,robocube) \
	    $(NET_AUTH_BOARD_DIR)/auth_board.o $(NET_AUTH_BOARD_DIR)/auth.o \
	    $(NET_AUTH_MBEDTLS)/cpu32/libmbedcrypto.a $(CPU32_RT)
	$(if $(filter 1,$(V)),$(CROSS_SIZE) $@,@true)

CHECKS += net-auth net-auth-target
EMU_CHECKS += net-auth-target
HOST_UNIT_CHECKS += net-auth
.PHONY: check-net-auth check-net-auth-target net-auth-bench
check-net-auth:
	@$(SETUP) base m68k
	@$(MAKE) --no-print-directory $(NET_AUTH_TEST)
	@RESULTS=$(RESULTS) ci/cmocka-suite net-auth $(NET_AUTH_TEST)

check-net-auth-target:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(NET_AUTH_SAMPLE) $(NET_AUTH_BOARD_ELF)
	@NET_AUTH_SAMPLE=$(NET_AUTH_SAMPLE) NET_AUTH_BOARD_ELF=$(NET_AUTH_BOARD_ELF) \
	    BSCHED_QEMU=$(QEMU_M68K) $(ROOT)/ci/pytest-suite net-auth-target $(ROOT)/net/tests/auth

net-auth-bench:
	@$(SETUP) base m68k qemu
	@$(MAKE) --no-print-directory $(NET_AUTH_BOARD_ELF)
	@nice -n 19 $(PYTHON) net/tests/auth/auth_measure.py $(NET_AUTH_BOARD_ELF) $(QEMU_M68K)
