# 32-bit builds of the XDR decoder's tests (net/net.mk: check-net-xdr-widths and
# the 32-bit fuzzer): gcc-12-multilib for gcc -m32 (i386 crt files, libc, libgcc,
# libasan, libubsan), the 32-bit libstdc++ that clang-14's i386 libFuzzer runtime
# (in libclang-rt-14-dev, component net) links against, and the m68k C library
# and qemu-user to run an m68k Linux build on the host.
# Not the gcc-multilib package: it conflicts with the cross compilers
# (gcc-m68k-linux-gnu, component m68k), and apt would remove them for it.
apt_install gcc-12-multilib lib32stdc++-12-dev libc6-dev-m68k-cross qemu-user
