/*
 * bsched-plan: plans a priority set with bsched.c and prints the paper's
 * Tables 1 and 2 for it (or one JSON object with --json), and with --svg FILE
 * also draws the major cycle as an SVG chart into FILE.
 *
 *   bsched-plan [--json] [--svg FILE] PV [PV ...]
 *   bsched-plan --help
 *
 * Exit status 0 on success, 2 on bad input (one line on stderr, nothing on stdout).
 * FILE is replaced only if it is a regular file (or does not exist yet); the
 * chart is written to a new temporary file beside it and renamed over it.
 */
#define _POSIX_C_SOURCE 200809L /* mkstemp, fchmod, fsync, lstat, umask */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "bsched.h"

/* The major cycle has 2^maxpv minor cycles; listing it is capped here. */
#define PLAN_MAX_LISTED_PV 20
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
           "  --          the arguments after it are priority values\n"
           "  --help      this text\n"
           "Exit status: 0 done, 2 bad input or FILE not written (one line on stderr).\n",
           PLAN_MAX_LISTED_PV, BSCHED_MAX_PROCS);
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

int main(int argc, char **argv)
{
    int json = 0;
    const char *svg = NULL;
    size_t count = 0;
    int a;
    int32_t rc;
    unsigned long maxpv = 0;
    int options_done = 0;

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
