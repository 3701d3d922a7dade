# Counts the POSIX calls' instructions against the k_ calls (the posix suite: apps/posixcheck/app.mk).
posixmeasure_NEEDS := console tick libc posix
