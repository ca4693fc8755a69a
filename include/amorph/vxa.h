/* amorph/vxa.h: VoxCAD / Voxelyze files (VXA 1.1 holding a VXC 0.94 object), read and written.
 *
 * docs/vxa.md is the manual: which tags map to which amorph fields, the CTE convention (VXA's CTE
 * is linear per degree: a file read here sets env.cte_mode = AM_CTE_LINEAR), and what is not
 * supported. The reader parses the text with the fixed-memory XML reader (amorph/xml.h) into a
 * caller's workspace, fills a lattice and an environment, and lists every tag it does not
 * support as a warning line "fname:line: warning: unsupported tag <X> ignored" (never silence).
 * Malformed files are errors "fname:line: problem". ZLIB layers are inflated (amorph/inflate.h);
 * evosoro's per-voxel phases and stiffnesses and VoxCAD's boundary conditions come out as per-cell layers
 * (am_layers, for am_model_build_layers); a voxcraft VXD is read over its base (am_vxa_parse_vxd).
 *
 * The writer produces what VoxCAD writes (ASCII_READABLE structure) plus one <Amorph> element that
 * VoxCAD ignores and this reader uses, holding what VXA cannot say (per-material damping, fixed
 * materials, the volumetric CTE convention, the period in steps), so writing then reading gives
 * back the same lattice and materials bit for bit.
 */
#ifndef AMORPH_VXA_H
#define AMORPH_VXA_H

#include "amorph/config.h"
#include "amorph/lattice.h"
#include "amorph/sim.h"
#include "amorph/status.h"
#include "amorph/xml.h"

#ifdef __cplusplus
extern "C" {
#endif

/* what a VXA file says beside the lattice */
typedef struct am_vxa_info {
    am_env env;              /* the file's environment mapped to amorph (docs/vxa.md) */
    double temp_period;      /* s: the actuation period (<TempPeriod>); 0 when there is none */
    int period_steps_given;  /* 1 when the <Amorph> element fixed env.period_steps; else the caller
                                converts temp_period with am_vxa_period_steps once dt is known */
    am_layers layers;        /* per-cell layers beyond materials: evosoro's <PhaseOffset>, the boundary
                                conditions' fixed cells and forces (docs/vxa.md); build the model with
                                am_model_build_layers */
    char differ[256];        /* the ignored items (of those warned about) that change how the robot moves
                                in VoxCAD, Voxelyze or voxcraft-sim (FluidEnvironment, MatModel, ...),
                                comma separated, each once; empty when none (docs/vxa.md) */
    int warnings;            /* warnings found (all counted, the first ones kept in warning) */
    char warning[AM_VXA_WARN_TEXT]; /* warning lines, each ended by '\n'; NUL-terminated */
} am_vxa_info;

/* 1 when text looks like XML (after an optional byte order mark and blanks it starts with '<') */
int am_vxa_sniff(const char* text);

/* reads the NUL-terminated VXA text into lat and info, using work as the XML workspace (large:
 * declare it static). fname is used only in messages. AM_ERR_PARSE for malformed XML or VXA,
 * AM_ERR_RANGE for a value outside its range, AM_ERR_CAPACITY past a capacity of the build. */
am_status am_vxa_parse(am_lattice* lat, am_vxa_info* info, am_xml_doc* work, const char* text, const char* fname, char* err,
                       int errsz);

/* reads a base VXA file with a VXD file over it (voxcraft-sim's convention): every element of the
 * VXD (root <VXD>) with replace="VXA.A.B" stands for the element at that path of the base text,
 * or is added there when the base lacks it; the result is read as one VXA file. vxd_work is a
 * second XML workspace; messages name the file of the element at fault. A VXD text given alone to
 * am_vxa_parse is an error that says so. vxd_text NULL: am_vxa_parse. */
am_status am_vxa_parse_vxd(am_lattice* lat, am_vxa_info* info, am_xml_doc* work, const char* text, const char* fname,
                           am_xml_doc* vxd_work, const char* vxd_text, const char* vxd_fname, char* err, int errsz);

/* writes lat and env as a VXA file into buf (capacity cap, NUL-terminated); *len gets its length.
 * dt (s, > 0) is the time step the simulator uses for this robot (env.dt_frac times the model's
 * dt_rec): <TempPeriod> is env.period_steps * dt seconds. AM_ERR_ARG for a lattice or environment
 * that cannot be written, AM_ERR_CAPACITY when buf is short (AM_VXA_TEXT_MAX always suffices). */
am_status am_vxa_format(const am_lattice* lat, const am_env* env, double dt, char* buf, long cap, long* len, char* err,
                        int errsz);
/* the same with per-cell layers (NULL: none): phases as evosoro's <PhaseOffset> layers (in
 * periods, each value in the shortest form that reads back to the same bits), stiffnesses as its
 * <Stiffness> layers (Pa, likewise), and each voxel with a boundary condition (clamped, or a force)
 * as one box <FRegion> inside its own cell in <Boundary_Conditions>, at most AM_VXA_MAX_BC_VOXELS
 * of them (AM_ERR_CAPACITY past that) */
am_status am_vxa_format_layers(const am_lattice* lat, const am_layers* layers, const am_env* env, double dt, char* buf, long cap,
                               long* len, char* err, int errsz);
#define AM_VXA_MAX_BC_VOXELS 256
#define AM_VXA_TEXT_MAX (AM_MAX_MATERIALS * 2048L + AM_MAX_CELLS * 36L + AM_MAX_DIM * 128L + AM_VXA_MAX_BC_VOXELS * 640L + 8192L)

/* the actuation period in steps for a period in seconds and a time step: the nearest whole
 * number, at least 1, at most 10^7 (the configuration's largest period_steps) */
int am_vxa_period_steps(double period_s, double dt);

#ifdef __cplusplus
}
#endif
#endif
