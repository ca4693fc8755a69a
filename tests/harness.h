/* tests/harness.h: the plain-C test harness. Each tests/test_*.c is one program:
 *   static void test_something(void) { CHECK(x == 1, "x is %d", x); NEAR(a, b, tol); }
 *   int main(int argc, char** argv) { RUN(test_something); return SUMMARY(); }
 * `prog NAME` runs only the tests whose name contains NAME. The closing line is
 * "<file>: N passed, N failed". AM_TEST_QUICK=1 in the environment asks heavy tests to shrink
 * (used under valgrind). */
#ifndef AMORPH_TEST_HARNESS_H
#define AMORPH_TEST_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int t_pass_, t_fail_, t_argc_;
static char** t_argv_;
static const char* t_current_ = "";

#define CHECK(cond, ...)                                                                  \
    do {                                                                                  \
        if (cond) t_pass_++;                                                              \
        else {                                                                            \
            t_fail_++;                                                                    \
            fprintf(stderr, "%s:%d: %s: FAILED %s: ", __FILE__, __LINE__, t_current_, #cond); \
            fprintf(stderr, __VA_ARGS__);                                                 \
            fputc('\n', stderr);                                                          \
        }                                                                                 \
    } while (0)

/* |a - b| <= tol */
#define NEAR(a, b, tol)                                                                   \
    CHECK(fabs((double)(a) - (double)(b)) <= (double)(tol), "%s = %.9g, %s = %.9g, tolerance %.3g", \
          #a, (double)(a), #b, (double)(b), (double)(tol))
/* |a - b| <= rel * |b| */
#define NEAR_REL(a, b, rel)                                                               \
    CHECK(fabs((double)(a) - (double)(b)) <= (double)(rel) * fabs((double)(b)),           \
          "%s = %.9g, %s = %.9g, relative error %.3g > %.3g", #a, (double)(a), #b, (double)(b), \
          fabs((double)(a) - (double)(b)) / fabs((double)(b)), (double)(rel))

static int t_selected_(const char* name)
{
    if (t_argc_ < 2) return 1;
    for (int i = 1; i < t_argc_; i++)
        if (strstr(name, t_argv_[i])) return 1;
    return 0;
}

#define TEST_INIT(argc, argv) (t_argc_ = (argc), t_argv_ = (argv))
#define RUN(fn)                                                                           \
    do {                                                                                  \
        if (t_selected_(#fn)) {                                                           \
            t_current_ = #fn;                                                             \
            int f0_ = t_fail_;                                                            \
            fn();                                                                         \
            printf("  %-44s %s\n", #fn, t_fail_ == f0_ ? "ok" : "FAILED");                \
            fflush(stdout);                                                               \
        }                                                                                 \
    } while (0)
#define SUMMARY() (printf("%s: %d passed, %d failed\n", __FILE__, t_pass_, t_fail_), t_fail_ ? 1 : 0)

/* 1 when s is one line of printable ASCII, as every message must be (no control byte, no newline) */
static inline int printable_line(const char* s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 0x20 || (unsigned char)*s > 0x7e) return 0;
    return 1;
}

static int test_quick(void)
{
    const char* q = getenv("AM_TEST_QUICK");
    return q && *q == '1';
}

#endif
