/* tests/test_evo_run.c: reading log.csv back (src/evo/evo_run.c, am_evo_log_read_*): rows written by
 * am_evo_log_row read back exactly; columns are found by name (reordered, unknown ones skipped,
 * optional ones missing); a missing required column, a short or long row, a field that is not a
 * number, not finite or not whole are refused with "file:line: problem" (the field quoted by
 * am_quote); CRLF line ends, blank lines and an empty file. */
#include "harness.h"

#include "amorph.h"

#define MAX_ROWS 16

/* what reading a text gave: its rows, the status and message */
typedef struct log_read {
    am_evo_stats row[MAX_ROWS];
    int rows;
    am_status st;
    char err[AM_ERR_MAX];
    am_evo_log_reader r;
} log_read;

/* reads text line by line, as a file is read: each line is handed over without its newline, from
 * a copy followed by digits, so a reader that looked past the line's end would read them */
static void read_text(log_read* out, const char* text)
{
    memset(out, 0, sizeof *out);
    am_evo_log_read_begin(&out->r, "t.csv");
    const char* p = text;
    while (*p && out->st == AM_OK) {
        const char* nl = strchr(p, '\n');
        long n = nl ? (long)(nl - p) : (long)strlen(p);
        char line[512];
        if (n + 8 >= (long)sizeof line) {
            out->st = AM_ERR_CAPACITY;
            break;
        }
        memcpy(line, p, (size_t)n);
        memcpy(line + n, "9999999", 8);
        am_evo_stats row;
        int is_row = -1;
        out->st = am_evo_log_read_line(&out->r, line, n, &row, &is_row, out->err, sizeof out->err);
        if (out->st == AM_OK && is_row == 1 && out->rows < MAX_ROWS) out->row[out->rows++] = row;
        if (out->st == AM_OK && is_row != 0 && is_row != 1) out->st = AM_ERR_ARG; /* is_row must be set */
        p = nl ? nl + 1 : p + n;
    }
    if (out->st == AM_OK) out->st = am_evo_log_read_end(&out->r, out->err, sizeof out->err);
}

static log_read g_r;

static void test_round_trip(void)
{
    static const am_evo_stats in[4] = {
        {0, 20, 0.00607548222, 0.00357374351, 0.00343036047, 0, 0, 47.749, 0},
        {1, 40, 0.125, 0.0625, 0.05, 1, 2, 1.5, 3},
        {2, 60, -1.0, -1.0, -1.0, 20, 0, 0.0, 0}, /* every member diverged */
        {123456, 2469120, 1.23456789e-05, 3e-7, 0.5, 3, 17, 3600.125, 11},
    };
    char text[2048];
    int n = snprintf(text, sizeof text, "%s\n", am_evo_log_header());
    for (int i = 0; i < 4; i++) {
        n += am_evo_log_row(&in[i], text + n, (int)sizeof text - n);
        text[n++] = '\n';
        text[n] = 0;
    }
    read_text(&g_r, text);
    CHECK(g_r.st == AM_OK, "status %s: %s", am_status_name(g_r.st), g_r.err);
    CHECK(g_r.rows == 4 && g_r.r.rows == 4, "%d rows, reader counts %ld", g_r.rows, g_r.r.rows);
    CHECK(g_r.r.columns == AM_EVO_LOG_COLUMNS, "columns %d", g_r.r.columns);
    for (int k = 0; k < AM_EVO_LOG_COLUMNS; k++) CHECK(g_r.r.col[k] == k, "column of name %d: %d", k, g_r.r.col[k]);
    for (int i = 0; i < 4 && i < g_r.rows; i++) {
        const am_evo_stats* a = &in[i];
        const am_evo_stats* b = &g_r.row[i];
        CHECK(a->generation == b->generation && a->evaluations == b->evaluations, "row %d: generation %ld evaluations %ld", i,
              b->generation, b->evaluations);
        CHECK(a->best == b->best && a->mean == b->mean && a->median == b->median, "row %d: best %.17g mean %.17g median %.17g", i,
              b->best, b->mean, b->median);
        CHECK(a->diverged == b->diverged && a->empty == b->empty && a->unsettled == b->unsettled,
              "row %d: diverged %d empty %d unsettled %d", i, b->diverged, b->empty, b->unsettled);
        NEAR(b->wall_s, a->wall_s, 5e-4); /* written with 3 decimals */
    }
}

static void test_columns_by_name(void)
{
    /* reordered, two columns this reader does not know (one of them empty in the row), the
     * optional ones missing */
    read_text(&g_r, "note,best,wall_s,evaluations,extra,generation\n"
                    "first,0.5,2.25,40,,1\n"
                    "second,0.75,3,60,x,2\n");
    CHECK(g_r.st == AM_OK, "status %s: %s", am_status_name(g_r.st), g_r.err);
    CHECK(g_r.rows == 2, "%d rows", g_r.rows);
    CHECK(g_r.r.columns == 6, "columns %d", g_r.r.columns);
    if (g_r.rows == 2) {
        const am_evo_stats* a = &g_r.row[0];
        CHECK(a->generation == 1 && a->evaluations == 40 && a->best == 0.5 && a->wall_s == 2.25, "row 1: %ld %ld %g %g",
              a->generation, a->evaluations, a->best, a->wall_s);
        CHECK(isnan(a->mean) && isnan(a->median) && a->diverged == -1 && a->empty == -1 && a->unsettled == -1,
              "absent columns: %g %g %d %d %d", a->mean, a->median, a->diverged, a->empty, a->unsettled);
        CHECK(g_r.row[1].generation == 2 && g_r.row[1].evaluations == 60 && g_r.row[1].best == 0.75, "row 2");
    }
    /* blank lines before the header and between rows are skipped; a header alone is a log with no rows */
    read_text(&g_r, "\n\ngeneration,evaluations,best\n\n0,20,0.125\n\n1,40,0.25\n");
    CHECK(g_r.st == AM_OK && g_r.rows == 2 && g_r.row[1].best == 0.25, "blank lines: %s, %d rows", g_r.err, g_r.rows);
    read_text(&g_r, "generation,evaluations,best");
    CHECK(g_r.st == AM_OK && g_r.rows == 0 && g_r.r.header == 1, "a header alone: %s", g_r.err);
    /* a row is read to its given length only */
    read_text(&g_r, "generation,evaluations,best\n3,80,0.5");
    CHECK(g_r.st == AM_OK && g_r.rows == 1 && g_r.row[0].best == 0.5, "last line without a newline: %s %g", g_r.err,
          g_r.rows ? g_r.row[0].best : -1);
}

/* reading text must fail with status st and a message containing want */
static void expect_refused(const char* text, am_status st, const char* want)
{
    read_text(&g_r, text);
    CHECK(g_r.st == st && strstr(g_r.err, want) != NULL, "'%.40s...': status %s, message '%s' (want %s, '%s')", text,
          am_status_name(g_r.st), g_r.err, am_status_name(st), want);
}

static void test_bad_header(void)
{
    expect_refused("generation,evaluations,mean\n0,20,0.5\n", AM_ERR_PARSE, "t.csv:1: not a log.csv header: no 'best' column");
    expect_refused("generation,evals,fitness\n", AM_ERR_PARSE, "t.csv:1: not a log.csv header: no 'evaluations' column");
    expect_refused("\n0,20,0.5\n", AM_ERR_PARSE, "t.csv:2: not a log.csv header: no 'generation' column");
    expect_refused("generation,best,evaluations,best\n", AM_ERR_PARSE, "t.csv:1: not a log.csv header: column 'best' named twice (columns 2 and 4)");
    /* names match whole: a longer or padded name is another column */
    expect_refused("generation,evaluations,best_so_far\n", AM_ERR_PARSE, "no 'best' column");
    expect_refused("generation, evaluations,best\n", AM_ERR_PARSE, "no 'evaluations' column");
    expect_refused("", AM_ERR_PARSE, "t.csv:1: not a log.csv: no header line");
    expect_refused("\n\n", AM_ERR_PARSE, "t.csv:2: not a log.csv: no header line");
}

static void test_bad_rows(void)
{
    const char* h = "generation,evaluations,best,mean,median,diverged,empty,wall_s\n";
    char text[512];
    struct {
        const char* row;
        const char* want;
    } cases[] = {
        {"0,20,0.5,0.25,0.25,0,0", "t.csv:3: 7 fields, the header has 8 columns"},
        {"0,20,0.5,0.25,0.25,0,0,1.5,9", "t.csv:3: 9 fields, the header has 8 columns"},
        {"0", "t.csv:3: 1 field, the header has 8 columns"},
        {"0,20,zero,0.25,0.25,0,0,1.5", "t.csv:3: best (column 3): not a number: 'zero'"},
        {"0,20,0.5x,0.25,0.25,0,0,1.5", "t.csv:3: best (column 3): not a number: '0.5x'"},
        {"0,20,0.5,0.25,0.25,0,0, 1.5", "t.csv:3: wall_s (column 8): not a number: ' 1.5'"},
        {"0,20,0x10,0.25,0.25,0,0,1.5", "t.csv:3: best (column 3): not a number: '0x10'"},
        {"0,20,\x1b[31m,0.25,0.25,0,0,1.5", "t.csv:3: best (column 3): not a number: '\\x1b[31m'"}, /* quoted by am_quote */
        {"0,20,0.5,0.25,0.25,2\t0,0,1.5", "t.csv:3: diverged (column 6): not a whole number from 0 to 2147483647: '2\\t0'"},
        {"0,20,,0.25,0.25,0,0,1.5", "t.csv:3: best (column 3): empty, expected a number"},
        {"0,20,inf,0.25,0.25,0,0,1.5", "t.csv:3: best (column 3): not a finite number: 'inf'"},
        {"0,20,0.5,nan,0.25,0,0,1.5", "t.csv:3: mean (column 4): not a finite number: 'nan'"},
        {"0,20,0.5,0.25,1e999,0,0,1.5", "t.csv:3: median (column 5): not a finite number: '1e999'"},
        {"0,20.5,0.5,0.25,0.25,0,0,1.5", "t.csv:3: evaluations (column 2): not a whole number from 0"},
        {"-1,20,0.5,0.25,0.25,0,0,1.5", "t.csv:3: generation (column 1): not a whole number from 0"},
        {"0,20,0.5,0.25,0.25,3000000000,0,1.5", "t.csv:3: diverged (column 6): not a whole number from 0 to 2147483647"},
        {"0,99999999999999999999999,0.5,0.25,0.25,0,0,1.5", "t.csv:3: evaluations (column 2): not a whole number"},
        {"0,20,0.5,0.25,0.25,0,0,1.00000000000000000000000000000000000000000000000000000000000000000001",
         "t.csv:3: wall_s (column 8): not a number: '1.00000000000000000000000000000000000000...'"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(text, sizeof text, "%s1,40,0.125,0.1,0.1,0,0,1.000\n%s\n2,60,0.25,0.1,0.1,0,0,1.000\n", h, cases[i].row);
        expect_refused(text, AM_ERR_PARSE, cases[i].want);
        CHECK(g_r.rows == 1, "case %zu: %d rows read before the bad one", i, g_r.rows);
    }
    /* the unsettled column (the ninth of today's header) is a count like diverged */
    snprintf(text, sizeof text, "%s\n0,20,0.5,0.25,0.25,0,0,1.5,-2\n", am_evo_log_header());
    expect_refused(text, AM_ERR_PARSE, "t.csv:2: unsettled (column 9): not a whole number from 0 to 2147483647: '-2'");
    /* the first failure sticks: a good line after it is refused the same way */
    am_evo_log_reader r;
    am_evo_stats row;
    char err[AM_ERR_MAX], err2[AM_ERR_MAX];
    int is_row = 1;
    am_evo_log_read_begin(&r, "s.csv");
    CHECK(am_evo_log_read_line(&r, "generation,evaluations,best", 27, &row, &is_row, err, sizeof err) == AM_OK && is_row == 0,
          "header: %s", err);
    CHECK(am_evo_log_read_line(&r, "0,x,1", 5, &row, &is_row, err, sizeof err) == AM_ERR_PARSE && is_row == 0, "bad row");
    CHECK(am_evo_log_read_line(&r, "1,20,1", 6, &row, &is_row, err2, sizeof err2) == AM_ERR_PARSE && is_row == 0,
          "a good row after a failure was taken");
    CHECK(am_evo_log_read_end(&r, err2, sizeof err2) == AM_ERR_PARSE, "end after a failure");
    CHECK(r.rows == 0 && strstr(err, "s.csv:2: evaluations (column 2)") != NULL, "message: %s", err);
    /* no row to fill */
    am_evo_log_read_begin(&r, "s.csv");
    CHECK(am_evo_log_read_line(&r, "generation,evaluations,best", 27, NULL, NULL, err, sizeof err) == AM_ERR_ARG, "row NULL");
}

static void test_crlf_line_ends(void)
{
    /* best last: without the CR dropped, the header would name 'best\r' and the row read '0.5\r' */
    read_text(&g_r, "generation,evaluations,best\r\n0,20,0.5\r\n1,40,0.75\r\n");
    CHECK(g_r.st == AM_OK && g_r.rows == 2, "CRLF: %s, %d rows", g_r.err, g_r.rows);
    CHECK(g_r.rows == 2 && g_r.row[0].best == 0.5 && g_r.row[1].best == 0.75, "CRLF values");
    /* the whole header: unsettled (its last column) found and read */
    am_evo_stats s = {4, 100, 0.25, 0.125, 0.125, 0, 1, 2.5, 2};
    char text[512], row[256];
    am_evo_log_row(&s, row, (int)sizeof row);
    snprintf(text, sizeof text, "%s\r\n%s\r\n\r\n", am_evo_log_header(), row);
    read_text(&g_r, text);
    CHECK(g_r.st == AM_OK && g_r.rows == 1 && g_r.r.col[AM_EVO_LOG_COLUMNS - 1] == AM_EVO_LOG_COLUMNS - 1,
          "CRLF full header: %s, %d rows, unsettled at %d", g_r.err, g_r.rows, g_r.r.col[AM_EVO_LOG_COLUMNS - 1]);
    CHECK(g_r.rows == 1 && g_r.row[0].wall_s == 2.5 && g_r.row[0].empty == 1 && g_r.row[0].unsettled == 2, "CRLF wall_s %g",
          g_r.rows ? g_r.row[0].wall_s : -1);
    /* only one CR is a line end: a field ending in another is not a number */
    expect_refused("generation,evaluations,best\r\n0,20,0.5\r\r\n", AM_ERR_PARSE, "t.csv:2: best (column 3): not a number");
}

/* an experiment's results.csv rows come from the library as log.csv's do: the header amorph
 * experiment has always written, a row in it, and a short buffer cut, not overrun */
static void test_results_rows(void)
{
    CHECK(!strcmp(am_exp_results_header(), "variant,evaluations,mean_best,stderr_best,runs"), "%s", am_exp_results_header());
    char row[AM_EXP_RESULTS_ROW_MAX];
    int n = am_exp_results_row("gmx", 400, 0.0123456789, 0.001, 3, row, (int)sizeof row);
    CHECK(n == (int)strlen(row) && !strcmp(row, "gmx,400,0.0123456789,0.001,3"), "%s", row);
    CHECK(am_exp_results_row("gmx", 400, 0.5, 0.1, 3, row, 5) == 4 && !strcmp(row, "gmx,"), "a short buffer: %s", row);
    /* the run folder's names, one place (amorph/io.h) */
    CHECK(!strcmp(AM_RUN_LOG, "log.csv") && !strcmp(AM_RUN_EVALS, "evals.csv") && !strcmp(AM_RUN_CHECKPOINT, "checkpoint.txt") &&
          !strcmp(AM_RUN_CONFIG, "config.txt") && !strcmp(AM_EXP_RESULTS, "results.csv"), "the run folder's file names changed");
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick; /* the harness's, unused here */
    RUN(test_round_trip);
    RUN(test_columns_by_name);
    RUN(test_bad_header);
    RUN(test_bad_rows);
    RUN(test_crlf_line_ends);
    RUN(test_results_rows);
    return SUMMARY();
}
