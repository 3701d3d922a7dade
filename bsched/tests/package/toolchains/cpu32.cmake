# The MC68332 (CPU32) for the bsched-package suite's cross build. It lives
# with the test, not in bsched/: an embedder builds with their own toolchain
# file, and this one only has to show that the package cross-builds.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR m68k)
set(CMAKE_C_COMPILER m68k-linux-gnu-gcc)
set(CMAKE_C_FLAGS_INIT "-mcpu=cpu32 -ffreestanding")
# No C library, start files or libgcc (Debian's m68k libgcc is the 68020's).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -nostartfiles -static")
# The compiler checks link no program: there is no C library to link.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
