/* The paper's Tables 1 and 2, shared by the library's and the reference
 * engine's tests: the priority values of Table 1 (p1.1..p4.3 as input indices
 * 0..8) and the processes Table 2 runs in each of the 16 minor cycles of the
 * major cycle, in execution order, -1 ending a row. */
#ifndef BSCHED_TESTS_TABLE2_H
#define BSCHED_TESTS_TABLE2_H

static const uint8_t table1_pv[] = {1, 1, 1, 2, 2, 3, 4, 4, 4};

static const int table2[16][4] = {
    {0, 2, 5, -1}, {1, 3, -1}, {0, 2, 8, -1}, {1, 4, -1},
    {0, 2, 6, -1}, {1, 3, -1}, {0, 2, -1},    {1, 4, -1},
    {0, 2, 5, -1}, {1, 3, -1}, {0, 2, -1},    {1, 4, -1},
    {0, 2, 7, -1}, {1, 3, -1}, {0, 2, -1},    {1, 4, -1},
};

#endif /* BSCHED_TESTS_TABLE2_H */
