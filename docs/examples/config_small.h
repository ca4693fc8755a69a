/* docs/examples/config_small.h: a project's own configuration header (docs/porting.md,
 * Capacities): the capacities it sets replace the defaults of include/amorph/base.h, the rest
 * keep them. A 6 x 6 x 6 workspace and small populations on two threads, on the desktop profile's
 * code. Build with it:
 *     make CONFIG=docs/examples/config_small.h BUILD=build/small
 * (make passes -DAMORPH_CONFIG_H="<its absolute path>"; a program built against that library
 * passes the same define, or AM_LAYOUT_CHECK refuses it). make test builds it and runs a scene. */
#ifndef CONFIG_SMALL_H
#define CONFIG_SMALL_H
#define AM_PROFILE_NAME "small"
#define AM_MAX_DIM 6
#define AM_COLL_BUCKETS 256
#define AM_MAX_DCT_K 4
#define AM_MAX_CPPN_LAYERS 3
#define AM_MAX_CPPN_NODES 4
#define AM_MAX_GMX_POINTS 16
#define AM_MAX_POPULATION 32
#define AM_MAX_WORKERS 2
#define AM_EVO_WAVE_MAX 2
#define AM_EVO_MEMO 32
#define AM_XML_MAX_NODES 1024
#define AM_XML_MAX_ATTRS 256
#define AM_XML_MAX_BYTES (512L << 10)
#define AM_GAIT_MAX_CYCLES 64
#define AM_GENO_LAYERS 0 /* no evolved phase or stiffness: genomes of materials only */
#endif
