/* amorph/config_desktop.h: the desktop profile's capacities (make PROFILE=desktop, the default), a
 * configuration header as a project writes its own (AMORPH_CONFIG_H; amorph/base.h lists every
 * capacity, its meaning and its default, which are these values). A 20 x 20 x 20 workspace, as in
 * the seed paper, populations of 256 on 16 threads. */
#ifndef AMORPH_CONFIG_DESKTOP_H
#define AMORPH_CONFIG_DESKTOP_H
#define AM_PROFILE_NAME "desktop"
#define AM_MAX_DIM 20
#define AM_MAX_PAIRS (12 * AM_MAX_VOXELS)
#define AM_COLL_BUCKETS 4096
#define AM_COLL_GAP_BINS 32
#define AM_MAX_DCT_K 8
#define AM_MAX_CPPN_LAYERS 5
#define AM_MAX_CPPN_NODES 8
#define AM_MAX_GMX_POINTS 64
#define AM_GENO_TABLE 4096
#define AM_GENO_LAYERS 1
#define AM_CPPN_CHUNK 256
#define AM_MAX_POPULATION 256
#define AM_MAX_WORKERS 16
#define AM_EVO_BATCH AM_MAX_POPULATION
#define AM_EVO_WAVE_MAX 16
#define AM_EVO_MEMO 256
#define AM_XML_MAX_NODES 8192
#define AM_XML_MAX_ATTRS 1024
#define AM_XML_MAX_DEPTH 32
#define AM_XML_MAX_BYTES (4L << 20)
#define AM_VXA_WARN_TEXT 4096
#define AM_GAIT_MAX_CYCLES 256
#endif
