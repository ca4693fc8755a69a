/* Results as key = value lines or one JSON object (tools/record.c): the same fields both ways,
 * numbers that are not finite written null in JSON (never nan or inf), strings escaped. */
#include <math.h>
#include <string.h>

#include "amorph.h"
#include "cmd.h"
#include "harness.h"

static char g_buf[4096];

static void record(int json, double v)
{
    am_text t;
    memset(&t, 0, sizeof t);
    t.buf = g_buf;
    t.cap = sizeof g_buf;
    tool_rec r;
    tool_rec_begin(&r, &t, json);
    tool_rec_str(&r, "robot", "a \"b\"\\c\n\x01");
    tool_rec_num(&r, "fitness", v);
    tool_rec_int(&r, "steps", 12);
    tool_rec_hex(&r, "hash", 0x0123456789abcdefULL);
    const double arr[3] = {1.5, v, -2};
    tool_rec_nums(&r, "travel", arr, 3);
    const char* names[2] = {"dct", "g\"mx"};
    tool_rec_strs(&r, "variants", names, 2);
    tool_rec_end(&r);
}

static void test_json(void)
{
    record(1, 0.25);
    CHECK(!strcmp(g_buf, "{\"robot\": \"a \\\"b\\\"\\\\c\\u000a\\u0001\", \"fitness\": 0.25, \"steps\": 12, \"hash\": \"0123456789abcdef\", "
                         "\"travel\": [1.5, 0.25, -2], \"variants\": [\"dct\", \"g\\\"mx\"]}\n"),
          "%s", g_buf);
    record(1, NAN);
    CHECK(strstr(g_buf, "\"fitness\": null,") && strstr(g_buf, "[1.5, null, -2]") && !strstr(g_buf, "nan"), "%s", g_buf);
    record(1, -INFINITY);
    CHECK(strstr(g_buf, "\"fitness\": null,") && !strstr(g_buf, "inf"), "%s", g_buf);
}

static void test_text(void)
{
    record(0, 0.25);
    CHECK(!strcmp(g_buf, "robot = a \"b\"\\c\n\x01\nfitness = 0.25\nsteps = 12\nhash = 0123456789abcdef\ntravel = 1.5 0.25 -2\n"
                         "variants = dct g\"mx\n"),
          "%s", g_buf);
}

static void test_escape_cuts(void)
{
    char out[10];
    tool_json_escape(out, sizeof out, "abcdefghijklmnop");
    CHECK(strlen(out) < sizeof out && !strncmp(out, "abc", 3), "%s", out);
    tool_json_escape(out, sizeof out, "\x1f\x1f\x1f");
    CHECK(!strcmp(out, "\\u001f"), "an escape is never cut: %s", out);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick; /* nothing here has a quick form */
    RUN(test_json);
    RUN(test_text);
    RUN(test_escape_cuts);
    return SUMMARY();
}
