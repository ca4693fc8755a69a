/* amorph/config.h: every capacity of the library, in one place.
 *
 * Nothing in amorph allocates. Each array is sized here at compile time, and a capacity that
 * would be exceeded is reported as a status with a message, never written past. Two profiles:
 *   desktop (default): a 20 x 20 x 20 workspace, as in the seed paper;
 *   board (make PROFILE=board): 8 x 8 x 8, for microcontrollers.
 */
#ifndef AMORPH_CONFIG_H
#define AMORPH_CONFIG_H

/* one profile per build (make PROFILE=desktop|board) */
#if defined(AM_PROFILE_BOARD) && defined(AM_PROFILE_DESKTOP)
#error "amorph: two profiles defined: build with one of AM_PROFILE_DESKTOP, AM_PROFILE_BOARD (make PROFILE=desktop|board)"
#endif

#if defined(AM_PROFILE_BOARD)
#define AM_PROFILE_NAME "board"
#define AM_MAX_DIM 8            /* cells along each lattice axis */
#else
#define AM_PROFILE_NAME "desktop"
#define AM_MAX_DIM 20
#endif

#define AM_MAX_CELLS (AM_MAX_DIM * AM_MAX_DIM * AM_MAX_DIM)   /* lattice cells */
#define AM_MAX_VOXELS AM_MAX_CELLS                            /* filled cells */
/* link entries: nv + 1 x lanes (sim.h), and the y and z face pairs of a full box */
#define AM_MAX_LINKS (AM_MAX_VOXELS + 1 + 2 * AM_MAX_DIM * AM_MAX_DIM * (AM_MAX_DIM - 1))
#define AM_MAX_MATERIALS 16     /* palette entries; cell value 0 is empty, 1..16 a material */
#if defined(AM_PROFILE_BOARD)
#define AM_MAX_PAIRS (6 * AM_MAX_VOXELS)   /* self-collision candidate pairs */
#define AM_COLL_BUCKETS 256     /* spatial hash buckets of the collision broad phase (power of 2) */
#else
#define AM_MAX_PAIRS (12 * AM_MAX_VOXELS)
#define AM_COLL_BUCKETS 4096
#define AM_COLL_GAP_BINS 32     /* the candidate pairs binned by their distance at the rebuild */
#endif
#define AM_NAME_MAX 24          /* material name, including the terminating NUL */
#define AM_ERR_MAX 256          /* recommended size of an error message buffer */

/* ---- genotypes (include/amorph/genotype.h, docs/genotypes.md) ---- */
#define AM_MAX_GENO_MATERIALS 3 /* density fields per genome: passive, active, active90 */
#if defined(AM_PROFILE_BOARD)
#define AM_MAX_DCT_K 4          /* DCT amplitudes per axis (k x k x k per material) */
#define AM_MAX_CPPN_LAYERS 3    /* CPPN layers m (>= 2) */
#define AM_MAX_CPPN_NODES 4     /* CPPN nodes per layer n */
#define AM_MAX_GMX_POINTS 24    /* Gaussian points per GMX genome */
#define AM_GENO_TABLE 256       /* intervals of the activation / falloff lookup tables */
#define AM_CPPN_CHUNK 64        /* cells a CPPN sweep evaluates at once */
#else
#define AM_MAX_DCT_K 8
#define AM_MAX_CPPN_LAYERS 5
#define AM_MAX_CPPN_NODES 8
#define AM_MAX_GMX_POINTS 64
#define AM_GENO_TABLE 4096
#define AM_CPPN_CHUNK 256
#endif
/* the largest genome text am_genome_format can produce (every value takes at most 26 chars) */
#define AM_GENOME_TEXT_MAX (4096L + 30L * (AM_MAX_GENO_MATERIALS * AM_MAX_DCT_K * AM_MAX_DCT_K * (AM_MAX_DCT_K + 4) \
    + AM_MAX_CPPN_LAYERS * AM_MAX_CPPN_NODES * (2 * AM_MAX_CPPN_NODES + 14) + AM_MAX_GENO_MATERIALS * (2 * AM_MAX_CPPN_NODES + 4) \
    + AM_MAX_GMX_POINTS * 8))
/* ---- end of genotypes ---- */

/* ---- evolver (include/amorph/evolve.h) ---- */
#if defined(AM_PROFILE_BOARD)
#define AM_MAX_POPULATION 20    /* individuals of a run */
#define AM_MAX_WORKERS 1        /* evaluation workspaces (one per thread) */
#define AM_EVO_BATCH 2          /* offspring made, evaluated and placed at a time (even, >= 2) */
#define AM_EVO_WAVE_MAX 1       /* runs evolved in lockstep by am_evo_generations */
#else
#define AM_MAX_POPULATION 256
#define AM_MAX_WORKERS 16
#define AM_EVO_BATCH AM_MAX_POPULATION /* a whole generation: one parallel map */
#define AM_EVO_WAVE_MAX 16
#endif

/* ---- XML and VXA files (include/amorph/xml.h, include/amorph/vxa.h, docs/vxa.md) ---- */
#if defined(AM_PROFILE_BOARD)
#define AM_XML_MAX_NODES 768    /* elements of one XML document */
#define AM_XML_MAX_ATTRS 128    /* attributes of one XML document */
#define AM_XML_MAX_DEPTH 16     /* element nesting */
#define AM_XML_MAX_BYTES (256L << 10) /* longest XML text read, bytes */
#define AM_VXA_WARN_TEXT 1024   /* bytes of warning lines kept by the VXA reader */
#else
#define AM_XML_MAX_NODES 8192
#define AM_XML_MAX_ATTRS 1024
#define AM_XML_MAX_DEPTH 32
#define AM_XML_MAX_BYTES (4L << 20)
#define AM_VXA_WARN_TEXT 4096
#endif
/* ---- end of XML and VXA ---- */

#endif
