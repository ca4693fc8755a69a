/* amorph/sim.h: the simulator layer (src/sim/): materials, the lattice a robot is made of, the model
 * built from it, the state and the step, and an evaluation's result. It includes amorph/base.h only.
 */
#ifndef AMORPH_SIM_H
#define AMORPH_SIM_H

#include <stdint.h>
#include "amorph/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ==== materials and the lattice of material ids a robot is made of.
 *
 * A lattice is nx x ny x nz cells of edge voxel_size metres. Cell (x, y, z) is stored at
 * index x + nx * (y + ny * z); value 0 is empty, value k in 1..palette.count is material
 * palette.mat[k - 1]. z is up; the floor is the plane z = 0.
 */

typedef struct am_material {
    char name[AM_NAME_MAX];  /* identifier: letters, digits, '_' and '-' */
    am_param E;               /* Young's modulus, Pa (> 0) */
    am_param density;         /* kg/m^3 (> 0) */
    am_param poisson;         /* Poisson ratio, [0, 0.5) */
    am_param cte;             /* thermal expansion per degree; volumetric or linear (see am_env) */
    am_param phase;           /* actuation phase, radians (added to the global temperature phase) */
    am_param mu_static;       /* static floor friction coefficient (>= 0) */
    am_param mu_kinetic;      /* kinetic floor friction coefficient (>= 0) */
    am_param zeta_internal;   /* internal (bond) damping ratio, fraction of critical */
    am_param zeta_global;     /* global (ground-referenced) damping ratio */
    am_param zeta_collision;  /* floor / self-collision damping ratio */
    uint8_t color[4];        /* display colour, RGBA */
    int fixed;               /* 1: voxels of this material are clamped in place */
} am_material;

typedef struct am_palette {
    int count;                              /* materials in use, 1..AM_MAX_MATERIALS */
    am_material mat[AM_MAX_MATERIALS];      /* mat[k - 1] is cell value k */
} am_palette;

/* the cell edges amorph simulates, m: one range wherever a size comes from (a lattice or VXA file,
 * the configuration's voxel_size, a model built from any of them); outside it the model's scales
 * lose their meaning (a subnormal edge makes masses and stiffnesses 0 or infinite) */
#define AM_VOXEL_SIZE_MIN 1e-5
#define AM_VOXEL_SIZE_MAX 10.0

typedef struct am_lattice {
    int nx, ny, nz;             /* cells along x, y, z; each 1..AM_MAX_DIM */
    am_param voxel_size;        /* cell edge, m */
    am_palette palette;
    uint8_t cell[AM_MAX_CELLS]; /* (nx*ny*nz) material ids, 0 = empty */
} am_lattice;

/* the default material (E 1 MPa, 1000 kg/m^3, passive, mu_s 1.0 / mu_k 0.3, zeta 1.0/0.01/0.8) */
AM_API am_material am_default_material(void);
/* the built-in palette of 9 materials: passive, active, active90 (90 degrees behind), stiff,
 * soft, heavy, light, active180, fixed. Active CTE is 0.01 (volumetric, as the seed). */
AM_API am_palette am_default_palette(void);
/* the same palette written into *out (no copy of the large struct on the stack) */
AM_API void am_default_palette_into(am_palette* out);
/* index (0-based) of the material named name in p, or -1 */
AM_API int am_palette_find(const am_palette* p, const char* name);

/* an empty lattice of the given size with the default palette; AM_ERR_CAPACITY past AM_MAX_DIM */
AM_API am_status am_lattice_init(am_lattice* lat, int nx, int ny, int nz, am_param voxel_size, char* err, int errsz);
static inline int am_lattice_index(const am_lattice* lat, int x, int y, int z) { return x + lat->nx * (y + lat->ny * z); }
AM_API int am_lattice_count(const am_lattice* lat);         /* filled cells */
/* 1 when a and b are the same robot: shape, voxel size and every material value bit for bit,
 * names up to their NUL, and the cells of the nx x ny x nz box */
AM_API int am_lattice_equal(const am_lattice* a, const am_lattice* b);

/* built-in scenes shared by tests, benchmarks and the command:
 *   cube:N        a solid N^3 cube of passive material
 *   sphere:D      cells whose centre is within D/2 of the centre of a D^3 lattice; the half with
 *                 x < D/2 is "active", the rest "passive" (sphere:20 has 4224 voxels)
 *   cantilever:N  an N x 1 x 1 beam of passive material whose x = 0 cell is "fixed" (the lattice
 *                 is N x 1 x 3 with the beam in the top layer; am_model_build sets the lowest
 *                 voxels on the floor, env.lift above it, as for every lattice)
 *   chain:N       an N x 1 x 1 row of passive voxels
 *   halfbar:N     the calibration bar (docs/validation.md): N x 3 x 3, the cells with x < N/2
 *                 "active", the rest "passive"
 *   antibar:N     the same with the rest "active180" (actuated half a period later) */
AM_API am_status am_scene_build(am_lattice* lat, const char* name, char* err, int errsz);


/* ==== the voxel soft-body simulator (docs/physics.md is the model).
 *
 * Immutable model, mutable state (as MuJoCo's mjModel / mjData): am_model_build turns a lattice and
 * an environment into voxels, links and constants once; am_step advances an am_state and never
 * writes the model, so one model can drive several states. Both structs are large (fixed
 * capacity): declare them static, one state per worker, never on the stack.
 *
 * Each step (docs/physics.md section 7): actuation (temperatures, voxel scales, rest lengths
 * once per pair of materials), self-collision and link forces (small- or large-angle beam), both from
 * the state at the start of the step, then semi-implicit Euler per voxel (the floor with its static and
 * kinetic friction inside it), which gathers its up-to-6 link
 * forces in a fixed order. Results do not depend on how work is split.
 */

enum { AM_CTE_VOLUMETRIC = 0, AM_CTE_LINEAR = 1 };
enum { AM_FIT_HORIZONTAL = 0, AM_FIT_PLUS_X = 1, AM_FIT_3D = 2 };

/* the environment of a simulation; am_default_env() gives the seed's */
typedef struct am_env {
    am_param gravity;          /* m/s^2 along -z (9.80665); 0 turns gravity off */
    int floor;                /* 1: the floor z = 0 is present */
    int collisions;           /* 1: self-collision on */
    int cte_mode;             /* AM_CTE_VOLUMETRIC (seed: s = cbrt(1 + cte T)) or AM_CTE_LINEAR (s = 1 + cte T) */
    am_param temp_base;        /* temperature offset at rest, degrees (0) */
    am_param temp_amplitude;   /* actuation amplitude A, degrees (30) */
    int period_steps;         /* actuation period P in time steps (500); 2 to 10^7 */
    am_param period_s;         /* s: when > 0, the period in seconds instead: am_model_build makes it
                               * period_steps of the model's step (and am_evaluate of a searched step);
                               * 0 (the default): period_steps as given */
    am_param dt_frac;          /* time step as a fraction of the analytic dt_rec */
    am_param lift;             /* m: the body's lowest face starts this high above the floor (0) */
    am_param zeta_internal_scale; /* multiplies every material's internal damping (1) */
    am_param zeta_global_scale;   /* multiplies every material's global damping (1) */
} am_env;

AM_API am_env am_default_env(void);

/* What a robot may carry per lattice cell beyond its material: VXA's per-voxel actuation phase
 * (evosoro's PhaseOffset layer), per-voxel stiffness (evosoro's Stiffness layer) and boundary
 * conditions (VXA's fixed and forced regions). Cell c is the lattice's cell c; entries of empty
 * cells are not read. am_model_build_layers takes it; am_model_build is that call with none. Large
 * (about 170 KB on the desktop): declare it static. */
/* the largest prescribed displacement of a clamped cell, in voxel edges (within the fixed-point range) */
#define AM_MAX_DISPLACE 50
typedef struct am_layers {
    int has_phase;                    /* 1: phase[] holds every cell's phase */
    int has_bc;                       /* 1: fixed[] and force[] hold boundary conditions */
    int has_stiffness;                /* 1: stiffness[] holds every cell's elastic modulus */
    am_param phase[AM_MAX_CELLS];     /* periods (evosoro's unit: 0.25 is a quarter period), added to the
                                       * material's phase as 2 pi phase radians */
    am_param stiffness[AM_MAX_CELLS]; /* Pa: the voxel's elastic modulus in place of its material's E
                                       * (every constant that follows from E: links, floor, damping) */
    uint8_t fixed[AM_MAX_CELLS];      /* 1: the cell's voxel is clamped (all six degrees of freedom) */
    am_param force[3][AM_MAX_CELLS];  /* N: a constant external force on the cell's voxel; on a clamped
                                       * cell (fixed[c]) m: its prescribed displacement from its lattice
                                       * place instead (VoxCAD's one slot per degree of freedom: a force
                                       * where it is free, a displacement where it is fixed) */
} am_layers;

/* no phases, no stiffnesses, no boundary conditions (the arrays are left as they are: only the
 * flags are read before them) */
AM_API void am_layers_clear(am_layers* l);

/* Index and constant layout. The desktop profile keeps every constant per voxel and per link and
 * 32-bit indices, so that the step's loops read them contiguously and vectorise. The board profile
 * (AM_COMPACT, make PROFILE=board) keeps them once per material and per pair of materials, which
 * is what they depend on, and 16-bit indices: the same values, a fraction of the RAM. Read them
 * through AM_VC (voxel constants) and AM_LC (link constants). */
#if defined(AM_PROFILE_BOARD)
#define AM_COMPACT 1
typedef int16_t am_index;                 /* voxel, link and cell index */
typedef uint8_t am_flag;                  /* a per-link flag */
typedef uint8_t am_pair;                  /* a link's pair of materials */
typedef uint8_t am_matid;                 /* a voxel's material */
#define AM_VC_CAP AM_MAX_MATERIALS        /* entries of a per-voxel constant */
#define AM_LC_CAP (AM_MAX_MATERIALS * AM_MAX_MATERIALS) /* entries of a per-link constant */
#define AM_VC(m, i) ((m)->mat[i])         /* the entry of voxel i */
#define AM_LC(m, l) ((m)->lpair[l])       /* the entry of link l */
#else
typedef int32_t am_index;
typedef int32_t am_flag;                  /* as wide as the values beside it: the loops vectorise */
typedef int32_t am_pair;                  /* 32 bits: the link loop gathers the rest lengths by it */
typedef int32_t am_matid;                 /* 32 bits: the step gathers the voxel scales by it */
#define AM_VC_CAP AM_MAX_VOXELS
#define AM_LC_CAP AM_MAX_LINKS
#define AM_VC(m, i) (i)
#define AM_LC(m, l) (l)
#endif

/* the immutable model. Shapes in the comments: nv = voxels, nl = link entries. Links are grouped
 * by axis: x-links are [0, axis_end[0]), y-links [axis_end[0], axis_end[1]), z-links the rest.
 * The x entries are lanes, nv + 1 of them: lane e (0 < e < nv) joins voxel e - 1 to voxel e, its +x
 * neighbour when it has one (voxels go by cell, x fastest); otherwise, and always for lanes 0 and
 * nv, the lane is empty (am_link_live) and its results are zeros, like those of the zero link nl.
 * So the step's x-link loop reads both ends contiguously, and voxel i finds its +x and -x results
 * at lanes i + 1 and i, instead of gathering them. */
typedef struct am_model {
    int nv, nl;                  /* voxels, link entries (links and empty x lanes) */
    int links;                   /* links */
    int axis_end[3];             /* see above */
    am_real L;                   /* nominal voxel edge, m */
    am_env env;                  /* the environment the model was built for */
    am_palette palette;          /* copy of the lattice's palette */
    int nx, ny, nz;              /* lattice size */
    am_index cell_voxel[AM_MAX_CELLS];    /* voxel of each lattice cell, -1 if empty */
    /* per voxel (nv); the constants below per voxel through AM_VC */
    am_index cell[AM_MAX_VOXELS];         /* lattice cell index */
    am_matid mat[AM_MAX_VOXELS];          /* palette index (0-based) */
    uint8_t surface[AM_MAX_VOXELS];       /* 1 when fewer than 6 links */
    uint8_t fixed[AM_MAX_VOXELS];         /* 1 when clamped */
    am_index slot[6][AM_MAX_VOXELS];      /* link per direction +x,-x,+y,-y,+z,-z; nl (a zero link) if none */
    am_real x0[3][AM_MAX_VOXELS];         /* initial centre, m */
    am_real mass[AM_VC_CAP];          /* kg */
    am_real inv_mass[AM_VC_CAP];      /* 1/kg, 0 for fixed voxels */
    am_real inv_inertia[AM_VC_CAP];   /* 1/(kg m^2), 0 for fixed voxels */
    am_real c_glob_t[AM_VC_CAP];      /* global damping, N s/m */
    am_real c_glob_r[AM_VC_CAP];      /* global damping, N m s */
    am_real k_floor[AM_VC_CAP];       /* floor/contact stiffness 2 E L, N/m */
    am_real c_col[AM_VC_CAP];         /* collision damping, N s/m */
    am_real mu_s[AM_VC_CAP], mu_k[AM_VC_CAP]; /* floor friction */
    /* per link (nl); index nl is the zero link that missing slots point at; the constants per link
     * through AM_LC */
    am_index lneg[AM_MAX_LINKS], lpos[AM_MAX_LINKS]; /* voxel at the -axis / +axis end */
    am_pair lpair[AM_MAX_LINKS];   /* materials of the ends: mat_neg * AM_MAX_MATERIALS + mat_pos */
    am_real k_ax[AM_LC_CAP];    /* E_link L^2, N (axial force = k_ax * strain) */
    am_real a2[AM_LC_CAP];      /* torsion GJ/L, N m */
    am_real b1[AM_LC_CAP];      /* shear 12EI/L^3, N/m */
    am_real b2[AM_LC_CAP];      /* coupling 6EI/L^2, N */
    am_real b3[AM_LC_CAP];      /* bending 2EI/L, N m */
    am_real c_t[AM_LC_CAP];     /* internal damping on the midpoint's relative velocity, N s/m (the
                                 * relative spin's is c_t L^2 / 12, N m s: docs/physics.md, Damping) */
    /* per material: actuation */
    am_real mat_cte[AM_MAX_MATERIALS];
    am_real mat_phase[AM_MAX_MATERIALS];
    /* a robot with its own phase per voxel (am_layers; desktop profile): each voxel actuates with
     * its material's phase plus vphase, and each link's rest length follows its two voxels (the
     * link loop finds it where the state's rest_at[l] says, where a robot without them finds its
     * pair of materials' at lpair[l]). voxel_phase is 0 for every other robot, which keeps the
     * per-material actuation */
    int voxel_phase;
    int any_force;                 /* 1: some voxel has a constant external force or a prescribed
                                      displacement (force) */
#if !defined(AM_COMPACT)
    int vphase_any;                   /* 1: some voxel's vphase is not 0 */
    am_real vphase[AM_MAX_VOXELS];    /* radians */
    /* the voxels of an actuated material and a phase other than 0, by their material and phase:
     * a class's sinusoid is found once a step for all its voxels (evolved phases are bytes) */
    int nphase;                           /* classes */
    am_index vphase_class[AM_MAX_VOXELS]; /* voxel i's class, -1 for none (its material's values) */
    am_index class_mat[AM_MAX_VOXELS];    /* a class's material */
    am_real class_phase[AM_MAX_VOXELS];   /* its phase, radians */
    am_index class_hash[2 * AM_MAX_VOXELS]; /* model build's scratch: the classes by material and phase */
    am_real force[3][AM_MAX_VOXELS];  /* the boundary conditions, model units: a free voxel's force
                                       * (am_state_reset puts it in fext), a clamped voxel's prescribed
                                       * displacement (am_state_reset puts it in x, where it stays: the
                                       * region moves there at the first step, as in VoxCAD) */
#endif
    am_real dt_rec;                /* analytic time step, s */
    am_real max_speed;             /* divergence bound on any voxel speed, m/s */
    am_real coll_range;            /* largest contact distance (two spheres at full scale), m */
    am_real max_scale;             /* largest linear voxel scale the actuation can reach */
    int any_cte;                   /* 1 when some material has a non-zero CTE */
    /* units: the SI value of one model unit of length, mass and time. 1 in the float and double
     * builds, where the model works in SI; in the fixed-point build the voxel edge, the mass of the
     * densest voxel and sqrt(mass / (E_max * edge)), so that every quantity of a step is O(1)
     * (docs/fixed.md). Every am_real of the model and the state is in these units. */
    double unit_len, unit_mass, unit_time;
    am_real gravity;               /* env.gravity in model units */
    am_real temp_base, temp_amplitude; /* env temperatures, degrees */
} am_model;

/* the neighbour of voxel i in direction d (0..5: +x, -x, +y, -y, +z, -z): the other end of the
 * link in that slot, -1 if none */
static inline int am_neighbour(const am_model* m, int d, int i)
{
    const int l = m->slot[d][i];
    return l == m->nl ? -1 : (d & 1 ? m->lneg[l] : m->lpos[l]);
}

/* 1 when entry l is a link (not an empty x lane) */
static inline int am_link_live(const am_model* m, int l) { return l >= m->axis_end[0] || m->slot[1][m->lpos[l]] == l; }

/* dimensions for converting model values to and from SI */
enum {
    AM_DIM_NONE, AM_DIM_LENGTH, AM_DIM_TIME, AM_DIM_MASS, AM_DIM_VELOCITY, AM_DIM_ACCEL, AM_DIM_MOMENTUM,
    AM_DIM_ANGMOM, AM_DIM_FORCE, AM_DIM_MOMENT, AM_DIM_ANGVEL, AM_DIM_ENERGY, AM_DIM_INERTIA, AM_DIM_STIFFNESS,
    AM_DIM_PRESSURE, AM_DIM_DAMPING
};
/* the SI value of one model unit of the dimension (1 in the float and double builds) */
AM_API double am_unit(const am_model* m, int dim);
/* a model value in SI (exactly (double)v in the float and double builds); never in a step */
AM_API double am_to_si(const am_model* m, am_real v, int dim);
/* an SI value in model units (exactly (am_real)v in the float and double builds) */
AM_API am_real am_from_si(const am_model* m, double v, int dim);
/* the time step dt_frac * dt_rec, s (rounded to am_real first in the float and double builds) */
AM_API double am_dt_si(const am_model* m, am_param dt_frac);

/* recording of voxel poses every `every` steps into a caller's fixed buffer, or handed to a sink */
struct am_state;
typedef struct am_record {
    int every;           /* record every this many steps (>= 1) */
    int max_frames;      /* capacity in frames */
    int nv;              /* voxels per frame (set by the simulator) */
    int frames;          /* frames written (or handed to the sink) so far */
    int truncated;       /* 1 when a frame was dropped for lack of room */
    float* pose;         /* max_frames * nv * 7 floats: x, y, z (m), qw, qx, qy, qz */
    long* step;          /* max_frames step numbers (may be NULL) */
    long pose_cap;       /* capacity of pose in floats */
    /* optional (NULL: frames are stored in pose): each frame is handed to sink(sink_ctx, m, s)
     * instead, nothing is stored and max_frames does not apply, so a recording of any length
     * streams; am_evaluate then also hands it the last step of the relaxation and the last step
     * of the evaluation when they are not multiples of every (each step at most once) */
    void (*sink)(void* sink_ctx, const am_model* m, const struct am_state* s);
    void* sink_ctx;
} am_record;

/* entries of the state's rest lengths: a pair of materials each, or on the desktop a link each */
#if defined(AM_COMPACT)
#define AM_REST_CAP (AM_MAX_MATERIALS * AM_MAX_MATERIALS)
#else
#define AM_REST_CAP (AM_MAX_MATERIALS * AM_MAX_MATERIALS + AM_MAX_LINKS)
#endif

/* the mutable state of one simulation */
typedef struct am_state {
    long step;               /* steps taken */
    int period_steps;        /* the actuation period in steps (the model's env.period_steps, or
                              * env.period_s at this state's dt; am_state_reset, am_evaluate) */
    am_real dt;              /* time step, s (the simulated time: am_sim_time) */
    long settle_steps;       /* of the steps, those the relaxation took at its settling pseudo-step */
    am_real settle_dt;       /* and that step (am_sim_time) */
    int actuate;             /* 1: temperatures follow the actuation; 0: held at temp_base */
    long actuation_step0;    /* step at which actuation started (phase reference) */
    int diverged;            /* 1 once NaN/Inf, strain or speed left its bound */
    long diverge_step;       /* step at which divergence was flagged */
    int pairs_overflow;      /* 1 when the collision candidate list hit AM_MAX_PAIRS */
    long rebuilds;           /* collision candidate list rebuilds */
    /* per voxel (nv) */
    am_real x[3][AM_MAX_VOXELS];  /* displacement of the centre from the rest lattice (model x0), m:
                                   * small numbers keep small increments (docs/physics.md) */
    am_real q[4][AM_MAX_VOXELS];  /* orientation quaternion w, x, y, z */
    am_real p[3][AM_MAX_VOXELS];  /* linear momentum, kg m/s */
    am_real h[3][AM_MAX_VOXELS];  /* angular momentum, kg m^2/s */
#if !defined(AM_COMPACT)
    /* derived and kept for the link loop; the board profile computes them where they are read,
     * the same values (src/sim/sim_internal.h, src/sim/sim_step.c) */
    am_real v[3][AM_MAX_VOXELS];  /* velocity p/m */
    am_real w[3][AM_MAX_VOXELS];  /* angular velocity h/I */
#endif
    am_real s[AM_MAX_VOXELS];     /* current linear scale from temperature */
#if !defined(AM_COMPACT)
    am_real s_rate[AM_MAX_VOXELS]; /* its rate of change, 1/s (a board reads mat_scale_rate) */
    /* a controller's actuation (am_api_sim_step; a model with a phase per voxel, voxel_phase):
     * each voxel with ctl_on takes ctl_scale and ctl_rate for its scale and its rate in place of
     * the sinusoid's; controlled is 1 when some voxel has ctl_on; am_state_reset clears it */
    int controlled;
    uint8_t ctl_on[AM_MAX_VOXELS];
    am_real ctl_scale[AM_MAX_VOXELS];
    am_real ctl_rate[AM_MAX_VOXELS];  /* 1/s, model units */
#endif
    am_real fext[3][AM_MAX_VOXELS]; /* external force set by the caller, N */
    am_real mext[3][AM_MAX_VOXELS]; /* external moment set by the caller, N m */
    am_real fc[3][AM_MAX_VOXELS];   /* scratch: self-collision force, then the step's total force, N */
    uint8_t contact[AM_MAX_VOXELS]; /* 0 no floor contact, 1 stuck, 2 sliding */
    /* per pair of materials (i * AM_MAX_MATERIALS + j): a link's rest length follows the scales
     * of its two voxels' materials. A robot with a phase per voxel (model voxel_phase) also has one
     * per link (entry AM_MAX_MATERIALS^2 + l) for each link with an end whose scale is not its
     * material's (a phase, a controller), and rest_at[l] says which entry link l reads */
    am_real pair_rest[AM_REST_CAP];     /* current rest length, m */
    am_real pair_inv_rest[AM_REST_CAP]; /* its inverse, 1/m */
#if !defined(AM_COMPACT)
    am_pair rest_at[AM_MAX_LINKS];      /* link l's entry: lpair[l], or its own */
    uint8_t rest_own[AM_MAX_VOXELS];    /* bit 0: voxel i's scale is not its material's at this
                                         * step; bit 1: nor was it at the last; bit 2: it moved
                                         * (a controlled robot without phases keeps them) */
    int vox_plain;                      /* 1: at the last step every voxel had its material's
                                         * scale and rate (and rest_own bit 0 is clear) */
    am_real class_scale[AM_MAX_VOXELS], class_rate[AM_MAX_VOXELS]; /* each phase class's (model
                                         * nphase) scale and rate at this step */
#endif
    /* the damping the step applies at this dt, per link constant (AM_LC): the model's c_t (scaled
     * down only past the limit of docs/physics.md, Damping), L^2 / 12 (c_r = c_t L^2 / 12) and the
     * scale alpha dt^2 of the damping correction; recomputed when dt or glob_scale changes */
    am_real damp_t[AM_LC_CAP], damp_kr;
    am_real damp_scale;                  /* alpha dt^2, s^2 */
    int damp_on;                         /* 1: some link is damped (the correction runs) */
    int damp_limited;                    /* 1: the damping is scaled down at this dt (docs/physics.md) */
    am_real glob_t[AM_VC_CAP], glob_r[AM_VC_CAP]; /* the global damping likewise, per voxel constant */
    am_real glob_scale;                  /* multiplies the global damping (1; 0 while the evaluation
                                          * settles a body with kinetic damping) */
    am_real damp_dt, glob_for_scale;     /* the dt and scale they were computed for (0: not yet) */
    /* per link (nl + 1; index nl stays zero) */
    am_flag large[AM_MAX_LINKS + 1];     /* 1 while the large-angle treatment is on */
    am_real mc[3][AM_MAX_VOXELS];        /* scratch: the step's total moment, N m */
#if defined(AM_COMPACT)
    /* the board profile keeps no per-link results: the step adds each link's force and moments
     * to its two voxels' totals (fc and mc) as it goes, in the order in which the desktop's voxels
     * gather them, so that every sum is the same (sim_step.c) */
#else
    am_real fn[3][AM_MAX_LINKS + 1];     /* force on the negative voxel, world, N */
    am_real mn[3][AM_MAX_LINKS + 1];     /* moment on the negative voxel, world, N m */
    am_real mp[3][AM_MAX_LINKS + 1];     /* moment on the positive voxel, world, N m */
    am_real strain[AM_MAX_LINKS + 1];    /* axial strain (diagnostic) */
#endif
    /* self-collision candidates */
    int npairs;                          /* -1 until the first build */
    int max_npairs;                      /* largest list so far */
    am_index pa[AM_MAX_PAIRS], pb[AM_MAX_PAIRS];
    am_real xref[3][AM_MAX_VOXELS];      /* displacements at the last rebuild */
#if !defined(AM_COMPACT)
    am_real pos[3][AM_MAX_VOXELS];       /* scratch: the centres x0 + x of the step, for the contacts
                                          * (the board computes them where read) */
    am_real bucket_pos[3][AM_MAX_VOXELS]; /* broad-phase scratch: bucket_item's centres, */
    int32_t bucket_seen[AM_COLL_BUCKETS];  /* the last voxel + 1 that visited the bucket, */
    am_index bucket_cursor[AM_COLL_BUCKETS]; /* and the bucket's first entry after that voxel */
    /* the candidate pairs by how far apart they were at the rebuild: bin b of AM_COLL_GAP_BINS
     * holds the pairs whose distance then exceeded the contact range by b to b + 1 bin widths
     * (the model's slack / AM_COLL_GAP_BINS), at pair_by_gap[b ? gap_end[b - 1] : 0, gap_end[b]);
     * a step tests only the bins a pair can have crossed since (sim_collide.c) */
    am_index pair_by_gap[AM_MAX_PAIRS];
    int32_t gap_end[AM_COLL_GAP_BINS];
    uint8_t pair_touch[AM_MAX_PAIRS];    /* scratch: the step's overlapping pairs, then bins */
#endif
    am_index bucket_end[AM_COLL_BUCKETS]; /* broad-phase scratch: the surface voxels sorted by */
    am_index bucket_item[AM_MAX_VOXELS];  /* bucket, bucket b at [b ? end[b-1] : 0, end[b]) */
    am_real mat_scale[AM_MAX_MATERIALS]; /* current linear scale per material */
    am_real mat_scale_rate[AM_MAX_MATERIALS]; /* its rate of change, 1/s */
    /* the rounding remainder of x: what the step's v dt lost when added to the displacement, carried
     * to the next step (compensated summation; in the fixed-point build the Q48 - Q24 part), so
     * that increments below the displacement's resolution accumulate instead of rounding away
     * (docs/physics.md, Bodies) */
    am_real x_rem[3][AM_MAX_VOXELS];
#if defined(AM_REAL_FIXED_POINT)
    /* the rounding remainders of p and h (Q48 - Q24 parts, error diffusion): a step adds F dt
     * exactly, so no increment below the resolution is lost (docs/fixed.md) */
    am_real p_rem[3][AM_MAX_VOXELS], h_rem[3][AM_MAX_VOXELS];
#endif
    int scales_valid;                    /* 0 until voxel scales and rest lengths follow mat_scale */
} am_state;

/* builds the model; AM_ERR_EMPTY for no voxel, AM_ERR_CAPACITY past a capacity, AM_ERR_RANGE for a
 * bad material or environment value */
AM_API am_status am_model_build(am_model* m, const am_lattice* lat, const am_env* env, char* err, int errsz);
/* the same with per-cell layers (NULL: none): phases make the model's voxel_phase, a stiffness per
 * cell replaces the material's E of its voxel (a link joins its two voxels' moduli as it joins two
 * materials'; dt_rec follows the stiffest), fixed cells are clamped as a fixed material's are, forces
 * act on their voxels at every step. The board profile has no room for phases, stiffnesses and
 * forces per voxel: AM_ERR_CAPACITY (fixed cells are taken there). */
AM_API am_status am_model_build_layers(am_model* m, const am_lattice* lat, const am_env* env, const am_layers* layers, char* err,
                                int errsz);
/* puts the state at rest at the initial pose, dt = env.dt_frac * dt_rec, actuation off */
AM_API void am_state_reset(const am_model* m, am_state* s);
/* one time step */
AM_API void am_step(const am_model* m, am_state* s);
/* n time steps, stopping early on divergence; returns steps taken */
AM_API long am_steps(const am_model* m, am_state* s, long n);
/* the invariants (docs/architecture.md, Invariants): AM_OK, or AM_ERR_RANGE with err naming the first
 * broken one. The model's: link layout, voxel, link and constant indices in range, finite positions,
 * stiffnesses and time step, positive masses; the state's: finite positions, orientations, momenta,
 * positive scales and time step (a diverged state passes: it is flagged). A build with -DAM_CHECKS
 * runs them after every am_model_build and am_step and calls AM_CHECK_HANDLER (amorph/base.h) on a failure */
AM_API am_status am_model_validate(const am_model* m, char* err, int errsz);
AM_API am_status am_state_validate(const am_model* m, const am_state* s, char* err, int errsz);

/* 1 / (2 pi sqrt(w)), s: w the largest of each link's a1 / min(m_neg, m_pos) and each voxel's
 * floor spring 0.5 k_floor / m (a lone voxel on the floor) */
AM_API am_real am_dt_analytic(const am_model* m);
/* the seed's empirical search: from 10 dt_rec down by factors of 10 until 100 steps of a thermal
 * step load show no significant strain energy growth, then a finer pass between the last unstable
 * and first stable value; returns 0.95 of the largest stable dt found. scratch is overwritten. */
AM_API am_real am_dt_search(const am_model* m, am_state* scratch);

/* energies (diagnostics and tests), J */
AM_API double am_kinetic_energy(const am_model* m, const am_state* s);
AM_API double am_strain_energy(const am_model* m, const am_state* s);
AM_API double am_potential_energy(const am_model* m, const am_state* s); /* gravity + floor springs */
/* centre of mass, m */
AM_API void am_com(const am_model* m, const am_state* s, double out[3]);
/* total linear and angular (about the origin) momentum */
AM_API void am_momentum(const am_model* m, const am_state* s, double lin[3], double ang[3]);
/* 64-bit hash of the dynamic state (positions, orientations, momenta, contact flags) */
AM_API uint64_t am_state_hash(const am_model* m, const am_state* s);

/* the seed's evaluation: relaxation, then `cycles` actuation cycles */
typedef struct am_eval_def {
    int cycles;              /* actuation cycles of the movement segment (10) */
    int fitness;             /* AM_FIT_HORIZONTAL (default), AM_FIT_PLUS_X or AM_FIT_3D */
    int dt_search;           /* 1: the seed's empirical time step search instead of env.dt_frac */
    /* the relaxation's step counts are steps of the default step, AM_REF_DT_FRAC dt_rec: at another
     * step (env.dt_frac, dt_search) am_evaluate scales them to last as long in seconds */
    long relax_max_steps;    /* relaxation ends here at the latest (40000) */
    long relax_min_steps;    /* and not before this (200) */
    am_param settle_speed;   /* m/s: relaxed when the RMS voxel speed stays below this (1e-4) */
    am_param relax_dt_frac;  /* settling's pseudo-step, a fraction of dt_rec (1.8; 0 or below the
                              * run's step: the run's step). The release window and the movement
                              * take the run's step; a relaxation that diverges or does not come to
                              * rest at the pseudo-step is done again at the run's step */
    long release_steps;      /* the last steps of relaxation, with the model's damping alone, over
                              * which the RMS speed must stay below settle_speed (500) */
    int score;               /* what the fitness scores: AM_SCORE_TRAVEL (the seed's, default) or
                              * AM_SCORE_SUSTAINED (am_result.sustained) */
    int sustained_from;      /* cycles: the sustained score's window starts after this many (10) */
    am_record* record;       /* optional recording (may be NULL) */
    struct am_gait* gait;    /* optional gait diagnostics of the movement segment (may be NULL) */
} am_eval_def;

AM_API am_eval_def am_default_eval(void);

/* A robot as one unit: its body, what it carries per cell, the environment it moves in and how it
 * is evaluated. A lattice file's robot is am_robot_init's; amorph/io.h fills one from a VXA file
 * (am_vxa_robot), and whoever builds its model takes it whole (am_robot_build). The lattice and
 * the layers are large: the robot points at them and their owner keeps them static. */
typedef struct am_robot {
    am_lattice* lattice;        /* the body */
    am_layers* layers;          /* per-cell layers (a VXA file's); NULL: none */
    am_env env;
    am_eval_def eval;           /* record and gait NULL unless a caller sets them */
} am_robot;

/* a robot of lat with no layers yet (layers, when not NULL, cleared), am_default_env() and
 * am_default_eval() */
AM_API void am_robot_init(am_robot* r, am_lattice* lat, am_layers* layers);
/* am_model_build_layers of the robot's lattice, environment and layers */
AM_API am_status am_robot_build(am_model* m, const am_robot* r, char* err, int errsz);

/* what an evaluation scores (am_eval_def.score; docs/evolve.md, Fitness) */
#define AM_SCORE_TRAVEL 0    /* the seed's: the centre of mass's travel over the whole movement */
#define AM_SCORE_SUSTAINED 1 /* sustained locomotion: the travel per cycle after sustained_from cycles */

/* the step the relaxation's step counts refer to, as a fraction of dt_rec: the default dt_frac */
#define AM_REF_DT_FRAC 0.9
/* n steps of the default step as steps of s's step: round(n AM_REF_DT_FRAC dt_rec / dt), at least 1
 * when n > 0 (n itself at the default step) */
AM_API long am_steps_at(const am_model* m, const am_state* s, long n);
/* the actuation period in steps of a step dt (model units) for env's period: period_steps, or
 * period_s / dt rounded, 2 to 10^7 (the range of the key period_steps; am_model_build refuses a
 * period_s outside it at the model's step). The one place a run's period is decided: the model
 * keeps it for its step (env.period_steps), a state for its own (am_state.period_steps) */
AM_API int am_period_steps(const am_model* m, const am_env* env, am_real dt);
/* its rounding: a period of period_s seconds in steps of dt_s seconds, period_s / dt_s rounded to
 * the nearest, 2 to 10^7 (2 below 1.5 steps or for NaN) */
AM_API int am_period_steps_si(double period_s, double dt_s);

/* The score of a body that has none: it diverged, or it did not come to rest before the movement.
 * It is the one meaning of "fitness when diverged" everywhere: am_result.fitness, the evolver's
 * individuals (am_evo_ind), the checkpoint and what amorph sim prints. log.csv's statistics leave
 * such bodies out, and evals.csv's fitness column is empty for a diverged row (its numbers are not
 * results) and AM_NO_SCORE for an unsettled one (docs/evolve.md). An empty body (no voxel) has no
 * model to evaluate: its callers give it fitness 0, a valid robot that goes nowhere. */
#define AM_NO_SCORE (-1.0)

typedef struct am_result {
    double fitness;          /* m: the score (travel, or sustained with AM_SCORE_SUSTAINED);
                              * AM_NO_SCORE when the body diverged or did not settle; travel holds
                              * the displacement measured either way */
    double travel;           /* m: the centre of mass displacement measured as the fitness is (0 when
                              * diverged) */
    double dx, dy, dz;       /* centre of mass displacement in the movement segment, m */
    double sustained;        /* m per cycle: the travel from the end of cycle sustained_from to the
                              * end of the movement, measured as the fitness is, over the cycles
                              * after sustained_from (0 when there are none, or diverged) */
    int voxels, links;
    double dt;               /* s */
    int period_steps;        /* the actuation period, steps */
    long relax_steps, move_steps, steps;
    double relax_dt;         /* s: the relaxation's settling pseudo-step (eval.relax_dt_frac) */
    int relax_retried;       /* 1: the relaxation failed at the pseudo-step (diverged or never came
                              * to rest) and was done again from the start at the run's step */
    int diverged;            /* 1 when the run diverged */
    int settled;             /* 1 when the body came to rest: calm through the release window */
    double residual_speed;   /* m/s: the largest RMS voxel speed over the last release window
                              * (the last RMS speed when relaxation ran out first) */
    long kinetic_resets;     /* kinetic damping's stops during relaxation (docs/physics.md) */
    double sim_seconds;      /* simulated time, s */
    long rebuilds;           /* collision list rebuilds */
    int max_pairs;           /* largest collision candidate list */
    uint64_t hash;           /* am_state_hash at the end */
} am_result;

/* s's simulated time, s: its steps at dt, those of the relaxation's settling at settle_dt */
AM_API double am_sim_time(const am_model* m, const am_state* s);

/* ==== a robot under a controller (amorph/api.h, Stepping, is the caller's interface to these).
 * am_eval_settle is am_evaluate up to its movement (the reset and the relaxation, *out's dt,
 * period and relaxation fields set), am_eval_actuate starts the actuation at the state's step (the
 * movement's phase 0). Between steps a caller may set each voxel's scale (1 + its linear
 * expansion) and the scale's rate in place of the sinusoid's (the desktop profile, a model with a
 * phase per voxel: am_model_build_layers with layers of has_phase); am_actuation_values gives
 * every voxel's own for the state's next step (scale, and rate in 1/s unless NULL), the values
 * am_step computes: set back as the control, the robot moves exactly as without it. */
AM_API void am_eval_settle(const am_model* m, am_state* s, const am_eval_def* def, am_result* out);
AM_API void am_eval_actuate(am_state* s);
AM_API void am_actuation_values(const am_model* m, const am_state* s, double* scale, double* rate);
/* what a controller sees: the state's step and time, its centre of mass and that's velocity */
typedef struct am_obs {
    long step;                /* steps since the reset */
    double time;              /* s (am_sim_time) */
    double com[3];            /* centre of mass, m */
    double com_vel[3];        /* its velocity, m/s */
    int nv;                   /* voxels */
    int contacts;             /* voxels touching the floor */
    int diverged;             /* 1 once the state diverged (it takes no more steps) */
    uint64_t hash;            /* am_state_hash: the same calls give the same hash */
} am_obs;
/* the observation into *out and, each when not NULL, per voxel (the model's order): its centre (3 nv
 * doubles, x y z of voxel 0 first), m; its velocity, m/s; its axial strain (the mean over its links
 * of centre distance over rest length, less 1); its floor contact (0 none, 1 stuck, 2 sliding) */
AM_API void am_observe(const am_model* m, const am_state* s, am_obs* out, double* pos, double* vel, double* strain, int* contact);

/* the whole evaluation of one model; s is overwritten. An evaluation whose bound
 * (am_eval_max_steps of m->env and def) passes the budget AM_EVAL_MAX_STEPS takes no step: *out is
 * a result with no score (diverged 1, fitness AM_NO_SCORE, steps 0); am_eval_check says why, and
 * the callers that take settings from files and flags ask it first */
AM_API void am_evaluate(const am_model* m, am_state* s, const am_eval_def* def, am_result* out);

/* The budget of one evaluation (docs/physics.md, Evaluation): at most 10^9 time steps, whatever
 * the settings. The seed's evaluation takes at most 85,000 (two relaxations of 40,000 and 10
 * cycles of 500); a convergence study at 0.05 dt_rec 1.5 million; the time step search's worst
 * case (nothing stable down to AM_DT_SEARCH_MIN) with the seed's relaxation 7.6 x 10^8. */
#define AM_EVAL_MAX_STEPS 1000000000L
/* the smallest step am_dt_search can return, a fraction of dt_rec: 0.95 of its smallest candidate */
#define AM_DT_SEARCH_MIN 9.5e-5
/* what an evaluation can cost at most, in time steps (am_eval_max_steps' parts) */
typedef struct am_eval_cost {
    double search;           /* the time step search (def->dt_search): 15 candidates of 100 steps */
    double step;             /* the step the counts are scaled to, a fraction of dt_rec (with the
                              * search, its smallest: AM_DT_SEARCH_MIN) */
    int relaxations;         /* 2 when a settling pseudo-step may fail and be done again, else 1 */
    double relax;            /* steps of one relaxation: relax_max_steps scaled to the step */
    double period;           /* steps of one actuation period at the step */
    double move;             /* cycles x period */
    double total;            /* search + relaxations x relax + move */
} am_eval_cost;
/* the most time steps am_evaluate can take with env and def, before any step: period_steps is
 * the period in steps of env's step (env->dt_frac dt_rec), as am_model_build makes env->period_s
 * (pass 10^7, the most, while no model is built and env->period_s > 0); with def->dt_search the
 * searched step is taken at its smallest. Fills *cost when not NULL. */
AM_API double am_eval_max_steps(const am_env* env, const am_eval_def* def, double period_steps, am_eval_cost* cost);
/* AM_OK when am_eval_max_steps is within AM_EVAL_MAX_STEPS; else AM_ERR_RANGE and a message that
 * gives the figures ("up to ... steps an evaluation (...), over the budget of 1e+09"); the caller
 * adds where the settings came from */
AM_API am_status am_eval_check(const am_env* env, const am_eval_def* def, double period_steps, char* err, int errsz);

/* ---- gait diagnostics (docs/results.md, Gaits) ----
 * What the movement segment looked like, cycle by cycle: the centre of mass sampled at the same
 * phase of every actuation cycle (so vibration within a cycle cancels), how much of each cycle
 * the body spent with no voxel on the floor, and how far its centre of mass rose and fell. */
/* AM_GAIT_MAX_CYCLES: a capacity of amorph/base.h */
typedef struct am_gait {
    int cycles;                                /* cycles recorded: the first AM_GAIT_MAX_CYCLES */
    double com[AM_GAIT_MAX_CYCLES + 1][3];     /* m: at the start of the movement, then at the end of each cycle */
    double airborne[AM_GAIT_MAX_CYCLES];       /* fraction of the cycle's steps with no voxel touching the floor */
    double lift[AM_GAIT_MAX_CYCLES];           /* m: highest minus lowest centre-of-mass height within the cycle */
    double turn[AM_GAIT_MAX_CYCLES][3];        /* rad: the body's turn in the cycle as a rotation vector in
                                                * world axes (axis times angle), from its mean orientation */
    double quat[4];                            /* scratch: the body's mean orientation at the last cycle's end */
    double low, high;                          /* scratch: the cycle under way's height range so far */
    long air_steps;                            /* scratch: and its steps off the floor */
} am_gait;

/* the gait told by numbers (thresholds in docs/results.md) */
typedef enum am_gait_mode {
    AM_GAIT_STILL,           /* travels less than AM_GAIT_STILL_FRAC voxel edges per cycle */
    AM_GAIT_FLOP,            /* travel stops: the last half's travel per cycle is below AM_GAIT_FLOP_RATIO of the first half's */
    AM_GAIT_SCOOT,           /* travel goes on, the body on the floor */
    AM_GAIT_BOUNCE,          /* travel goes on, the body off the floor at least AM_GAIT_BOUNCE_AIR of the time */
    AM_GAIT_ROLL             /* travel goes on, and rolling explains at least AM_GAIT_ROLL_SHARE of it
                              * (am_gait_summary.roll) */
} am_gait_mode;
#define AM_GAIT_STILL_FRAC 0.01
#define AM_GAIT_FLOP_RATIO 0.25
#define AM_GAIT_BOUNCE_AIR 0.2
#define AM_GAIT_ROLL_SHARE 0.5
#define AM_GAIT_ROLL_MIN_DEG 10.0 /* and turns at least this far over the last half of the cycles */

typedef struct am_gait_summary {
    int cycles;              /* cycles summarised */
    double travel_total;     /* m: the sum of the per-cycle travels */
    double first_half;       /* m per cycle: mean travel per cycle over the first floor(cycles / 2) cycles */
    double last_half;        /* m per cycle: the same over the last floor(cycles / 2) cycles */
    double sustained;        /* last_half / first_half (0 when the first half did not move) */
    double airborne;         /* fraction of the movement's steps with no voxel on the floor */
    double lift;             /* m: mean over the cycles of the centre of mass's rise and fall */
    double rotation;         /* degrees per cycle: the body's net turn (the sum of the cycles' rotation
                              * vectors: a rocking body turns back, a rolling one adds up) over the cycles */
    double roll_turn;        /* degrees: the net turn over the last floor(cycles / 2) cycles */
    double roll;             /* over the last floor(cycles / 2) cycles, the share of the horizontal
                              * travel that rolling without slipping explains: the net turn (rad) about
                              * the horizontal axis across the travel times the centre of mass's
                              * height, over the travel (negative: turning against it) */
    am_gait_mode mode;
} am_gait_summary;

/* the travel of cycle k (0-based): the distance between the centres of mass at its start and end,
 * measured as the fitness is (AM_FIT_HORIZONTAL: in the floor's plane; AM_FIT_PLUS_X: along +x;
 * AM_FIT_3D: in space) */
AM_API double am_gait_travel(const am_gait* g, int fitness, int k);
/* the summary of g; voxel_size (m) scales the "still" threshold */
AM_API void am_gait_summarize(const am_gait* g, int fitness, double voxel_size, am_gait_summary* out);
/* "still", "flop", "scoot", "bounce", "roll" */
AM_API const char* am_gait_mode_name(am_gait_mode mode);

/* recording helper used by am_evaluate: stores a frame (or hands it to rec->sink) if s->step is a
 * multiple of rec->every */
AM_API void am_record_frame(const am_model* m, const am_state* s, am_record* rec);

#ifdef __cplusplus
}
#endif
#endif
