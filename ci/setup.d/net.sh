# The radio network (net/): libtirpc's xdrmem is the independent XDR the host
# tests compare with; clang-14 builds the libFuzzer targets (make fuzz).
apt_install libtirpc-dev clang-14 libclang-rt-14-dev
