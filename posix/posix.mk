# The POSIX layer (posix/, README.md): one of the libraries every image may
# link (mk/image.mk). It stands on newlib (its headers, errno, the malloc
# lock), so the pipeline builds it only for a board with the posix capability.
# Its suite is declared with its test image (apps/posixcheck/app.mk).
NEEDS_posix += $(wildcard posix/*.c)
