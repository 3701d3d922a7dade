/*
 * bsched-plan: plans a priority set with bsched.c and prints the paper's
 * Tables 1 and 2 for it (or one JSON object with --json).
 *
 *   bsched-plan [--json] PV [PV ...]
 *
 * Exit status 0 on success, 2 on bad input (one line on stderr, nothing on stdout).
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bsched.h"

/* The major cycle has 2^maxpv minor cycles; listing it is capped here. */
#define PLAN_MAX_LISTED_PV 20

static struct bsched plan;
static uint8_t pvs[BSCHED_MAX_PROCS];

/* Bad input: one line on stderr naming the argument, exit status 2. */
static int usage_error(const char *what, const char *arg)
{
    fprintf(stderr, "bsched-plan: %s '%s' (usage: bsched-plan [--json] PV [PV ...], "
            "PV an integer 0..%d, at most %d processes)\n",
            what, arg, PLAN_MAX_LISTED_PV, BSCHED_MAX_PROCS);
    return 2;
}

/* Name of process i as in the paper: pK.J = member J (from 1) of class K. */
static void process_name(char *out, size_t size, uint16_t i)
{
    unsigned member = 1;
    uint16_t j;
    for (j = 0; j < i; j++) {
        if (plan.pv[j] == plan.pv[i]) {
            member++;
        }
    }
    snprintf(out, size, "p%u.%u", (unsigned)plan.pv[i], member);
}

/* U = sum 2^-pv, as a double for printing (exact for these magnitudes). */
static double utilisation(void)
{
    double u = 0.0;
    uint16_t i;
    for (i = 0; i < plan.count; i++) {
        u += 1.0 / (double)((uint32_t)1u << plan.pv[i]);
    }
    return u;
}

static void print_tables(void)
{
    uint32_t cycles = (uint32_t)1u << plan.maxpv;
    uint32_t t;
    uint16_t i;
    char name[32];

    printf("Table 1: processes (input order)\n");
    printf("%-10s %6s %12s %12s\n", "name", "pv", "2^pv", "wait");
    for (i = 0; i < plan.count; i++) {
        process_name(name, sizeof name, i);
        printf("%-10s %6u %12lu %12lu\n", name, (unsigned)plan.pv[i],
               (unsigned long)((uint32_t)1u << plan.pv[i]), (unsigned long)plan.offset[i]);
    }
    printf("\nTable 2: major cycle of %lu minor cycles\n", (unsigned long)cycles);
    printf("%-8s %s\n", "cycle", "processes");
    for (t = 0; t < cycles; t++) {
        int32_t n = bsched_step(&plan);
        int32_t k;
        printf("%-8lu ", (unsigned long)t);
        for (k = 0; k < n; k++) {
            process_name(name, sizeof name, plan.ran[k]);
            printf("%s%s", k ? ", " : "", name);
        }
        printf("\n");
    }
    printf("\nperfect = %u\n", (unsigned)plan.perfect);
    printf("utilisation U = %.10g processes per minor cycle (loads %u..%u)\n", utilisation(),
           (unsigned)(utilisation() >= 1.0 ? (unsigned)utilisation() : 0u), (unsigned)plan.perfect);
}

static void print_json(void)
{
    uint32_t cycles = (uint32_t)1u << plan.maxpv;
    uint32_t t;
    uint16_t i;

    printf("{\"count\": %u, \"maxpv\": %u, \"pv\": [", (unsigned)plan.count, (unsigned)plan.maxpv);
    for (i = 0; i < plan.count; i++) {
        printf("%s%u", i ? ", " : "", (unsigned)plan.pv[i]);
    }
    printf("], \"wait\": [");
    for (i = 0; i < plan.count; i++) {
        printf("%s%lu", i ? ", " : "", (unsigned long)plan.offset[i]);
    }
    printf("], \"order\": [");
    for (i = 0; i < plan.count; i++) {
        printf("%s%u", i ? ", " : "", (unsigned)plan.order[i]);
    }
    printf("], \"perfect\": %u, \"utilisation\": %.10g, \"major_cycle\": [", (unsigned)plan.perfect,
           utilisation());
    for (t = 0; t < cycles; t++) {
        int32_t n = bsched_step(&plan);
        int32_t k;
        printf("%s[", t ? ", " : "");
        for (k = 0; k < n; k++) {
            printf("%s%u", k ? ", " : "", (unsigned)plan.ran[k]);
        }
        printf("]");
    }
    printf("]}\n");
}

int main(int argc, char **argv)
{
    int json = 0;
    size_t count = 0;
    int a;
    int32_t rc;
    unsigned long maxpv = 0;
    int options_done = 0;

    for (a = 1; a < argc; a++) {
        const char *arg = argv[a];
        char *end;
        long value;
        if (!options_done && strcmp(arg, "--json") == 0) {
            json = 1;
            continue;
        }
        if (!options_done && strcmp(arg, "--") == 0) {
            options_done = 1;
            continue;
        }
        if (!options_done && arg[0] == '-' && arg[1] != '\0' &&
            !(arg[1] >= '0' && arg[1] <= '9')) {
            return usage_error("unknown option", arg);
        }
        errno = 0;
        value = strtol(arg, &end, 10);
        if (arg[0] == '\0' || *end != '\0' || errno == ERANGE || arg[0] == '+' || arg[0] == ' ') {
            return usage_error("priority value is not an integer:", arg);
        }
        if (value < 0) {
            return usage_error("priority value is negative:", arg);
        }
        if (value > BSCHED_MAX_PV) {
            return usage_error("priority value out of range:", arg);
        }
        if (value > PLAN_MAX_LISTED_PV) {
            /* The library takes up to BSCHED_MAX_PV, but 2^maxpv lines are too many to list. */
            return usage_error("priority value too large to list its major cycle:", arg);
        }
        if (count >= BSCHED_MAX_PROCS) {
            return usage_error("too many processes at argument", arg);
        }
        pvs[count++] = (uint8_t)value;
        if ((unsigned long)value > maxpv) {
            maxpv = (unsigned long)value;
        }
    }
    if (count == 0) {
        return usage_error("no priority values given", "");
    }
    rc = bsched_init(&plan, pvs, count);
    if (rc != BSCHED_OK) {
        fprintf(stderr, "bsched-plan: bsched_init failed with code %ld\n", (long)rc);
        return 2;
    }
    if (json) {
        print_json();
    } else {
        print_tables();
    }
    return fflush(stdout) == 0 ? 0 : 1;
}
