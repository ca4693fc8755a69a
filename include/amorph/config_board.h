/* amorph/config_board.h: the board profile's capacities (make PROFILE=board), a configuration
 * header as a project writes its own (AMORPH_CONFIG_H; amorph/base.h lists every capacity, its
 * meaning and its default). An 8 x 8 x 8 workspace and a population of 20 on one thread, within
 * 192 KiB of RAM on a Cortex-M4 (docs/porting.md, Memory). */
#ifndef AMORPH_CONFIG_BOARD_H
#define AMORPH_CONFIG_BOARD_H
#define AM_PROFILE_NAME "board"
#define AM_MAX_DIM 8
#define AM_MAX_PAIRS (6 * AM_MAX_VOXELS)
#define AM_COLL_BUCKETS 256
#define AM_MAX_GENO_MATERIALS 3
#define AM_MAX_DCT_K 4
#define AM_MAX_CPPN_LAYERS 3
#define AM_MAX_CPPN_NODES 4
#define AM_MAX_GMX_POINTS 24
#define AM_GENO_TABLE 256
#define AM_GENO_LAYERS 0
#define AM_CPPN_CHUNK 64
#define AM_MAX_POPULATION 20
#define AM_MAX_WORKERS 1
#define AM_EVO_BATCH 2
#define AM_EVO_WAVE_MAX 1
#define AM_EVO_MEMO 2
#define AM_XML_MAX_NODES 768
#define AM_XML_MAX_ATTRS 128
#define AM_XML_MAX_DEPTH 16
#define AM_XML_MAX_BYTES (256L << 10)
#define AM_VXA_WARN_TEXT 1024
#define AM_GAIT_MAX_CYCLES 32
#endif
