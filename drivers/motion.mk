# The motion drivers (drivers/tpu.c, motor.c, motor_pi.c, odometry.c):
#   make check-motion-unit     host cmocka tests: PI controller, odometry
#   make check-motion-target   apps/motiontest on the emulated board, checked over QMP
#                              (declared with the image, apps/motiontest/app.mk)
#   make motion-size           text/data/bss of the motion drivers for CPU32 (-Os)

MOTION_BUILD      := $(BUILD)/motion
MOTION_UNIT_TESTS := $(MOTION_BUILD)/test_motor_pi $(MOTION_BUILD)/test_odometry
MOTION_SRCS       := drivers/tpu.c drivers/motor.c drivers/motor_pi.c drivers/odometry.c

CHECKS += motion-unit
HOST_UNIT_CHECKS += motion-unit

.PHONY: motion-unit-tests check-motion-unit motion-size
motion-unit-tests: $(MOTION_UNIT_TESTS)
ALL += $(MOTION_UNIT_TESTS)

$(MOTION_BUILD)/test_motor_pi: drivers/tests/test_motor_pi.c drivers/motor_pi.c drivers/motor_pi.h
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(HOST_CFLAGS) -I$(ROOT) -o $@ drivers/tests/test_motor_pi.c drivers/motor_pi.c -lcmocka

$(MOTION_BUILD)/test_odometry: drivers/tests/test_odometry.c drivers/odometry.c drivers/odometry.h drivers/drv_err.c
	@mkdir -p $(@D)
	$(call quiet,HOSTCC,$@)$(HOST_CC) $(HOST_CFLAGS) -I$(ROOT) -o $@ drivers/tests/test_odometry.c drivers/odometry.c \
	    drivers/drv_err.c -lcmocka -lm

check-motion-unit: $(MOTION_UNIT_TESTS)
	@$(SETUP) base
	@RESULTS=$(RESULTS) ci/cmocka-suite motion-unit $(MOTION_UNIT_TESTS)

motion-size:
	@$(MAKE) --no-print-directory firmware APP=motiontest
	@$(CROSS_SIZE) $(patsubst %,$(FW_BUILD)/motiontest/obj/%.o,$(MOTION_SRCS)) | awk \
	    '{ print } NR>1 { t += $$1; d += $$2; b += $$3 } \
	     END { printf "motion drivers: text %d, data %d, bss %d bytes\n", t, d, b }'
