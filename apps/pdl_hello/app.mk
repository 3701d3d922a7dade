# A PDL program: apps/pdl_hello/main.c (make run APP=pdl_hello).
