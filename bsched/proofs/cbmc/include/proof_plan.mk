# The make settings of the harnesses built on proof_plan.h (step, agree), which
# their Makefiles include before ../Makefile.common: the default bounds (N:
# largest process count, also BSCHED_MAX_PROCS; P: largest priority value), one
# input order per multiset (ascending, as proof_plan.h assumes), and the
# bounds of proof_model.h's and proof_plan.h's loops (processes <= N, classes
# 32, bits <= P) for the harness's UNWINDSET.
N ?= 16
P ?= 8
override EXTRA_DEFINES += -DPROOF_SORTED_INPUT=1
N1 = $(shell echo $$(($(N)+1)))
P1 = $(shell echo $$(($(P)+1)))
PROOF_PLAN_UNWINDSET = proof_nondet_set.0:$(N1), proof_plan_at.0:33, proof_plan_at.1:$(N1), \
                       proof_plan_at.2:33, proof_plan_next_ok.0:33, \
                       proof_reverse_bits.0:$(P1), proof_reverse_p.0:$(P1)
