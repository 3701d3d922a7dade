# An ordinary C program: apps/hello/main.c (make run APP=hello).
