# Counts the POSIX calls' instructions against the k_ calls (the posix suite: apps/posixcheck/app.mk).
