/* amorph/base.h: the base layer (src/base/): capacities and profile, the number type, status and
 * messages, text buffers and streams, maths, the random stream and the discrete cosine transform.
 * Of the amorph headers it includes only the profile's configuration (amorph/config_desktop.h,
 * config_board.h, or the project's AMORPH_CONFIG_H).
 */
#ifndef AMORPH_BASE_H
#define AMORPH_BASE_H

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ==== the library's version and its exported API.
 *
 * AM_VERSION_MAJOR names the binary interface: the shared library is libamorph.so.MAJOR (its
 * SONAME), in the file libamorph.so.MAJOR.MINOR.PATCH (the Makefile reads the three from here).
 * MAJOR goes up when a function's signature or a public struct's layout changes, MINOR when a
 * function is added, PATCH for anything else.
 *
 * AM_API marks each function of the public headers. The shared library is compiled with hidden
 * visibility (make shared), so it exports these functions and nothing else (make check-exports);
 * in the static library it changes nothing. On Windows it is empty unless a DLL is built
 * (AM_BUILD_DLL: dllexport) or used (AM_USE_DLL: dllimport); the Makefile builds none there. */
#define AM_VERSION_MAJOR 1
#define AM_VERSION_MINOR 1
#define AM_VERSION_PATCH 1
#if defined(_WIN32) || defined(__CYGWIN__)
#if defined(AM_BUILD_DLL)
#define AM_API __declspec(dllexport)
#elif defined(AM_USE_DLL)
#define AM_API __declspec(dllimport)
#else
#define AM_API
#endif
#elif defined(__GNUC__)
#define AM_API __attribute__((visibility("default")))
#else
#define AM_API
#endif

/* ==== every capacity of the library, in one place.
 *
 * Nothing in amorph allocates. Each array is sized here at compile time, and a capacity that
 * would be exceeded is reported as a status with a message, never written past. The capacities
 * come from one configuration header, as lwIP's lwipopts.h and FreeRTOS's FreeRTOSConfig.h: a
 * project's own, named by AMORPH_CONFIG_H (-DAMORPH_CONFIG_H='"myconfig.h"', or make
 * CONFIG=myconfig.h), or else the profile's, amorph/config_desktop.h (the default) or
 * amorph/config_board.h (make PROFILE=board). Each capacity the header leaves out takes the
 * default below, the desktop profile's value. docs/examples/config_small.h is a third one.
 * PROFILE also chooses how the model keeps its constants (amorph/sim.h) and which commands the
 * program has; the header only sizes.
 */

/* one profile per build (make PROFILE=desktop|board) */
#if defined(AM_PROFILE_BOARD) && defined(AM_PROFILE_DESKTOP)
#error "amorph: two profiles defined: build with one of AM_PROFILE_DESKTOP, AM_PROFILE_BOARD (make PROFILE=desktop|board)"
#endif

#if defined(AMORPH_CONFIG_H)
#include AMORPH_CONFIG_H
#elif defined(AM_PROFILE_BOARD)
#include "amorph/config_board.h"
#else
#include "amorph/config_desktop.h"
#endif

/* the name messages give the capacities ("exceeds the desktop profile's 20 cells per side") */
#ifndef AM_PROFILE_NAME
#define AM_PROFILE_NAME "custom"
#endif

/* ---- the lattice and the simulator (include/amorph/sim.h) ---- */
#ifndef AM_MAX_DIM
#define AM_MAX_DIM 20           /* cells along each lattice axis (board: 8) */
#endif
#define AM_MAX_CELLS (AM_MAX_DIM * AM_MAX_DIM * AM_MAX_DIM)   /* lattice cells */
#define AM_MAX_VOXELS AM_MAX_CELLS                            /* filled cells */
/* link entries: nv + 1 x lanes (sim.h), and the y and z face pairs of a full box */
#define AM_MAX_LINKS (AM_MAX_VOXELS + 1 + 2 * AM_MAX_DIM * AM_MAX_DIM * (AM_MAX_DIM - 1))
#define AM_MAX_MATERIALS 16     /* palette entries; cell value 0 is empty, 1..16 a material */
#ifndef AM_MAX_PAIRS
#define AM_MAX_PAIRS (12 * AM_MAX_VOXELS) /* self-collision candidate pairs (board: 6 per voxel) */
#endif
#ifndef AM_COLL_BUCKETS
#define AM_COLL_BUCKETS 4096    /* spatial hash buckets of the collision broad phase, a power of 2 (board: 256) */
#endif
#ifndef AM_COLL_GAP_BINS
#define AM_COLL_GAP_BINS 32     /* the candidate pairs binned by their distance at the rebuild (desktop profile) */
#endif
#ifndef AM_GAIT_MAX_CYCLES
#define AM_GAIT_MAX_CYCLES 256  /* actuation cycles a gait records (board: 32) */
#endif
#define AM_NAME_MAX 24          /* material name, including the terminating NUL */
#define AM_ERR_MAX 256          /* recommended size of an error message buffer */

/* ---- genotypes (include/amorph/geno.h, docs/genotypes.md) ---- */
#ifndef AM_MAX_GENO_MATERIALS
#define AM_MAX_GENO_MATERIALS 6 /* density fields per genome: materials of a run's palette, 3..8 (board: 3) */
#endif
#if AM_MAX_GENO_MATERIALS < 3 || AM_MAX_GENO_MATERIALS > 8
#error "AM_MAX_GENO_MATERIALS: 3 to 8 (the seed's three materials; a remembered body's counts and packed cells hold 8)"
#endif
#ifndef AM_MAX_DCT_K
#define AM_MAX_DCT_K 8          /* DCT amplitudes per axis, k x k x k per material (board: 4) */
#endif
#ifndef AM_MAX_CPPN_LAYERS
#define AM_MAX_CPPN_LAYERS 5    /* CPPN layers m, >= 2 (board: 3) */
#endif
#ifndef AM_MAX_CPPN_NODES
#define AM_MAX_CPPN_NODES 8     /* CPPN nodes per layer n (board: 4) */
#endif
#ifndef AM_MAX_GMX_POINTS
#define AM_MAX_GMX_POINTS 64    /* Gaussian points per GMX genome (board: 24) */
#endif
#ifndef AM_GENO_TABLE
#define AM_GENO_TABLE 4096      /* intervals of the activation / falloff lookup tables (board: 256;
                                 * another value expresses genomes differently) */
#endif
#ifndef AM_CPPN_CHUNK
#define AM_CPPN_CHUNK 256       /* cells a CPPN sweep evaluates at once (board: 64) */
#endif
#ifndef AM_GENO_LAYERS
#define AM_GENO_LAYERS 1        /* 1: a genome may carry evolved fields beyond its materials, a phase and a
                                 * stiffness per voxel (actuation = phase, stiffness = evolved; docs/genotypes.md);
                                 * 0: not, and no memory for them (board: 0, its simulator has no per-voxel layers) */
#endif
#define AM_GENO_CONTROLS (2 * AM_GENO_LAYERS) /* evolved fields a genome may carry: phase, stiffness */
#define AM_MAX_GENO_FIELDS (AM_MAX_GENO_MATERIALS + AM_GENO_CONTROLS) /* fields of a genome: materials, then those */
/* the largest genome text am_genome_format can produce (every value takes at most 26 chars) */
#define AM_GENOME_TEXT_MAX (4096L + 30L * (AM_MAX_GENO_FIELDS * AM_MAX_DCT_K * AM_MAX_DCT_K * (AM_MAX_DCT_K + 4) \
    + AM_MAX_CPPN_LAYERS * AM_MAX_CPPN_NODES * (2 * AM_MAX_CPPN_NODES + 14) + AM_MAX_GENO_FIELDS * (2 * AM_MAX_CPPN_NODES + 4) \
    + AM_MAX_GMX_POINTS * (8 + AM_GENO_CONTROLS)))
/* ---- end of genotypes ---- */

/* ---- evolver (include/amorph/evo.h) ---- */
#ifndef AM_MAX_POPULATION
#define AM_MAX_POPULATION 256   /* individuals of a run (board: 20) */
#endif
#ifndef AM_MAX_WORKERS
#define AM_MAX_WORKERS 16       /* evaluation workspaces, one per thread (board: 1) */
#endif
#ifndef AM_EVO_BATCH
#define AM_EVO_BATCH AM_MAX_POPULATION /* offspring made, evaluated and placed at a time, even, >= 2
                                        * (desktop: a whole generation, one parallel map; board: 2) */
#endif
#ifndef AM_EVO_WAVE_MAX
#define AM_EVO_WAVE_MAX 16      /* runs evolved in lockstep by am_evo_generations (board: 1) */
#endif
#ifndef AM_EVO_MEMO
#define AM_EVO_MEMO 256         /* bodies whose results a run remembers, am_evo.memo (board: 2) */
#endif

/* ---- XML and VXA files (include/amorph/io.h, docs/vxa.md) ---- */
#ifndef AM_XML_MAX_NODES
#define AM_XML_MAX_NODES 8192   /* elements of one XML document (board: 768) */
#endif
#ifndef AM_XML_MAX_ATTRS
#define AM_XML_MAX_ATTRS 1024   /* attributes of one XML document (board: 128) */
#endif
#ifndef AM_XML_MAX_DEPTH
#define AM_XML_MAX_DEPTH 32     /* element nesting (board: 16) */
#endif
#ifndef AM_XML_MAX_BYTES
#define AM_XML_MAX_BYTES (4L << 20) /* longest XML text read, bytes (board: 256 KiB) */
#endif
#ifndef AM_VXA_WARN_TEXT
#define AM_VXA_WARN_TEXT 4096   /* bytes of warning lines kept by the VXA reader (board: 1024) */
#endif
/* ---- end of XML and VXA ---- */

/* what a configuration header must respect */
#if AM_MAX_DIM < 2 || AM_MAX_DIM > 64
#error "amorph: AM_MAX_DIM must be 2..64"
#endif
#if AM_COLL_BUCKETS < 1 || (AM_COLL_BUCKETS & (AM_COLL_BUCKETS - 1)) != 0
#error "amorph: AM_COLL_BUCKETS must be a power of 2"
#endif
#if AM_EVO_BATCH < 2 || AM_EVO_BATCH % 2 != 0 || AM_EVO_BATCH > AM_MAX_POPULATION
#error "amorph: AM_EVO_BATCH must be even, at least 2 and at most AM_MAX_POPULATION"
#endif
#if AM_MAX_CPPN_LAYERS < 2 || AM_MAX_WORKERS < 1 || AM_EVO_WAVE_MAX < 1 || AM_EVO_MEMO < 1 || AM_GAIT_MAX_CYCLES < 1
#error "amorph: AM_MAX_CPPN_LAYERS must be at least 2; AM_MAX_WORKERS, AM_EVO_WAVE_MAX, AM_EVO_MEMO and AM_GAIT_MAX_CYCLES at least 1"
#endif

/* ==== the number type of every simulation quantity.
 *
 * am_real is float by default (make REAL=float), double (make REAL=double) or a 32-bit fixed-point
 * integer (make REAL=fixed, docs/fixed.md). All simulation arithmetic goes through am_real and the
 * few macros below so that the fixed-point build is a switch rather than a fork: products and
 * quotients are written AM_MUL / AM_DIV, constants AM_R(1.5) (a constant expression only),
 * integers AM_INT(n), and conversions from and to double AM_FROM_DOUBLE / AM_TO_DOUBLE (never in
 * the per-step hot path).
 *
 * Parameters given by the user in SI units (material moduli, densities, the voxel size, gravity,
 * temperatures) are am_param: am_real in the float and double builds, double in the fixed build,
 * where the model converts them once into its own scaled units (voxel edge, voxel mass, a
 * reference time: include/amorph/sim.h), so that every quantity of a step is O(1).
 *
 * Determinism: only IEEE-exact operations are used (+ - * / sqrt, comparisons). The build uses
 * -ffp-contract=off and never -ffast-math, so every compiler, optimisation level and vector
 * width rounds each operation the same way. The fixed build uses integers only in a step.
 */

/* Bit-identical results need floating-point arithmetic done in the types the code names: float in
 * float, double in double (FLT_EVAL_METHOD 0). A compiler that evaluates in wider registers (the
 * x87 unit of 32-bit x86: 2; s390x under -std=c11: 1) rounds differently and gives other results,
 * so such a build is refused; docs/porting.md gives the flags that make it 0. */
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "amorph needs FLT_EVAL_METHOD 0: build x86-32 with -msse2 -mfpmath=sse, s390x with -fexcess-precision=fast (docs/porting.md)"
#endif

/* one number type per build: make REAL=... defines one of these; two would compile one silently */
#if defined(AM_REAL_FLOAT) + defined(AM_REAL_DOUBLE) + defined(AM_REAL_FIXED) > 1
#error "amorph: two number types defined: build with one of AM_REAL_FLOAT, AM_REAL_DOUBLE, AM_REAL_FIXED (make REAL=float|double|fixed)"
#endif

#if defined(AM_REAL_FIXED)
/* Q7.24: value = raw / 2^24, range [-128, 128), resolution 6.0e-8. Products and quotients go
 * through int64_t; AM_MUL rounds half up (adds half an ulp, then shifts arithmetically), AM_DIV
 * rounds half away from zero and saturates. Sums wrap (the build adds -fwrapv); the simulator
 * bounds its state every step so that a physical run never comes near the range. */
#define AM_REAL_FIXED_POINT 1
typedef int32_t am_real;
typedef double am_param;
#define AM_REAL_NAME "fixed"
#ifndef AM_FIX_FRAC
#define AM_FIX_FRAC 24
#endif
#define AM_FIX_ONE ((int32_t)1 << AM_FIX_FRAC)
#define AM_FIX_HALF ((int64_t)1 << (AM_FIX_FRAC - 1))
/* a constant (a constant expression: folded at compile time), rounded to nearest */
#define AM_R(c) ((am_real)((c) * (double)AM_FIX_ONE + ((c) < 0 ? -0.5 : 0.5)))
#define AM_P(c) ((am_param)(c))
#define AM_INT(n) ((am_real)((int32_t)(n) * AM_FIX_ONE)) /* |n| < 128 */
/* a / n and p / q for integers n, p, q (q > 0), rounded half away from zero */
#define AM_DIV_INT(a, n) ((am_real)am_fx_div_i64((int64_t)(a), (int64_t)(n)))
#define AM_RATIO(p, q) ((am_real)am_fx_div_i64((int64_t)(p) * AM_FIX_ONE, (int64_t)(q)))
/* a * n for an integer n, saturated */
#define AM_MUL_INT(a, n) am_fx_sat64((int64_t)(a) * (int64_t)(n))
#define AM_REAL_MAX ((am_real)INT32_MAX)
#define AM_REAL_EPS ((am_real)1)
static inline am_real am_fx_mul(am_real a, am_real b) { return (am_real)(((int64_t)a * b + AM_FIX_HALF) >> AM_FIX_FRAC); }
static inline am_real am_fx_sat64(int64_t v) { return v > INT32_MAX ? INT32_MAX : (v < -INT32_MAX ? -INT32_MAX : (am_real)v); }
static inline int64_t am_fx_div_i64(int64_t n, int64_t d) { return (n >= 0 ? n + d / 2 : n - d / 2) / d; }
static inline am_real am_fx_div(am_real a, am_real b)
{
    int64_t n = (int64_t)a * AM_FIX_ONE, d = b;
    if (d == 0) return a >= 0 ? INT32_MAX : -INT32_MAX;
    int64_t h = (d < 0 ? -d : d) / 2;
    int64_t q = (n >= 0 ? n + h : n - h) / d;
    return q > INT32_MAX ? INT32_MAX : (q < -INT32_MAX ? -INT32_MAX : (am_real)q);
}
AM_API am_real am_fx_sqrt(am_real x); /* base_math.c: the root rounded to nearest, 0 for x <= 0 */
/* a product kept whole (Q14.48 in int64_t), for squared norms of small vectors (friction forces
 * and speeds, whose squares would fall below the Q24 resolution) and exact sign tests */
typedef int64_t am_wide;
#define AM_MULW(a, b) ((int64_t)(a) * (b))
AM_API am_real am_fx_sqrt_wide(am_wide w); /* the root of a wide value, as am_real, rounded to nearest */
#define AM_WIDE_SQRT(w) am_fx_sqrt_wide(w)

#define AM_MUL(a, b) am_fx_mul((a), (b))
#define AM_DIV(a, b) am_fx_div((a), (b))
#define am_sqrt(x) am_fx_sqrt(x)
#define am_fabs(x) am_fx_abs(x)
#define am_floor(x) am_fx_floor(x)
static inline am_real am_fx_abs(am_real x) { return x < 0 ? -x : x; }
static inline am_real am_fx_floor(am_real x) { return (am_real)(x & ~(AM_FIX_ONE - 1)); }
/* the whole part of x (floor), as an integer */
#define AM_FLOOR_INT(x) ((int32_t)((x) >> AM_FIX_FRAC))
#define AM_TO_DOUBLE(x) ((double)(x) * (1.0 / (double)AM_FIX_ONE))
static inline am_real am_fx_from_double(double d)
{
    double r = d * (double)AM_FIX_ONE;
    if (!(r == r)) return 0;
    if (r >= 2147483647.0) return INT32_MAX;
    if (r <= -2147483647.0) return -INT32_MAX;
    return (am_real)(r < 0 ? r - 0.5 : r + 0.5);
}
#define AM_FROM_DOUBLE(d) am_fx_from_double(d)
#define AM_PARAM_TO_DOUBLE(p) ((double)(p))
#define AM_PARAM_FROM_DOUBLE(d) ((am_param)(d))
/* 1: every fixed-point value is finite */
static inline int am_finite(am_real x) { (void)x; return 1; }
#define AM_ISNAN(x) 0
static inline int am_param_finite(am_param x) { return (x - x) == (x - x) && (x - x) == 0.0; }
#else
#if defined(AM_REAL_DOUBLE)
typedef double am_real;
#define AM_REAL_NAME "double"
#define am_sqrt(x) sqrt(x)
#define am_fabs(x) fabs(x)
#define am_floor(x) floor(x)
#define AM_REAL_MAX 1.0e300
#define AM_REAL_EPS 2.220446049250313e-16
#else
typedef float am_real;
#define AM_REAL_NAME "float"
#define am_sqrt(x) sqrtf(x)
#define am_fabs(x) fabsf(x)
#define am_floor(x) floorf(x)
#define AM_REAL_MAX 1.0e30f
#define AM_REAL_EPS 1.1920929e-07f
#endif
typedef am_real am_param;
#define AM_R(c) ((am_real)(c))
#define AM_P(c) ((am_param)(c))
#define AM_INT(n) ((am_real)(n))
typedef am_real am_wide;
#define AM_MULW(a, b) AM_MUL((a), (b))
#define AM_WIDE_SQRT(w) am_sqrt(w)
#define AM_DIV_INT(a, n) AM_DIV((a), (am_real)(n))
#define AM_RATIO(p, q) AM_DIV((am_real)(p), (am_real)(q))
#define AM_MUL_INT(a, n) AM_MUL((am_real)(n), (a))
#define AM_MUL(a, b) ((a) * (b))
#define AM_DIV(a, b) ((a) / (b))
#define AM_FLOOR_INT(x) ((int32_t)am_floor(x))
#define AM_TO_DOUBLE(x) ((double)(x))
#define AM_FROM_DOUBLE(d) ((am_real)(d))
#define AM_PARAM_TO_DOUBLE(p) ((double)(p))
#define AM_PARAM_FROM_DOUBLE(d) ((am_param)(d))
/* 1 when x is neither NaN nor infinite (IEEE: x - x is 0 only for finite x) */
static inline int am_finite(am_real x) { return (x - x) == (x - x) && (x - x) == AM_R(0); }
static inline int am_param_finite(am_param x) { return am_finite(x); }
#define AM_ISNAN(x) ((x) != (x))
#endif

#define AM_PI AM_R(3.14159265358979323846)

static inline am_real am_min(am_real a, am_real b) { return a < b ? a : b; }
static inline am_real am_max(am_real a, am_real b) { return a > b ? a : b; }
static inline am_real am_clamp(am_real x, am_real lo, am_real hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* ==== status codes. Functions that can fail return am_status and write a one-line,
 * human-readable message (for files: "file:line: problem") into a caller's buffer; a piece of input
 * in a message goes through am_quote (below). */

typedef enum am_status {
    AM_OK = 0,
    AM_ERR_PARSE,      /* malformed input text */
    AM_ERR_RANGE,      /* a value outside its allowed range */
    AM_ERR_CAPACITY,   /* a compile-time capacity would be exceeded */
    AM_ERR_IO,         /* a file could not be read or written */
    AM_ERR_EMPTY,      /* nothing to simulate (no voxel) */
    AM_ERR_ARG,        /* a bad argument from the caller */
    AM_ERR_CANCELLED   /* the caller asked to stop (a cancel callback returned non-zero) */
} am_status;

/* the code's name ("ok", "parse", "range", "capacity", "io", "empty", "arg", "cancelled";
 * "unknown" for any other value) */
AM_API const char* am_status_name(am_status code);

/* writes "fmt" into err (size errsz, may be 0) like snprintf and returns code */
AM_API am_status am_fail(char* err, int errsz, am_status code, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* "fname:line: " followed by fmt into err, like am_fail: the one form of every file message.
 * The va_list form serves the parsers' own variadic wrappers. */
AM_API am_status am_vfail_at(char* err, int errsz, am_status code, const char* fname, int line, const char* fmt, va_list ap)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 0)))
#endif
    ;
AM_API am_status am_fail_at(char* err, int errsz, am_status code, const char* fname, int line, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* ---- invariants ----
 * AM_ASSERT(cond) states what the library assumes at that point (an index in range, a count within
 * its capacity). Compiled out unless the build defines AM_CHECKS (make CHECKS=1): then cond is not
 * evaluated and no instruction is emitted. With AM_CHECKS a false cond calls the check handler
 * with the file, the line and the condition's text. The handler is AM_CHECK_HANDLER(file, line,
 * message): a project's function given with -DAM_CHECK_HANDLER=name (a compile-time hook: the
 * library keeps no writable global), else am_check_failed, which prints "file:line: invariant
 * broken: message" on stderr and aborts. The model's and the state's invariants after every
 * build and step (am_model_validate, am_state_validate: docs/architecture.md, Invariants) go to
 * the same handler. */
#if defined(AM_CHECKS)
#if defined(AM_CHECK_HANDLER)
void AM_CHECK_HANDLER(const char* file, int line, const char* msg);
#else
#define AM_CHECK_HANDLER am_check_failed
#endif
AM_API void am_check_failed(const char* file, int line, const char* msg);
#define AM_ASSERT(cond) ((cond) ? (void)0 : AM_CHECK_HANDLER(__FILE__, __LINE__, #cond))
#else
#define AM_ASSERT(cond) ((void)sizeof(!(cond))) /* not evaluated: no code, and its names count as used */
#endif

/* ---- input quoted in messages ----
 * am_quote writes the input token s (its first n bytes; n < 0: up to its NUL; NULL: empty) into
 * out (capacity cap) the one way every reader quotes input in a message, "... '%s' ...":
 *   - at most AM_QUOTE_MAX (40) bytes of s are shown; when s is longer, "..." follows them;
 *   - printable ASCII (0x20..0x7e) stands for itself, except a backslash, written \\, and a single
 *     quote, written \';
 *   - newline, tab and carriage return are written \n, \t and \r; every other byte below 0x20,
 *     0x7f (DEL) and every byte from 0x80 up (so UTF-8 too) is written \xNN, two lowercase hex
 *     digits;
 * so the result is one line of printable ASCII whatever the input (the bytes ESC [ 3 1 m show as
 * \x1b[31m, the empty token as nothing). A cap of AM_QUOTE_BUF always holds the whole result; a
 * smaller cap holds whole escapes up to what fits, then "..." when that fits too. out is always
 * NUL-terminated (when cap >= 1). Returns out, or "" when out is NULL or cap < 1, for use as a
 * printf argument. */
#define AM_QUOTE_MAX 40
#define AM_QUOTE_BUF (4 * AM_QUOTE_MAX + 4) /* 40 escapes of 4 characters, "...", the NUL */
AM_API const char* am_quote(char* out, int cap, const char* s, long n);

/* ==== the bounded text buffer every writer formats into (genome, lattice, configuration,
 * checkpoint, VXA, SVG, HTML).
 *
 * Appending never writes past cap. Without a flush function the buffer holds the whole text: text
 * that does not fit sets `full`, keeps what was written NUL-terminated, and every later append is
 * dropped, so a writer checks once at the end. With a flush function the buffer is a window of a
 * stream: when a piece does not fit, the buffered bytes are handed to flush (which writes them to
 * a file, say) and the buffer starts again, so a text of any length goes through a small buffer;
 * `full` is then set only when flush fails or one piece is longer than the buffer. */

typedef struct am_text {
    char* buf;   /* output (cap bytes) */
    long cap;    /* capacity, including the NUL */
    long len;    /* characters in buf */
    int full;    /* 0; 1 once something did not fit; 2 once a flush failed */
    /* streaming (optional, NULL for a whole-text buffer): receives the n buffered bytes at data;
     * AM_OK, or a failure that sets full (the flush function keeps its own message) */
    am_status (*flush)(void* ctx, const char* data, long n);
    void* ctx;   /* the flush function's context */
    long done;   /* bytes handed to flush so far (the text's length is done + len) */
} am_text;

/* appends printf-style text */
AM_API void am_text_put(am_text* t, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* the va_list form, for the writers' own variadic helpers */
AM_API void am_text_vput(am_text* t, const char* fmt, va_list ap)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 0)))
#endif
    ;
/* appends n bytes of data (no NUL inside) */
AM_API void am_text_write(am_text* t, const char* data, long n);
/* a flush function that drops the text: a stream through it only counts (done + len is the length) */
AM_API am_status am_text_drop(void* ctx, const char* data, long n);
/* a writer of a whole text: formats ctx into out (the genome, configuration and checkpoint
 * writers behind one of these) */
typedef am_status (*am_text_writer)(const void* ctx, am_text* out, char* err, int errsz);
/* writes ctx into buf (capacity cap, NUL-terminated) as one whole text; *len (may be NULL) gets
 * its length. When it does not fit, writes it again through a counting stream and fails with
 * "WHAT needs N bytes, the buffer holds CAP" (AM_ERR_CAPACITY), *len then the length needed. */
AM_API am_status am_text_format(am_text_writer write, const void* ctx, const char* what, char* buf, long cap, long* len,
                         char* err, int errsz);
/* hands the buffered bytes to flush (a whole-text buffer keeps them). AM_OK while nothing was
 * dropped, else AM_ERR_CAPACITY (full 1) or AM_ERR_IO (full 2: the flush function's message) */
AM_API am_status am_text_flush(am_text* t);

/* Strict numbers, as every reader and command-line flag takes them: the whole token is the number
 * (no blank, no '+', nothing after it); 1 with *out set, else 0 (NULL counts as no number).
 * am_parse_long: decimal digits after an optional '-', within long. am_parse_u64: decimal digits
 * only, within 64 bits. am_parse_double: strtod's syntax, finite, and within +-1e300. */
AM_API int am_parse_long(const char* s, long* out);
AM_API int am_parse_u64(const char* s, uint64_t* out);
AM_API int am_parse_double(const char* s, double* out);

/* the process id in an atomic write's temporary file name, NAME.tmp.PID.NONCE as the POSIX and
 * Windows ports name them (NAME not empty, PID decimal digits, NONCE 1 to 16 lowercase hex digits)
 * or NAME.tmp.PID as builds before them did; -1 for any other name. A PID of 2 * 10^9 or more
 * reads as 2 * 10^9. The ports' am_port_remove_stale removes the files so named. */
AM_API long am_temp_name_pid(const char* name);

/* ==== deterministic elementary functions (am_ prefix: pure utilities).
 *
 * libm's sin, cos, exp, pow and cbrt differ between C libraries and versions in the last bit,
 * which would break bit-identical results across platforms. These are written from + - * / and
 * sqrt in a fixed order, so every platform computes the same bits. Accuracy: a few ulp of am_real
 * over the documented range; they are not for the hot loop (the simulator calls them once per
 * material per step at most).
 */

AM_API am_real am_sin(am_real x);            /* any finite x (radians) */
AM_API am_real am_cos(am_real x);            /* any finite x (radians) */
AM_API am_real am_exp(am_real x);            /* x in [-80, 80]; clamps outside */
AM_API am_real am_log(am_real x);            /* x > 0; returns -AM_REAL_MAX for x <= 0 */
AM_API am_real am_cbrt(am_real x);           /* any finite x */
AM_API am_real am_pow(am_real x, am_real y); /* x > 0 */
AM_API am_real am_atan2(am_real y, am_real x); /* radians in (-pi, pi] */
AM_API am_real am_acos(am_real x);           /* x clamped to [-1, 1] */

/* ==== the seeded pseudo-random stream (xoshiro256** algorithm, splitmix64 seeding).
 *
 * Random numbers are consumed only serially from one stream (the evolver's), so a run is the same
 * for any thread count. Every draw is defined on integers, so it is the same on every platform.
 */

typedef struct am_rng {
    uint64_t s[4];   /* generator state; never all zero */
} am_rng;

AM_API void am_rng_seed(am_rng* r, uint64_t seed);          /* any seed, 0 included */
AM_API uint64_t am_rng_u64(am_rng* r);                      /* uniform 64-bit integer */
AM_API uint32_t am_rng_below(am_rng* r, uint32_t n);        /* uniform in [0, n), n >= 1, unbiased */
AM_API am_real am_rng_unit(am_rng* r);                      /* uniform in [0, 1) */
AM_API am_real am_rng_range(am_rng* r, am_real lo, am_real hi); /* uniform in [lo, hi) */
AM_API am_real am_rng_normal(am_rng* r);                    /* standard normal (Box-Muller on am_log/am_cos) */
AM_API int am_rng_chance(am_rng* r, am_real p);             /* 1 with probability p */

/* 64-bit FNV-1a style hashing used for golden hashes of runs and states */
#define AM_HASH_INIT UINT64_C(0xcbf29ce484222325)
AM_API uint64_t am_hash_bytes(uint64_t h, const void* data, unsigned long n);
AM_API uint64_t am_hash_u64(uint64_t h, uint64_t v);
AM_API uint64_t am_hash_real(uint64_t h, am_real v);        /* hashes the bit pattern (-0 folded to 0) */

/* ==== the hand-written, separable 3-D discrete cosine transform.
 *
 * Orthonormal pair: the forward transform is the DCT-II and the inverse the DCT-III, each scaled so
 * that the basis is orthonormal. Along one axis of n cells, coefficient u and cell x:
 *     B[u][x] = c_u cos(pi (2x + 1) u / (2n)),   c_0 = sqrt(1/n), c_u = sqrt(2/n) for u > 0
 *     inverse:  f[x] = sum_u a[u] B[u][x]          forward:  a[u] = sum_x f[x] B[u][x]
 * In 3-D the basis is the product of the three axes'. Only the k lowest coefficients per axis are
 * held (k <= n): the inverse zero-pads them to the n-cell workspace, the forward keeps the k lowest
 * (with k = n the two are exact inverses). The tables are computed once per (k, n) with am_cos and
 * cached in the caller's am_dct_work; the passes run axis by axis (through the caller's
 * am_dct_scratch), so the inverse costs
 * nx k^3 + nx ny k^2 + nx ny nz k multiply-adds instead of nx ny nz k^3.
 *
 * Layouts: coefficients (k0 x k1 x k2) at u + k0 (v + k1 w); cells (n0 x n1 x n2) at
 * x + n0 (y + n1 z), the lattice order. Every sum runs in a fixed order (deterministic).
 */

/* cached basis tables of the transforms; declare it static, zeroed */
typedef struct am_dct_work {
    int k[3];                                   /* coefficients kept per axis (table key) */
    int n[3];                                   /* cells per axis (table key) */
    am_real basis[3][AM_MAX_DIM * AM_MAX_DIM];  /* basis[a][u * n[a] + x] = B[u][x] of axis a */
} am_dct_work;

/* scratch of one transform (the passes' intermediate fields); nothing in it outlives a call, so
 * it may share memory with other scratch (am_geno_work does) */
typedef struct am_dct_scratch {
    am_real t1[AM_MAX_CELLS];                   /* the first pass */
    am_real t2[AM_MAX_CELLS];                   /* the second pass */
} am_dct_scratch;

/* prepares w for k[a] coefficients on n[a] cells per axis (1 <= k[a] <= n[a] <= AM_MAX_DIM);
 * recomputes the tables only when (k, n) changed. AM_ERR_CAPACITY / AM_ERR_RANGE otherwise. */
AM_API am_status am_dct_plan(am_dct_work* w, const int k[3], const int n[3], char* err, int errsz);
/* inverse (DCT-III): coef (k0 x k1 x k2, zero-padded) -> out (n0 x n1 x n2); needs am_dct_plan */
AM_API void am_dct_inverse(const am_dct_work* w, am_dct_scratch* s, const am_real* coef, am_real* out);
/* forward (DCT-II): in (n0 x n1 x n2) -> the k0 x k1 x k2 lowest coefficients; needs am_dct_plan */
AM_API void am_dct_forward(const am_dct_work* w, am_dct_scratch* s, const am_real* in, am_real* coef);

#ifdef __cplusplus
}
#endif
#endif
