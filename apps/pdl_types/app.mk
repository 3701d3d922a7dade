# Every quantity type (int8, int16, int32, uint8, uint16, float) for 1000
# cycles, printed: the board's output must equal the host's, line for line
# (pdl/tests/target/test_pdl_types.py). make run APP=pdl_types
