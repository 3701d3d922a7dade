/*
 * bsched-plan: plans a priority set with bsched.c and prints the paper's
 * Tables 1 and 2 for it (or one JSON object with --json), and with --svg FILE
 * also draws the major cycle as an SVG chart into FILE.
 *
 *   bsched-plan [--json] [--svg FILE] PV [PV ...]
 *   bsched-plan --certify FILE [--method cbmc|check|auto] [--source DIR] [--time-limit S] PV [PV ...]
 *   bsched-plan --recheck FILE [--source DIR] [--time-limit S]
 *   bsched-plan --help
 *
 * --certify checks the set's whole major cycle on bsched.c and writes a
 * certificate to FILE: by CBMC (certify_cbmc below) for small sets, or by
 * running bsched.c and checking its trace with an independent checker
 * (certify_check, tools/bsched-check.c) for sets out of CBMC's reach;
 * --recheck re-runs the check of a certificate by its method and compares
 * (exit 0 only when it is reproduced and certified).
 *
 * Exit status 0 on success, 2 on bad input (one line on stderr, nothing on stdout).
 * FILE is replaced only if it is a regular file (or does not exist yet); the
 * chart is written to a new temporary file beside it and renamed over it.
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fchmod, fsync, lstat, umask, scandir */
#define _DEFAULT_SOURCE         /* wait4: the library run's own peak memory */
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bsched.h"
#include "bsched-check.h"

/* The major cycle has 2^maxpv minor cycles; listing it is capped here. */
#define PLAN_MAX_LISTED_PV 20
/* The largest priority value --certify takes (the checker's limit: a major cycle of
 * 65536 minor cycles); CBMC could not do larger ones in a day. */
#define CERT_MAX_PV 16u
/* --method auto: CBMC up to this many process-cycles (N x 2^maxpv), run+check above. */
#define CERT_CBMC_MAX_WORK 1024ull
/* The chart draws at most this many minor cycles and process rows (the rest
 * is left out, and the chart says so). */
#define SVG_MAX_CYCLES 1024u
#define SVG_MAX_ROWS   512u

static struct bsched plan;
static uint8_t pvs[BSCHED_MAX_PROCS];
/* member_of[i]: J of process i's name pK.J, set once by number_members(). */
static uint16_t member_of[BSCHED_MAX_PROCS];

/* Bad input: one line on stderr naming the argument, exit status 2. */
static int usage_error(const char *what, const char *arg)
{
    fprintf(stderr, "bsched-plan: %s '%s' (usage: bsched-plan [--json] [--svg FILE] PV [PV ...], "
            "PV an integer 0..%d, at most %d processes)\n",
            what, arg, PLAN_MAX_LISTED_PV, BSCHED_MAX_PROCS);
    return 2;
}

static void print_help(void)
{
    printf("usage: bsched-plan [--json] [--svg FILE] PV [PV ...]\n"
           "Plans the processes of priority values PV (integers 0..%d, at most %d processes)\n"
           "with bsched.c and prints the paper's Table 1 (processes, their waits) and Table 2\n"
           "(the major cycle).\n"
           "  --json      one JSON object instead of the tables\n"
           "  --svg FILE  also draw the major cycle as an SVG chart into FILE (replaces FILE\n"
           "              only if it is a regular file or does not exist)\n"
           "  --certify FILE  check the whole major cycle of bsched.c for the set (PV 0..16,\n"
           "              every cycle: period exactly 2^pv with a constant phase, the balance\n"
           "              theorem's load, so floor(U)..ceil(U) and at most perfect, the same\n"
           "              schedule as Fig. 7) and write a certificate to FILE (the log: FILE.log)\n"
           "  --method M  how --certify checks: cbmc (CBMC model-checks bsched.c beside Fig. 7's\n"
           "              reference engine), check (run+check: bsched.c, compiled with $CC or cc,\n"
           "              runs the major cycle and an independent checker reads its trace;\n"
           "              O(N + 2^maxpv) memory) or auto (the default: cbmc while N x 2^maxpv <= %llu\n"
           "              process-cycles, about 17 s of CBMC; check above)\n"
           "  --recheck FILE  re-run the check of certificate FILE by its method and compare\n"
           "  --source DIR    the bsched folder to certify (bsched.c, bsched.h, spec/, proofs/ref/)\n"
           "  --time-limit S  stop the check after S seconds (default 3600): not certified\n"
           "  --check-trace FILE  run the checker of --method check alone on a trace file (its\n"
           "              format: tools/bsched-check.h) for the set PV...; exit 0 if it holds\n"
           "  --          the arguments after it are priority values\n"
           "  --help      this text\n"
           "Exit status: 0 done (certified), 1 not certified, 2 bad input or FILE not written\n"
           "(one line on stderr).\n",
           PLAN_MAX_LISTED_PV, BSCHED_MAX_PROCS, CERT_CBMC_MAX_WORK);
}

/* Numbers the members of each class in input order, in one pass (a running
 * count per priority value), so that naming a process costs O(1): Table 2
 * names every process of every minor cycle, and counting a process's earlier
 * class members at each name made 16,000 processes take a minute. */
static void number_members(void)
{
    uint16_t seen[BSCHED_MAX_PV + 1] = {0};
    uint16_t i;
    for (i = 0; i < plan.count; i++) {
        member_of[i] = ++seen[plan.pv[i]];
    }
}

/* Name of process i as in the paper: pK.J = member J (from 1) of class K. */
static void process_name(char *out, size_t size, uint16_t i)
{
    snprintf(out, size, "p%u.%u", (unsigned)plan.pv[i], (unsigned)member_of[i]);
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

/* The major cycle as an SVG chart: minor cycles across, processes down (in
 * execution order, named pK.J), a mark where a process runs, the load of each
 * cycle as a bar under it with the `perfect` level drawn across. Every mark is
 * <rect class="run" data-cycle="t" data-process="i">, every bar
 * <rect class="load" data-cycle="t" data-load="n">, so tests can read them. */
static int write_svg(FILE *out)
{
    uint32_t cycles = (uint32_t)1u << plan.maxpv;
    uint32_t shown = cycles < SVG_MAX_CYCLES ? cycles : SVG_MAX_CYCLES;
    uint32_t rows = plan.count < SVG_MAX_ROWS ? plan.count : SVG_MAX_ROWS;
    uint32_t cw = 1600u / shown, rh = 1200u / rows;
    uint32_t left = 70u, top = 50u, grid_w, grid_h, load_h = 120u, load_top, width, height;
    uint32_t t, r;
    char name[32];
    static uint16_t row_of[BSCHED_MAX_PROCS];

    cw = cw < 2u ? 2u : (cw > 24u ? 24u : cw);
    rh = rh < 2u ? 2u : (rh > 18u ? 18u : rh);
    grid_w = shown * cw;
    grid_h = rows * rh;
    load_top = top + grid_h + 30u;
    width = left + grid_w + 150u;
    height = load_top + load_h + 70u;
    for (r = 0; r < plan.count; r++) {
        row_of[plan.order[r]] = (uint16_t)r;
    }
    fprintf(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%lu\" height=\"%lu\" "
            "viewBox=\"0 0 %lu %lu\" font-family=\"sans-serif\" font-size=\"11\">\n",
            (unsigned long)width, (unsigned long)height, (unsigned long)width, (unsigned long)height);
    fprintf(out, "<style>.run{fill:#1f5fa8}.load{fill:#7a9cc6}.load.perfect{fill:#d0702a}"
            ".grid{stroke:#ddd;stroke-width:1}.perfect-line{stroke:#d0702a;stroke-dasharray:4 3}</style>\n");
    fprintf(out, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(out, "<text x=\"%lu\" y=\"20\" font-size=\"14\">major cycle of %lu minor cycles, "
            "%u processes, perfect = %u, U = %.6g</text>\n", (unsigned long)left,
            (unsigned long)cycles, (unsigned)plan.count, (unsigned)plan.perfect, utilisation());
    if (shown < cycles || rows < plan.count) {
        fprintf(out, "<text class=\"left-out\" x=\"%lu\" y=\"38\" fill=\"#b00\">left out:", (unsigned long)left);
        if (shown < cycles) {
            fprintf(out, " minor cycles %lu..%lu (%lu of %lu shown)", (unsigned long)shown,
                    (unsigned long)(cycles - 1u), (unsigned long)shown, (unsigned long)cycles);
        }
        if (rows < plan.count) {
            fprintf(out, "%s rows of %u processes after the first %lu in execution order (counted in the loads)",
                    shown < cycles ? ";" : "", (unsigned)(plan.count - rows), (unsigned long)rows);
        }
        fprintf(out, "</text>\n");
    }
    /* Row labels and guide lines. */
    for (r = 0; r < rows; r++) {
        if (rh >= 9u) {
            process_name(name, sizeof name, plan.order[r]);
            fprintf(out, "<text x=\"%lu\" y=\"%lu\" text-anchor=\"end\">%s</text>\n",
                    (unsigned long)(left - 6u), (unsigned long)(top + r * rh + rh - 3u), name);
        }
    }
    for (t = 0; t <= shown; t += (shown / 16u ? shown / 16u : 1u)) {
        fprintf(out, "<line class=\"grid\" x1=\"%lu\" y1=\"%lu\" x2=\"%lu\" y2=\"%lu\"/>",
                (unsigned long)(left + t * cw), (unsigned long)top, (unsigned long)(left + t * cw),
                (unsigned long)(load_top + load_h));
        if (t < shown) {
            fprintf(out, "<text x=\"%lu\" y=\"%lu\">%lu</text>", (unsigned long)(left + t * cw),
                    (unsigned long)(top - 4u), (unsigned long)t);
        }
        fprintf(out, "\n");
    }
    /* Marks and loads, cycle by cycle. */
    for (t = 0; t < shown; t++) {
        int32_t n = bsched_step(&plan);
        int32_t k;
        uint32_t bar;
        for (k = 0; k < n; k++) {
            uint16_t i = plan.ran[k];
            if (row_of[i] < rows) {
                fprintf(out, "<rect class=\"run\" data-cycle=\"%lu\" data-process=\"%u\" x=\"%lu\" "
                        "y=\"%lu\" width=\"%lu\" height=\"%lu\"/>\n", (unsigned long)t, (unsigned)i,
                        (unsigned long)(left + t * cw), (unsigned long)(top + row_of[i] * rh),
                        (unsigned long)(cw > 2u ? cw - 1u : cw), (unsigned long)(rh > 2u ? rh - 1u : rh));
            }
        }
        bar = (uint32_t)((uint64_t)load_h * (uint32_t)n / plan.perfect);
        fprintf(out, "<rect class=\"load%s\" data-cycle=\"%lu\" data-load=\"%ld\" x=\"%lu\" y=\"%lu\" "
                "width=\"%lu\" height=\"%lu\"/>\n", (uint32_t)n == plan.perfect ? " perfect" : "",
                (unsigned long)t, (long)n, (unsigned long)(left + t * cw),
                (unsigned long)(load_top + load_h - bar), (unsigned long)(cw > 2u ? cw - 1u : cw),
                (unsigned long)bar);
        if (cw >= 14u) {
            fprintf(out, "<text x=\"%lu\" y=\"%lu\" font-size=\"9\">%ld</text>\n",
                    (unsigned long)(left + t * cw + 2u), (unsigned long)(load_top + load_h + 12u), (long)n);
        }
    }
    fprintf(out, "<line class=\"perfect-line\" x1=\"%lu\" y1=\"%lu\" x2=\"%lu\" y2=\"%lu\"/>\n"
            "<text class=\"perfect-label\" x=\"%lu\" y=\"%lu\" fill=\"#d0702a\">perfect = %u</text>\n",
            (unsigned long)left, (unsigned long)load_top, (unsigned long)(left + grid_w),
            (unsigned long)load_top, (unsigned long)(left + grid_w + 6u), (unsigned long)(load_top + 4u),
            (unsigned)plan.perfect);
    fprintf(out, "<text x=\"%lu\" y=\"%lu\" text-anchor=\"end\">load</text>\n",
            (unsigned long)(left - 6u), (unsigned long)(load_top + load_h));
    fprintf(out, "<text x=\"%lu\" y=\"%lu\">minor cycle &#8594;  (bars: processes run per cycle; "
            "orange = perfect)</text>\n", (unsigned long)left, (unsigned long)(load_top + load_h + 40u));
    fprintf(out, "</svg>\n");
    return ferror(out) ? -1 : 0;
}

/* One line on stderr for a chart that was not written; the target is untouched. */
static int svg_error(const char *path, const char *why)
{
    fprintf(stderr, "bsched-plan: cannot write '%s': %s\n", path, why);
    return 2;
}

/*
 * Writes the chart to path. Only a regular file is ever replaced: anything
 * else there (a symbolic link, a device such as /dev/null, a FIFO, a folder)
 * is refused and left as it is. The chart goes to a temporary file that
 * mkstemp creates exclusively (O_EXCL: it follows no link planted under its
 * name) in path's folder, so the final rename stays on one file system and
 * replaces path whole or not at all; a failed run leaves no partial chart.
 */
static int write_svg_file(const char *path)
{
    static char tmp[PATH_MAX + 16];
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash != NULL ? (size_t)(slash - path) + 1u : 0u;
    struct stat st;
    FILE *out;
    int fd, failed, saved;
    mode_t mask;

    if (path[strlen(path) - 1u] == '/') {
        return svg_error(path, "names a folder, not a file");
    }
    if (lstat(path, &st) == 0) {
        if (!S_ISREG(st.st_mode)) {
            return svg_error(path, S_ISLNK(st.st_mode) ? "it is a symbolic link; refusing to replace it"
                                                       : "not a regular file; refusing to replace it");
        }
    } else if (errno != ENOENT) {
        return svg_error(path, strerror(errno));
    }
    if (dir_len + sizeof ".bsched-plan-XXXXXX" > sizeof tmp) {
        return svg_error(path, "file name too long");
    }
    memcpy(tmp, path, dir_len);
    memcpy(tmp + dir_len, ".bsched-plan-XXXXXX", sizeof ".bsched-plan-XXXXXX");
    fd = mkstemp(tmp);
    if (fd < 0) {
        return svg_error(path, strerror(errno));
    }
    /* mkstemp makes the file 0600; give the chart the mode a new file gets. */
    mask = umask(0);
    (void)umask(mask);
    (void)fchmod(fd, (mode_t)(0666 & ~mask));
    out = fdopen(fd, "w");
    if (out == NULL) {
        saved = errno;
        close(fd);
        unlink(tmp);
        return svg_error(path, strerror(saved));
    }
    failed = write_svg(out);
    failed |= fflush(out) != 0;
    saved = errno;
    failed |= fclose(out) != 0;
    if (failed) {
        unlink(tmp);
        return svg_error(path, strerror(saved != 0 ? saved : EIO));
    }
    /* Looked at again just before the rename: something may have appeared there meanwhile. */
    if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        unlink(tmp);
        return svg_error(path, "not a regular file any more; refusing to replace it");
    }
    if (rename(tmp, path) != 0) {
        saved = errno;
        unlink(tmp);
        return svg_error(path, strerror(saved));
    }
    return 0;
}

/* ------------------------------------------------------------------------
 * --certify and --recheck: a CBMC certificate for one priority set.
 *
 * bsched-plan writes a harness (CERTIFY_HARNESS below, with the set as a constant
 * array) into a fresh temporary folder and runs CBMC on it with bsched.c and Fig. 7's
 * reference engine (proofs/ref/bsched_fig7.c), all of CBMC's property classes on, every
 * loop unwound to its end (--unwinding-assertions: a bound that is too small fails).
 * The set is constant, so CBMC runs the real code symbolically along the one path
 * it takes, through every minor cycle of the major cycle, and checks every assertion
 * and every overflow, bounds and shift on that path: exhaustive for this set. Its
 * cost grows as 2^maxpv x N (Fig. 7's engine counts every wait down each cycle).
 */
#ifndef BSCHED_PLAN_SOURCE
#define BSCHED_PLAN_SOURCE "bsched"
#endif
#define CERT_FORMAT "bsched-plan certificate 2"
/* Written before --method: no method line, no digest of bsched.h and spec/. */
#define CERT_FORMAT_1 "bsched-plan certificate 1"
#define CERT_DEFAULT_LIMIT 3600L
/* A certificate's set line holds up to 65535 values of up to 2 digits and a space. */
#define CERT_TEXT_MAX 262144u

enum cert_method { METHOD_AUTO, METHOD_CBMC, METHOD_CHECK };

static const char CERTIFY_HARNESS[] =
    "void harness(void)\n"
    "{\n"
    "    static struct bsched s, plan, before;\n"
    "    static struct bsched_fig7 r;\n"
    "    static uint32_t runs[CERT_N], first[CERT_N], last[CERT_N];\n"
    "    uint64_t area = 0u;\n"
    "    uint32_t cycles, lo, hi, t, i;\n"
    "    int32_t n, m, k;\n"
    "    __CPROVER_assert(bsched_init(&s, cert_pv, CERT_N) == BSCHED_OK, \"init: the set is accepted\");\n"
    "    plan = s;\n"
    "    before = s;\n"
    "    __CPROVER_assert(bsched_fig7_start(&r, &plan) == BSCHED_OK, \"fig7: the reference engine starts on the plan\");\n"
    "    cycles = (uint32_t)1u << s.maxpv;\n"
    "    /* U * 2^maxpv, exactly: floor(U) and ceil(U) from it */\n"
    "    for (i = 0u; i < CERT_N; i++) { area += (uint64_t)(cycles >> cert_pv[i]); }\n"
    "    lo = (uint32_t)(area >> s.maxpv);\n"
    "    hi = (uint32_t)((area + cycles - 1u) >> s.maxpv);\n"
    "    for (t = 0u; t < cycles; t++) {\n"
    "        n = bsched_step(&s);\n"
    "        m = bsched_fig7_step(&r, &plan);\n"
    "        __CPROVER_assert(n >= 0 && n == m && s.ran_count == r.ran_count,\n"
    "                         \"fig7: as many processes as Fig. 7's reference engine in every cycle\");\n"
    "        for (k = 0; k < n; k++) {\n"
    "            uint16_t p = s.ran[k];\n"
    "            __CPROVER_assert(p == r.ran[k], \"fig7: the same processes in the same order as Fig. 7 in every cycle\");\n"
    "            __CPROVER_assert(p < CERT_N, \"period: a process index\");\n"
    "            if (runs[p] == 0u) {\n"
    "                __CPROVER_assert(t < ((uint32_t)1u << cert_pv[p]), \"period: the first run within 2^pv cycles\");\n"
    "                first[p] = t;\n"
    "            } else {\n"
    "                __CPROVER_assert(t - last[p] == ((uint32_t)1u << cert_pv[p]), \"period: runs exactly 2^pv cycles apart\");\n"
    "            }\n"
    "            last[p] = t;\n"
    "            runs[p]++;\n"
    "        }\n"
    "        __CPROVER_assert((uint32_t)n >= lo, \"load: at least floor(U) processes in every cycle\");\n"
    "        __CPROVER_assert((uint32_t)n <= hi, \"load: at most ceil(U) processes in every cycle\");\n"
    "        __CPROVER_assert((uint32_t)n <= s.perfect, \"load: at most perfect processes in every cycle\");\n"
    "        __CPROVER_assert(area < cycles || n > 0, \"idle: no idle cycle while U >= 1\");\n"
    "    }\n"
    "    for (i = 0u; i < CERT_N; i++) {\n"
    "        __CPROVER_assert(runs[i] == cycles >> cert_pv[i], \"period: 2^(maxpv - pv) runs in the major cycle\");\n"
    "        __CPROVER_assert(first[i] + cycles - last[i] == ((uint32_t)1u << cert_pv[i]),\n"
    "                         \"period: 2^pv cycles from the last run to the first of the next major cycle\");\n"
    "    }\n"
    "    __CPROVER_assert(s.cycle == before.cycle && s.reversed == before.reversed && r.cycle == 0,\n"
    "                     \"repeat: the major cycle ends where it began\");\n"
    "}\n";

/* What one check found; the certificate's lines. */
struct certificate {
    enum cert_method method;
    char set[CERT_TEXT_MAX];
    /* the sources it was made from: the library (both methods) */
    char bsched_sha[80], bsched_h_sha[80], spec_sha[80];
    /* cbmc: Fig. 7's reference engine, the harness, the tool */
    char fig7_sha[80], harness_sha[80];
    char cbmc[PATH_MAX + 32];
    /* run+check: the trace driver, the checker, the compiler and its flags */
    char driver_sha[80], checker_sha[80], compiler[PATH_MAX + 32], compile[PATH_MAX + 64];
    unsigned long count, maxpv, properties, failed;
    /* run+check: what the checker saw */
    unsigned long cycles;
    unsigned long long executions;
    char loads[128], failed_checks[256], first_failure[256];
    char verdict[320];
    double seconds;
    long checker_rss_kib, driver_rss_kib;
};

static int cert_error(const char *what, const char *arg)
{
    fprintf(stderr, "bsched-plan: %s '%s'\n", what, arg);
    return 2;
}

/* Runs argv with stdout (and stderr) into the file out, or captured into buf when
 * out is NULL; waits at most limit seconds (0: no limit), then kills the process
 * group. Returns the exit status, -1 if it could not run, -2 on the time limit. */
static int run_command(char *const argv[], const char *out, char *buf, size_t size, long limit)
{
    int pipefd[2] = {-1, -1};
    pid_t pid;
    int status = 0;
    time_t start = time(NULL);
    size_t used = 0;

    if (out == NULL && pipe(pipefd) != 0) {
        return -1;
    }
    pid = fork();
    if (pid < 0) {
        return -1;
    }
    if (pid == 0) {
        int fd = out != NULL ? open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644) : pipefd[1];
        (void)setpgid(0, 0);
        if (fd < 0) {
            _exit(127);
        }
        (void)dup2(fd, 1);
        (void)dup2(fd, 2);
        if (out == NULL) {
            close(pipefd[0]);
        }
        execvp(argv[0], argv);
        _exit(127);
    }
    (void)setpgid(pid, pid);
    if (out == NULL) {
        ssize_t got;
        close(pipefd[1]);
        while ((got = read(pipefd[0], buf + used, size - 1u - used)) > 0) {
            used += (size_t)got;
            if (used + 1u >= size) {
                break;
            }
        }
        buf[used] = '\0';
        close(pipefd[0]);
    }
    for (;;) {
        pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) {
            break;
        }
        if (w < 0) {
            return -1;
        }
        if (limit > 0 && time(NULL) - start >= limit) {
            (void)kill(-pid, SIGKILL);
            (void)waitpid(pid, &status, 0);
            return -2;
        }
        {
            struct timespec pause = {0, 100000000L};
            (void)nanosleep(&pause, NULL);
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The first line of `TOOL --version` into out, or "not found (TOOL)": the tool
 * named in a certificate. */
static void tool_version(char *tool, char *out, size_t size)
{
    char version[256];
    char *argv[] = {tool, "--version", NULL};
    if (run_command(argv, NULL, version, sizeof version, 60) == 0) {
        version[strcspn(version, "\r\n")] = '\0';
        snprintf(out, size, "%s", version);
    } else {
        snprintf(out, size, "not found (%s)", tool);
    }
}

/* The sha256 of a file (sha256sum), or "" when it cannot be read. */
static void file_sha256(const char *path, char *out, size_t size)
{
    char buf[512];
    char *argv[] = {"sha256sum", "--", (char *)path, NULL};
    out[0] = '\0';
    if (run_command(argv, NULL, buf, sizeof buf, 60) == 0 && strlen(buf) >= 64u && size > 64u) {
        memcpy(out, buf, 64);
        out[64] = '\0';
    }
}

/* The CBMC to run: $CBMC, else ci/setup cbmc's under $BSCHED_TOOLS (or the XDG
 * cache), else cbmc on PATH. */
static void find_cbmc(char *out, size_t size)
{
    const char *env = getenv("CBMC");
    const char *tools = getenv("BSCHED_TOOLS");
    const char *xdg = getenv("XDG_CACHE_HOME");
    const char *home = getenv("HOME");
    if (env != NULL && env[0] != '\0') {
        snprintf(out, size, "%s", env);
        return;
    }
    if (tools != NULL && tools[0] != '\0') {
        snprintf(out, size, "%s/cbmc/bin/cbmc", tools);
    } else if (xdg != NULL && xdg[0] != '\0') {
        snprintf(out, size, "%s/bsched/cbmc/bin/cbmc", xdg);
    } else {
        snprintf(out, size, "%s/.cache/bsched/cbmc/bin/cbmc", home != NULL ? home : "");
    }
    if (access(out, X_OK) != 0) {
        snprintf(out, size, "cbmc");
    }
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

/* Counts CBMC's result lines ("[id] line ... description: SUCCESS" / ": FAILURE"). */
static void count_results(const char *log, unsigned long *success, unsigned long *failure, int *verified)
{
    FILE *f = fopen(log, "r");
    static char line[8192];
    *success = *failure = 0;
    *verified = 0;
    if (f == NULL) {
        return;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        size_t len = strlen(line);
        while (len > 0u && (line[len - 1u] == '\n' || line[len - 1u] == '\r')) {
            line[--len] = '\0';
        }
        if (line[0] == '[' && len > 9u && strcmp(line + len - 9u, ": SUCCESS") == 0) {
            (*success)++;
        } else if (line[0] == '[' && len > 9u && strcmp(line + len - 9u, ": FAILURE") == 0) {
            (*failure)++;
        } else if (strcmp(line, "VERIFICATION SUCCESSFUL") == 0) {
            *verified = 1;
        }
    }
    fclose(f);
}

/* sha256 of a string, through a temporary file and sha256sum. */
static void text_sha256(const char *text, char *out, size_t size)
{
    char path[] = "/tmp/bsched-certificate.XXXXXX";
    int fd = mkstemp(path);
    out[0] = '\0';
    if (fd < 0) {
        return;
    }
    if (write(fd, text, strlen(text)) == (ssize_t)strlen(text)) {
        close(fd);
        file_sha256(path, out, size);
    } else {
        close(fd);
    }
    unlink(path);
}

/* The sha256 of the library's sources in `source`: bsched.c, bsched.h, and spec/
 * as one digest (of the "digest  name" lines of its headers in name order):
 * bsched.c includes the spec headers, so a define in one of them changes the code. */
static void library_digests(const char *source, struct certificate *c)
{
    char path[PATH_MAX + 512], spec[PATH_MAX], one[80];
    static char lines[64 * 160];
    struct dirent **names = NULL;
    size_t used = 0;
    int n, k;

    snprintf(path, sizeof path, "%s/bsched.c", source);
    file_sha256(path, c->bsched_sha, sizeof c->bsched_sha);
    snprintf(path, sizeof path, "%s/bsched.h", source);
    file_sha256(path, c->bsched_h_sha, sizeof c->bsched_h_sha);
    snprintf(spec, sizeof spec, "%s/spec", source);
    c->spec_sha[0] = '\0';
    n = scandir(spec, &names, NULL, alphasort);
    if (n < 0) {
        return;
    }
    lines[0] = '\0';
    for (k = 0; k < n; k++) {
        size_t len = strlen(names[k]->d_name);
        if (len > 2u && strcmp(names[k]->d_name + len - 2u, ".h") == 0 && used + len + 80u < sizeof lines) {
            snprintf(path, sizeof path, "%s/%s", spec, names[k]->d_name);
            file_sha256(path, one, sizeof one);
            used += (size_t)snprintf(lines + used, sizeof lines - used, "%s  %s\n", one, names[k]->d_name);
        }
        free(names[k]);
    }
    free(names);
    if (used > 0u) {
        text_sha256(lines, c->spec_sha, sizeof c->spec_sha);
    }
}

/* The cbmc method: fills c's cbmc lines (the tool, the harness, the property
 * counts, the verdict, the time); CBMC's log goes to log_path. Returns 0
 * certified, 1 not certified. */
static int certify_cbmc(const char *source, const uint8_t *set, size_t count, unsigned long maxpv,
                        long limit, const char *log_path, struct certificate *c)
{
    char dir[] = "/tmp/bsched-certify.XXXXXX";
    char harness[PATH_MAX], lib[PATH_MAX], ref[PATH_MAX], incl[PATH_MAX + 4], incl_ref[PATH_MAX + 8];
    char cbmc[PATH_MAX], capacity[48], unwind[32];
    size_t i;
    unsigned long success = 0, failure = 0, bound;
    int verified = 0, rc;
    double start;
    FILE *h;

    snprintf(lib, sizeof lib, "%s/bsched.c", source);
    snprintf(ref, sizeof ref, "%s/proofs/ref/bsched_fig7.c", source);
    file_sha256(ref, c->fig7_sha, sizeof c->fig7_sha);
    find_cbmc(cbmc, sizeof cbmc);
    tool_version(cbmc, c->cbmc, sizeof c->cbmc);
    if (c->bsched_sha[0] == '\0' || c->fig7_sha[0] == '\0') {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: no bsched.c or proofs/ref/bsched_fig7.c");
        fprintf(stderr, "bsched-plan: cannot read %s or %s\n", lib, ref);
        return 1;
    }
    if (mkdtemp(dir) == NULL) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: no temporary folder");
        return 1;
    }
    snprintf(harness, sizeof harness, "%s/certify_harness.c", dir);
    h = fopen(harness, "w");
    if (h == NULL) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: harness not written");
        return 1;
    }
    fprintf(h, "/* Written by bsched-plan --certify for the set: %s */\n"
               "#include \"bsched.h\"\n#include \"bsched_fig7.h\"\n#define CERT_N %lu\n"
               "static const uint8_t cert_pv[CERT_N] = {", c->set, (unsigned long)count);
    for (i = 0; i < count; i++) {
        fprintf(h, "%s%u", i ? ", " : "", (unsigned)set[i]);
    }
    fprintf(h, "};\n%s", CERTIFY_HARNESS);
    if (fclose(h) != 0) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: harness not written");
        return 1;
    }
    file_sha256(harness, c->harness_sha, sizeof c->harness_sha);
    /* Every loop runs to its end: the longest is the major cycle (2^maxpv) or a walk
     * over the processes (count) or the classes (32). */
    bound = (1ul << maxpv) > count ? (1ul << maxpv) : (unsigned long)count;
    bound = (bound > 32ul ? bound : 32ul) + 2ul;
    snprintf(capacity, sizeof capacity, "-DBSCHED_MAX_PROCS=%lu", (unsigned long)count);
    snprintf(unwind, sizeof unwind, "%lu", bound);
    snprintf(incl, sizeof incl, "-I%s", source);
    snprintf(incl_ref, sizeof incl_ref, "-I%s/proofs/ref", source);
    {
        char *argv[] = {cbmc, "--function", "harness", capacity, incl, incl_ref, harness, lib, ref,
                        "--bounds-check", "--pointer-check", "--div-by-zero-check",
                        "--signed-overflow-check", "--unsigned-overflow-check", "--conversion-check",
                        "--undefined-shift-check", "--pointer-overflow-check", "--unwinding-assertions",
                        "--unwind", unwind, "--trace", NULL};
        start = now_seconds();
        rc = run_command(argv, log_path, NULL, 0, limit);
        c->seconds = now_seconds() - start;
    }
    unlink(harness);
    rmdir(dir);
    count_results(log_path, &success, &failure, &verified);
    c->properties = success + failure;
    c->failed = failure;
    if (rc == 0 && verified && failure == 0 && success > 0) {
        snprintf(c->verdict, sizeof c->verdict, "CERTIFIED");
        return 0;
    }
    if (rc == -2) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: time limit of %ld s", limit);
    } else if (failure > 0) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: %lu properties fail", failure);
    } else {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: cbmc exited %d", rc);
    }
    return 1;
}

/* ------------------------------------------------------------------------
 * The run+check method: the library runs, an independent checker judges.
 *
 * bsched-plan writes the trace driver below into a fresh temporary folder and
 * compiles it with the bsched.c of --source, unchanged ($CC, else cc; the
 * compiler's version and flags go into the certificate). The driver plans the
 * set with bsched_init and runs the whole major cycle through bsched_run_cycle,
 * writing what the library did (its plan, then each cycle's calls in order) to
 * a pipe; the checker (tools/bsched-check.c: no code shared with bsched.c or
 * Fig. 7's reference engine, none of their functions called) reads it cycle by
 * cycle and checks it against its own Fig. 6 and Fig. 7 and the balance
 * theorem's count. Nothing is stored per cycle: memory is O(N + 2^maxpv), time
 * O(N + 2^maxpv + the runs of the major cycle). The checker's sha256 is the one
 * of the source it was compiled from (BSCHED_CHECK_SHA256, set by the build).
 */
#ifndef BSCHED_CHECK_SHA256
#define BSCHED_CHECK_SHA256 "unknown (bsched-plan built without BSCHED_CHECK_SHA256)"
#endif

static const char TRACE_DRIVER[] =
    "/* Written by bsched-plan --certify (run+check): plans the set in the file argv[1]\n"
    " * (one byte per priority value) with bsched.c, runs its whole major cycle through\n"
    " * bsched_run_cycle and writes the trace to stdout (format: tools/bsched-check.h). */\n"
    "#include <stdio.h>\n"
    "#include \"bsched.h\"\n"
    "static struct bsched s;\n"
    "static uint8_t pv[BSCHED_MAX_PROCS + 1u];\n"
    "static uint16_t called[BSCHED_MAX_PROCS];\n"
    "static uint32_t calls;\n"
    "static char out_buffer[1 << 16];\n"
    "static void record(void *context, uint16_t index)\n"
    "{\n"
    "    (void)context;\n"
    "    if (calls < BSCHED_MAX_PROCS) {\n"
    "        called[calls] = index;\n"
    "    }\n"
    "    calls++; /* more calls than processes: the checker refuses the trace */\n"
    "}\n"
    "static void put32(uint32_t v)\n"
    "{\n"
    "    (void)fwrite(&v, sizeof v, 1u, stdout);\n"
    "}\n"
    "int main(int argc, char **argv)\n"
    "{\n"
    "    FILE *in = argc == 2 ? fopen(argv[1], \"rb\") : NULL;\n"
    "    size_t n = in != NULL ? fread(pv, 1u, sizeof pv, in) : 0u;\n"
    "    int32_t status, ran;\n"
    "    uint32_t t, cycles;\n"
    "    (void)setvbuf(stdout, out_buffer, _IOFBF, sizeof out_buffer);\n"
    "    status = bsched_init(&s, pv, n);\n"
    "    (void)fwrite(\"BSTRACE1\", 1u, 8u, stdout);\n"
    "    (void)fwrite(&status, sizeof status, 1u, stdout);\n"
    "    if (status == BSCHED_OK) {\n"
    "        put32(s.count);\n"
    "        put32(s.maxpv);\n"
    "        put32(s.perfect);\n"
    "        (void)fwrite(s.pv, 1u, s.count, stdout);\n"
    "        (void)fwrite(s.offset, sizeof s.offset[0], s.count, stdout);\n"
    "        cycles = (uint32_t)1u << s.maxpv;\n"
    "        for (t = 0u; t < cycles; t++) {\n"
    "            calls = 0u;\n"
    "            ran = bsched_run_cycle(&s, record, NULL);\n"
    "            (void)fwrite(&ran, sizeof ran, 1u, stdout);\n"
    "            put32(calls);\n"
    "            (void)fwrite(called, sizeof called[0], calls < BSCHED_MAX_PROCS ? calls : BSCHED_MAX_PROCS, stdout);\n"
    "        }\n"
    "        put32(s.cycle);\n"
    "        put32(s.reversed);\n"
    "        (void)fwrite(\"BSTREND1\", 1u, 8u, stdout);\n"
    "    }\n"
    "    return fflush(stdout) != 0 || ferror(stdout) ? 1 : 0;\n"
    "}\n";

/* The time limit of a run+check: SIGALRM kills the library run's process group,
 * which ends the trace early (the checker then calls it malformed). */
static volatile sig_atomic_t trace_timed_out;
static volatile pid_t trace_pid;

static void on_trace_alarm(int sig)
{
    (void)sig;
    trace_timed_out = 1;
    if (trace_pid > 0) {
        (void)kill(-trace_pid, SIGKILL);
    }
}

static void append_log(const char *log_path, const char *line)
{
    FILE *f = fopen(log_path, "a");
    if (f != NULL) {
        fputs(line, f);
        fclose(f);
    }
}

/* This process's peak resident memory in KiB: VmHWM of /proc/self/status, the
 * high-water mark of its own memory since exec. getrusage's ru_maxrss is kept
 * across exec on Linux, so it would report the parent that forked us (a Python
 * test runner: 140 MB) instead; it is the fallback without /proc. */
static long own_peak_rss_kib(void)
{
    char line[256];
    long kib = -1;
    FILE *f = fopen("/proc/self/status", "r");
    if (f != NULL) {
        while (fgets(line, sizeof line, f) != NULL) {
            if (strncmp(line, "VmHWM:", 6) == 0) {
                kib = strtol(line + 6, NULL, 10);
                break;
            }
        }
        fclose(f);
    }
    if (kib < 0) {
        struct rusage self;
        kib = getrusage(RUSAGE_SELF, &self) == 0 ? self.ru_maxrss : 0;
    }
    return kib;
}

/* Writes text to path (a new file); 0 on success. */
static int write_file(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    int failed;
    if (f == NULL) {
        return -1;
    }
    failed = fwrite(data, 1, size, f) != size;
    failed |= fclose(f) != 0;
    return failed ? -1 : 0;
}

/* The run+check method: fills c's run+check lines; the compiler's output and the
 * checker's findings go to log_path. Returns 0 certified, 1 not certified. */
static int certify_check(const char *source, const uint8_t *set, size_t count, long limit,
                         const char *log_path, struct certificate *c)
{
    char dir[] = "/tmp/bsched-check.XXXXXX";
    char driver[PATH_MAX], program[PATH_MAX], set_path[PATH_MAX], lib[PATH_MAX], incl[PATH_MAX + 4];
    char capacity[48], line[512];
    const char *cc_env = getenv("CC");
    char cc[PATH_MAX];
    struct check_result result;
    struct sigaction alarm_action, old_action;
    struct rusage usage;
    int pipefd[2], status = 0, rc, checked, k;
    long remaining;
    size_t used;
    double start = now_seconds();
    pid_t pid;
    FILE *trace;

    snprintf(cc, sizeof cc, "%s", cc_env != NULL && cc_env[0] != '\0' ? cc_env : "cc");
    snprintf(c->checker_sha, sizeof c->checker_sha, "%s", BSCHED_CHECK_SHA256);
    text_sha256(TRACE_DRIVER, c->driver_sha, sizeof c->driver_sha);
    snprintf(capacity, sizeof capacity, "-DBSCHED_MAX_PROCS=%lu", (unsigned long)count);
    snprintf(c->compile, sizeof c->compile, "%s -std=c99 -O2 %s", cc, capacity);
    snprintf(c->first_failure, sizeof c->first_failure, "none");
    tool_version(cc, c->compiler, sizeof c->compiler);
    if (c->bsched_sha[0] == '\0') {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: no bsched.c");
        fprintf(stderr, "bsched-plan: cannot read %s/bsched.c\n", source);
        return 1;
    }
    if (mkdtemp(dir) == NULL) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: no temporary folder");
        return 1;
    }
    snprintf(driver, sizeof driver, "%s/trace_driver.c", dir);
    snprintf(program, sizeof program, "%s/trace_driver", dir);
    snprintf(set_path, sizeof set_path, "%s/set", dir);
    snprintf(lib, sizeof lib, "%s/bsched.c", source);
    snprintf(incl, sizeof incl, "-I%s", source);
    rc = write_file(driver, TRACE_DRIVER, strlen(TRACE_DRIVER)) | write_file(set_path, set, count);
    if (rc == 0) {
        char *argv[] = {cc, "-std=c99", "-O2", capacity, incl, "-o", program, driver, lib, NULL};
        rc = run_command(argv, log_path, NULL, 0, limit);
    }
    if (rc != 0) {
        snprintf(c->verdict, sizeof c->verdict, rc == -2 ? "NOT CERTIFIED: time limit of %ld s"
                 : "NOT CERTIFIED: the library did not compile (see the log)", limit);
        unlink(program);
        unlink(driver);
        unlink(set_path);
        rmdir(dir);
        return 1;
    }
    append_log(log_path, "bsched-plan: compiled; the library runs the major cycle, the checker reads its trace\n");
    memset(&usage, 0, sizeof usage);
    if (pipe(pipefd) != 0) {
        pipefd[0] = pipefd[1] = -1;
    }
    pid = pipefd[0] >= 0 ? fork() : -1;
    if (pid < 0) {
        if (pipefd[0] >= 0) {
            close(pipefd[0]);
            close(pipefd[1]);
        }
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: the library could not be run");
        unlink(program);
        unlink(driver);
        unlink(set_path);
        rmdir(dir);
        return 1;
    }
    if (pid == 0) {
        int log_fd = open(log_path, O_WRONLY | O_APPEND | O_CREAT, 0644);
        char *argv[] = {program, set_path, NULL};
        (void)setpgid(0, 0);
        (void)dup2(pipefd[1], 1);
        if (log_fd >= 0) {
            (void)dup2(log_fd, 2);
        }
        close(pipefd[0]);
        close(pipefd[1]);
        execv(program, argv);
        _exit(127);
    }
    (void)setpgid(pid, pid);
    close(pipefd[1]);
    trace_pid = pid;
    trace_timed_out = 0;
    memset(&alarm_action, 0, sizeof alarm_action);
    alarm_action.sa_handler = on_trace_alarm;
    sigemptyset(&alarm_action.sa_mask);
    (void)sigaction(SIGALRM, &alarm_action, &old_action);
    remaining = limit - (long)(now_seconds() - start);
    alarm((unsigned)(remaining > 1 ? remaining : 1));
    trace = fdopen(pipefd[0], "rb");
    if (trace == NULL) {
        close(pipefd[0]);
        checked = -1;
    } else {
        (void)setvbuf(trace, NULL, _IOFBF, 1u << 16);
        checked = check_trace(trace, set, count, &result);
        fclose(trace); /* a library run still writing gets SIGPIPE */
    }
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    alarm(0);
    (void)sigaction(SIGALRM, &old_action, NULL);
    trace_pid = 0;
    c->driver_rss_kib = usage.ru_maxrss;
    c->checker_rss_kib = own_peak_rss_kib();
    unlink(program);
    unlink(driver);
    unlink(set_path);
    rmdir(dir);
    if (checked < 0) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: the checker ran out of memory");
        return 1;
    }
    c->cycles = result.cycles;
    c->executions = result.executions;
    snprintf(c->loads, sizeof c->loads, "%lu..%lu, %lu of %lu cycles at %lu", result.lowest_load,
             result.highest_load, result.cycles_at_highest, result.cycles, result.highest_load);
    snprintf(c->first_failure, sizeof c->first_failure, "%s", result.first_failure);
    used = 0;
    c->failed = 0;
    for (k = 0; k < CHECK_COUNT; k++) {
        used += (size_t)snprintf(c->failed_checks + used, sizeof c->failed_checks - used, "%s%s %llu",
                                 k ? ", " : "", check_property_name[k], result.failed[k]);
        c->failed += (unsigned long)result.failed[k];
        snprintf(line, sizeof line, "[%s] %s: %s\n", check_property_name[k],
                 result.failed[k] ? "violations found" : "holds in every cycle",
                 result.failed[k] ? "FAILURE" : "SUCCESS");
        append_log(log_path, line);
    }
    snprintf(line, sizeof line, "first failure: %s\n", result.first_failure);
    append_log(log_path, line);
    if (trace_timed_out) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: time limit of %ld s", limit);
        return 1;
    }
    if (checked != 0) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: %s", result.malformed ? "the trace is malformed"
                 : "the checker refuses the schedule");
        return 1;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        snprintf(c->verdict, sizeof c->verdict, "NOT CERTIFIED: the library run exited with status %d",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        return 1;
    }
    snprintf(c->verdict, sizeof c->verdict, "CERTIFIED");
    return 0;
}

/* --check-trace FILE PV...: the checker alone on a trace file (so that the
 * checker can be shown wrong traces no library writes). Exit 0 when every
 * property holds, 1 when one fails, 2 when FILE cannot be read. */
static int check_trace_file(const char *path, const uint8_t *set, size_t count)
{
    struct check_result result;
    FILE *f = fopen(path, "rb");
    int checked, k;
    if (f == NULL) {
        return cert_error("cannot read the trace", path);
    }
    checked = check_trace(f, set, count, &result);
    fclose(f);
    if (checked < 0) {
        fprintf(stderr, "bsched-plan: the checker ran out of memory\n");
        return 2;
    }
    printf("check-trace: %s: %lu cycles, %llu runs, failed:", checked == 0 ? "holds" : "FAILED", result.cycles,
           result.executions);
    for (k = 0; k < CHECK_COUNT; k++) {
        printf("%s %s %llu", k ? "," : "", check_property_name[k], result.failed[k]);
    }
    printf("; first failure: %s\n", result.first_failure);
    return checked == 0 ? 0 : 1;
}

/* The method --method auto picks: CBMC while the set's major cycle has at most
 * CERT_CBMC_MAX_WORK process-cycles (N x 2^maxpv; CBMC costs about 4 s + 13 ms
 * each, MEASUREMENTS.md), run+check above. */
static enum cert_method auto_method(size_t count, unsigned long maxpv)
{
    return (unsigned long long)count << maxpv <= CERT_CBMC_MAX_WORK ? METHOD_CBMC : METHOD_CHECK;
}

/* Certifies the set with the method given (not METHOD_AUTO): fills c. Returns 0
 * certified, 1 not certified. */
static int certify_run(enum cert_method method, const char *source, const uint8_t *set, size_t count,
                       unsigned long maxpv, long limit, const char *log_path, struct certificate *c)
{
    size_t i, used = 0;
    double start = now_seconds();
    int verdict;

    memset(c, 0, sizeof *c);
    c->method = method;
    for (i = 0; i < count; i++) {
        used += (size_t)snprintf(c->set + used, sizeof c->set - used, "%s%u", i ? " " : "", (unsigned)set[i]);
    }
    c->count = (unsigned long)count;
    c->maxpv = maxpv;
    library_digests(source, c);
    if (method == METHOD_CBMC) {
        verdict = certify_cbmc(source, set, count, maxpv, limit, log_path, c);
    } else {
        verdict = certify_check(source, set, count, limit, log_path, c);
        c->seconds = now_seconds() - start;
    }
    return verdict;
}

/* The certificate's text without its last two lines (the time and its own digest). */
static void certificate_body(const struct certificate *c, char *out, size_t size)
{
    int used = snprintf(out, size,
                        CERT_FORMAT "\n"
                        "method: %s\n"
                        "set: %s\n"
                        "processes: %lu\n"
                        "maxpv: %lu\n"
                        "bsched.c-sha256: %s\n"
                        "bsched.h-sha256: %s\n"
                        "spec-sha256: %s\n",
                        c->method == METHOD_CBMC ? "cbmc" : "run+check", c->set, c->count, c->maxpv,
                        c->bsched_sha, c->bsched_h_sha, c->spec_sha);
    if (used < 0 || (size_t)used >= size) {
        return;
    }
    if (c->method == METHOD_CBMC) {
        snprintf(out + used, size - (size_t)used,
                 "bsched_fig7.c-sha256: %s\n"
                 "harness-sha256: %s\n"
                 "cbmc: %s\n"
                 "solver: MiniSat (built into cbmc)\n"
                 "properties: %lu\n"
                 "failed: %lu\n"
                 "verdict: %s\n",
                 c->fig7_sha, c->harness_sha, c->cbmc, c->properties, c->failed, c->verdict);
    } else {
        snprintf(out + used, size - (size_t)used,
                 "trace-driver-sha256: %s\n"
                 "checker-sha256: %s\n"
                 "compiler: %s\n"
                 "compile: %s\n"
                 "checks: plan period balance fig7 repeat\n"
                 "cycles: %lu\n"
                 "executions: %llu\n"
                 "loads: %s\n"
                 "failed: %lu\n"
                 "failed-checks: %s\n"
                 "first-failure: %s\n"
                 "verdict: %s\n",
                 c->driver_sha, c->checker_sha, c->compiler, c->compile, c->cycles, c->executions, c->loads,
                 c->failed, c->failed_checks, c->first_failure, c->verdict);
    }
}

static int write_certificate(const char *path, const struct certificate *c)
{
    static char body[CERT_TEXT_MAX + 8192];
    char digest[80];
    FILE *f;
    certificate_body(c, body, sizeof body);
    text_sha256(body, digest, sizeof digest);
    f = fopen(path, "w");
    if (f == NULL) {
        return svg_error(path, strerror(errno));
    }
    fprintf(f, "%sseconds: %.1f\ncertificate-sha256: %s\n", body, c->seconds, digest);
    if (fclose(f) != 0) {
        return svg_error(path, strerror(errno));
    }
    return 0;
}

static void print_certificate_summary(const char *path, const struct certificate *c)
{
    if (c->method == METHOD_CBMC) {
        printf("%s: %lu processes, maxpv %lu, cbmc: %lu properties, %s (%.1f s) -> %s\n",
               c->verdict[0] == 'C' ? "certified" : "not certified", c->count, c->maxpv, c->properties,
               c->verdict, c->seconds, path);
    } else {
        printf("%s: %lu processes, maxpv %lu, run+check: %lu cycles, %llu runs, %s (%.1f s; max RSS: "
               "checker %ld KiB, library run %ld KiB) -> %s\n",
               c->verdict[0] == 'C' ? "certified" : "not certified", c->count, c->maxpv, c->cycles,
               c->executions, c->verdict, c->seconds, c->checker_rss_kib, c->driver_rss_kib, path);
    }
}

/* Reads the value of "key: value" from a certificate's text. */
static int cert_field(const char *text, const char *key, char *out, size_t size)
{
    size_t klen = strlen(key);
    const char *p = text;
    while (p != NULL && *p != '\0') {
        if (strncmp(p, key, klen) == 0 && p[klen] == ':' && p[klen + 1] == ' ') {
            const char *v = p + klen + 2;
            size_t len = strcspn(v, "\n");
            if (len >= size) {
                return -1;
            }
            memcpy(out, v, len);
            out[len] = '\0';
            return 0;
        }
        p = strchr(p, '\n');
        if (p != NULL) {
            p++;
        }
    }
    return -1;
}

/* --recheck FILE: the certificate is intact (its digest), its set is checked
 * again by the method it names, on the current sources and tools, and every
 * line but the time must come out the same. */
static int recheck(const char *path, const char *source, long limit)
{
    static char text[CERT_TEXT_MAX + 16384], body[CERT_TEXT_MAX + 8192], value[CERT_TEXT_MAX];
    static char was[CERT_TEXT_MAX], is[CERT_TEXT_MAX];
    static struct certificate now;
    static uint8_t set[BSCHED_MAX_PROCS];
    char digest[80], stored[80], log_path[PATH_MAX], method[32];
    FILE *f = fopen(path, "r");
    size_t got, count = 0, cut;
    unsigned long maxpv = 0;
    char *p, *end, *last_line;
    int differs = 0;
    enum cert_method m;
    static const char *const common_keys[] = {"method", "set", "processes", "maxpv", "bsched.c-sha256",
                                              "bsched.h-sha256", "spec-sha256"};
    static const char *const cbmc_keys[] = {"bsched_fig7.c-sha256", "harness-sha256", "cbmc", "solver",
                                            "properties", "failed", "verdict"};
    static const char *const check_keys[] = {"trace-driver-sha256", "checker-sha256", "compiler", "compile",
                                             "checks", "cycles", "executions", "loads", "failed",
                                             "failed-checks", "first-failure", "verdict"};
    const char *const *keys;
    size_t k, nkeys;

    if (f == NULL) {
        return cert_error("cannot read the certificate", path);
    }
    got = fread(text, 1, sizeof text - 1u, f);
    fclose(f);
    text[got] = '\0';
    if (strncmp(text, CERT_FORMAT_1 "\n", strlen(CERT_FORMAT_1) + 1u) == 0) {
        printf("recheck: FAILED: %s is a certificate of format 1 (before --method and the digests of "
               "bsched.h and spec/): certify the set again\n", path);
        return 1;
    }
    if (strncmp(text, CERT_FORMAT "\n", strlen(CERT_FORMAT) + 1u) != 0) {
        return cert_error("not a bsched-plan certificate:", path);
    }
    /* Its own digest covers every line before "seconds:" (the time may differ). */
    last_line = strstr(text, "\nseconds: ");
    if (last_line == NULL || cert_field(text, "certificate-sha256", stored, sizeof stored) != 0) {
        printf("recheck: FAILED: %s is corrupted (no seconds or certificate-sha256 line)\n", path);
        return 1;
    }
    cut = (size_t)(last_line - text) + 1u;
    memcpy(body, text, cut);
    body[cut] = '\0';
    text_sha256(body, digest, sizeof digest);
    if (strcmp(digest, stored) != 0) {
        printf("recheck: FAILED: %s is corrupted: its lines do not match its certificate-sha256\n", path);
        return 1;
    }
    if (cert_field(text, "method", method, sizeof method) != 0 ||
        (strcmp(method, "cbmc") != 0 && strcmp(method, "run+check") != 0)) {
        printf("recheck: FAILED: %s names no method (cbmc or run+check)\n", path);
        return 1;
    }
    m = strcmp(method, "cbmc") == 0 ? METHOD_CBMC : METHOD_CHECK;
    if (cert_field(text, "set", value, sizeof value) != 0) {
        printf("recheck: FAILED: %s has no set\n", path);
        return 1;
    }
    for (p = value; *p != '\0';) {
        unsigned long v = strtoul(p, &end, 10);
        if (end == p || v > CERT_MAX_PV || count >= BSCHED_MAX_PROCS) {
            printf("recheck: FAILED: %s: the set is not a list of priority values 0..%u\n", path, CERT_MAX_PV);
            return 1;
        }
        set[count++] = (uint8_t)v;
        maxpv = v > maxpv ? v : maxpv;
        p = end;
        while (*p == ' ') {
            p++;
        }
    }
    if (count == 0) {
        printf("recheck: FAILED: %s: the set is empty\n", path);
        return 1;
    }
    snprintf(log_path, sizeof log_path, "%s.recheck.log", path);
    (void)certify_run(m, source, set, count, maxpv, limit, log_path, &now);
    certificate_body(&now, body, sizeof body);
    keys = m == METHOD_CBMC ? cbmc_keys : check_keys;
    nkeys = m == METHOD_CBMC ? sizeof cbmc_keys / sizeof cbmc_keys[0] : sizeof check_keys / sizeof check_keys[0];
    for (k = 0; k < sizeof common_keys / sizeof common_keys[0] + nkeys; k++) {
        const char *key = k < sizeof common_keys / sizeof common_keys[0]
                              ? common_keys[k] : keys[k - sizeof common_keys / sizeof common_keys[0]];
        if (cert_field(text, key, was, sizeof was) != 0) {
            was[0] = '\0';
        }
        if (cert_field(body, key, is, sizeof is) != 0) {
            is[0] = '\0';
        }
        if (strcmp(was, is) != 0) {
            printf("recheck: differs: %s: certificate '%.200s%s', now '%.200s%s'\n", key, was,
                   strlen(was) > 200u ? "..." : "", is, strlen(is) > 200u ? "..." : "");
            differs = 1;
        }
    }
    if (differs) {
        printf("recheck: FAILED: the check of %s does not reproduce it (the log: %s)\n", path, log_path);
        return 1;
    }
    if (strcmp(now.verdict, "CERTIFIED") != 0) {
        printf("recheck: reproduced, but the set is %s (%s)\n", now.verdict, log_path);
        return 1;
    }
    printf("recheck: OK: %s reproduced by %s: %lu processes, CERTIFIED (%.1f s)\n", path, method, now.count,
           now.seconds);
    return 0;
}

int main(int argc, char **argv)
{
    int json = 0;
    const char *svg = NULL;
    const char *certify = NULL;
    const char *recheck_file = NULL;
    const char *trace_file = NULL;
    const char *source = BSCHED_PLAN_SOURCE;
    long limit = CERT_DEFAULT_LIMIT;
    size_t count = 0;
    int a;
    int32_t rc;
    unsigned long maxpv = 0;
    int options_done = 0;
    enum cert_method method = METHOD_AUTO;
    const char *method_arg = NULL;
    int first_above_cert = 0; /* argv index of the first pv above CERT_MAX_PV */

    for (a = 1; a < argc; a++) {
        const char *arg = argv[a];
        char *end;
        long value;
        if (!options_done && (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0)) {
            print_help();
            return fflush(stdout) == 0 ? 0 : 1;
        }
        if (!options_done && strcmp(arg, "--json") == 0) {
            json = 1;
            continue;
        }
        if (!options_done && (strcmp(arg, "--certify") == 0 || strcmp(arg, "--recheck") == 0 ||
                              strcmp(arg, "--source") == 0 || strcmp(arg, "--check-trace") == 0)) {
            if (a + 1 >= argc || argv[a + 1][0] == '\0') {
                return usage_error(strcmp(arg, "--source") == 0 ? "--source needs a folder"
                                                                : "needs a certificate file name:", arg);
            }
            if (strcmp(arg, "--certify") == 0) {
                certify = argv[++a];
            } else if (strcmp(arg, "--check-trace") == 0) {
                trace_file = argv[++a];
            } else if (strcmp(arg, "--recheck") == 0) {
                recheck_file = argv[++a];
            } else {
                source = argv[++a];
            }
            continue;
        }
        if (!options_done && strcmp(arg, "--method") == 0) {
            if (a + 1 >= argc) {
                return usage_error("--method needs cbmc, check or auto", arg);
            }
            method_arg = argv[++a];
            if (strcmp(method_arg, "cbmc") == 0) {
                method = METHOD_CBMC;
            } else if (strcmp(method_arg, "check") == 0 || strcmp(method_arg, "run+check") == 0) {
                method = METHOD_CHECK;
            } else if (strcmp(method_arg, "auto") == 0) {
                method = METHOD_AUTO;
            } else {
                return usage_error("--method is cbmc, check or auto, not", method_arg);
            }
            continue;
        }
        if (!options_done && strcmp(arg, "--time-limit") == 0) {
            char *rest;
            if (a + 1 >= argc) {
                return usage_error("--time-limit needs a number of seconds", arg);
            }
            errno = 0;
            limit = strtol(argv[a + 1], &rest, 10);
            if (argv[a + 1][0] < '0' || argv[a + 1][0] > '9' || *rest != '\0' || errno == ERANGE || limit < 1) {
                return usage_error("--time-limit is not a whole number of seconds >= 1:", argv[a + 1]);
            }
            a++;
            continue;
        }
        if (!options_done && strcmp(arg, "--svg") == 0) {
            if (a + 1 >= argc || argv[a + 1][0] == '\0') {
                return usage_error("--svg needs a file name", arg);
            }
            svg = argv[++a];
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
        if (value > (long)CERT_MAX_PV && first_above_cert == 0) {
            first_above_cert = a;
        }
        pvs[count++] = (uint8_t)value;
        if ((unsigned long)value > maxpv) {
            maxpv = (unsigned long)value;
        }
    }
    if (recheck_file != NULL) {
        if (count != 0 || certify != NULL || json || svg != NULL || method_arg != NULL) {
            return usage_error("--recheck takes only the certificate (and --source, --time-limit):", recheck_file);
        }
        return recheck(recheck_file, source, limit);
    }
    if (count == 0) {
        return usage_error("no priority values given", "");
    }
    if (certify == NULL && method_arg != NULL) {
        return usage_error("--method goes with --certify:", method_arg);
    }
    if (trace_file != NULL) {
        if (certify != NULL || json || svg != NULL || method_arg != NULL) {
            return usage_error("--check-trace takes only the trace and the priority values:", trace_file);
        }
        if (first_above_cert != 0) {
            return usage_error("priority value above 16, the largest the checker takes:", argv[first_above_cert]);
        }
        return check_trace_file(trace_file, pvs, count);
    }
    if (certify != NULL && first_above_cert != 0) {
        /* Both methods stop at 16: the checker's limit, and far beyond CBMC's reach. */
        return usage_error("priority value above 16, the largest --certify takes:", argv[first_above_cert]);
    }
    if (certify != NULL) {
        static struct certificate cert;
        char log_path[PATH_MAX];
        int verdict;
        if (json || svg != NULL) {
            return usage_error("--certify does not go with --json or --svg:", certify);
        }
        if (bsched_init(&plan, pvs, count) != BSCHED_OK) {
            fprintf(stderr, "bsched-plan: bsched_init failed\n");
            return 2;
        }
        snprintf(log_path, sizeof log_path, "%s.log", certify);
        if (method == METHOD_AUTO) {
            method = auto_method(count, maxpv);
        }
        verdict = certify_run(method, source, pvs, count, maxpv, limit, log_path, &cert);
        if (write_certificate(certify, &cert) != 0) {
            return 2;
        }
        print_certificate_summary(certify, &cert);
        return verdict;
    }
    rc = bsched_init(&plan, pvs, count);
    if (rc != BSCHED_OK) {
        fprintf(stderr, "bsched-plan: bsched_init failed with code %ld\n", (long)rc);
        return 2;
    }
    number_members();
    if (svg != NULL) {
        if (write_svg_file(svg) != 0) {
            return 2;
        }
        (void)bsched_init(&plan, pvs, count); /* back to cycle 0 for the listing */
    }
    if (json) {
        print_json();
    } else {
        print_tables();
    }
    return fflush(stdout) == 0 ? 0 : 1;
}
