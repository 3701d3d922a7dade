# The Cortex-M4 (the STM32F405 board's CPU) for the bsched-package suite's
# cross build. It lives with the test, not in bsched/: an embedder builds with
# their own toolchain file, and this one only has to show that the package
# cross-builds.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -ffreestanding")
# No C library, start files or libgcc.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -nostartfiles -static")
# The compiler checks link no program: there is no C library to link.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
