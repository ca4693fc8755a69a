/* VoxCAD / Voxelyze files: VXA 1.1 with a VXC 0.94 object (include/amorph/io.h, docs/vxa.md).
 *
 * Reading is two steps: the XML reader (src/io/io_xml.c) checks the text and builds a tree in the
 * caller's workspace, then this file walks the few levels VXA has with plain loops over the
 * children of each known element (the depth is fixed by the format, so no recursion is needed).
 * Each level knows its tags from a table; a tag given twice is an error, a tag it does not know is
 * a warning line and is skipped with everything inside it. Where VoxCAD's own reader gives a
 * missing tag a meaning (no <GravEnabled> inside <Gravity> is "off"), this reader does the same;
 * elsewhere a missing tag keeps amorph's default. Sections are read in a fixed order (VXC, then
 * Simulator, Environment, Amorph) whatever their order in the file, because the damping of
 * <Simulator> and the exact values of <Amorph> land on the materials read from <VXC>.
 *
 * A voxcraft VXD over the file (am_vxa_parse_vxd) lives in a second workspace: element ids of the
 * VXD are offset by VXD_BIAS, and the walker of a known element's children (children()) puts each
 * VXD element whose replace="VXA...." names a child in that child's place, or after the children
 * when the base has none, so every reader below reads the merged file without knowing it.
 * Per-cell layers (<PhaseOffset>, <Stiffness>, the boundary conditions' <FRegion> boxes) go into
 * am_vxa_info.layers. Warnings are sorted into line order at the end.
 *
 * Writing follows what VoxCAD writes (tag order, ASCII_READABLE layers in CDATA), then adds the
 * <Amorph> element for the values VXA cannot hold. Reals are printed in the shortest form that
 * reads back to the same bits, so a written file reads back to the same lattice.
 */
#include "amorph/io.h"

#include "amorph/base.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define VXA_VALUE_MAX 256
#define VXA_LAYER_MAX (2L * AM_MAX_DIM * AM_MAX_DIM + 512L) /* decoded text of one <Layer> */
#define VXA_TEMP_BASE 25.0                                 /* the reference temperature written (VoxCAD's default) */

/* a VXD's replacements (voxcraft-sim): each element of the VXD with replace="VXA.A.B" stands for
 * the element at that path of the base file */
#define VXD_MAX_REPLACE 64
#define VXD_PATH_MAX 128

typedef struct vctx {
    const am_xml_doc* d;     /* the base VXA file */
    am_vxa_info* info;
    long wlen; /* bytes of info->warning in use */
    char* err;
    int errsz;
    const am_xml_doc* d2;    /* the VXD file, or NULL */
    int nrep;                /* its replacements */
    int rep_node[VXD_MAX_REPLACE];   /* the VXD element (an id of the VXD: VXD_BIAS + index) */
    char rep_path[VXD_MAX_REPLACE][VXD_PATH_MAX];
    int rep_used[VXD_MAX_REPLACE];
} vctx;

/* Element ids: an element of the base file is its index there, one of the VXD file VXD_BIAS plus
 * its index there (the same for attributes); these helpers read either document. */
#define VXD_BIAS (1 << 20)
static const am_xml_doc* D(const vctx* c, int n) { return n >= VXD_BIAS ? c->d2 : c->d; }
static int IX(int n) { return n >= VXD_BIAS ? n - VXD_BIAS : n; }
static int BIAS(int n) { return n >= VXD_BIAS ? VXD_BIAS : 0; }
static const am_xml_node* N(const vctx* c, int n) { return &D(c, n)->node[IX(n)]; }
static int first_child(const vctx* c, int n) { return N(c, n)->child < 0 ? -1 : N(c, n)->child + BIAS(n); }
static int next_sib(const vctx* c, int k) { return N(c, k)->next < 0 ? -1 : N(c, k)->next + BIAS(k); }
static int is(const vctx* c, int n, const char* name) { return am_xml_is(D(c, n), IX(n), name); }
static int attr_find(const vctx* c, int n, const char* name)
{
    int a = am_xml_attr_find(D(c, n), IX(n), name);
    return a < 0 ? -1 : a + BIAS(n);
}
static am_status attr_text(const vctx* c, int a, char* out, long cap, long* len) { return am_xml_attr_text(D(c, a), IX(a), out, cap, len); }

/* ---- messages ---------------------------------------------------------------------------- */

static am_status verr(const vctx* c, int n, am_status code, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static void warn(vctx* c, int n, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* "fname:line: message", line of element n */
static am_status verr(const vctx* c, int n, am_status code, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    am_vfail_at(c->err, c->errsz, code, D(c, n)->fname, (int)N(c, n)->line, fmt, ap);
    va_end(ap);
    return code;
}

/* element n set the configuration key's value: its line, for messages about the setting */
static void note_key(const vctx* c, int n, const char* key)
{
    for (int i = 0; i < am_evo_key_count() && i < AM_EVO_KEY_MAX; i++)
        if (!strcmp(am_evo_key_name(i), key)) {
            c->info->key_line[i] = (int)N(c, n)->line;
            c->info->key_vxd[i] = (unsigned char)(n >= VXD_BIAS);
        }
}

/* appends "fname:line: warning: message\n" to the info's warning text while it has room */
static void warn(vctx* c, int n, const char* fmt, ...)
{
    char line[320];
    int k = snprintf(line, sizeof line, "%s:%d: warning: ", D(c, n)->fname, (int)N(c, n)->line);
    if (k >= 0 && k < (int)sizeof line) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(line + k, sizeof line - (size_t)k, fmt, ap);
        va_end(ap);
    }
    c->info->warnings++;
    size_t m = strlen(line);
    if (c->wlen + (long)m + 2 <= (long)sizeof c->info->warning) {
        memcpy(c->info->warning + c->wlen, line, m);
        c->wlen += (long)m;
        c->info->warning[c->wlen++] = '\n';
        c->info->warning[c->wlen] = 0;
    }
}

/* the name of element n quoted for a message (am_quote) into q */
static const char* tag(const vctx* c, int n, char q[AM_QUOTE_BUF])
{
    return am_quote(q, AM_QUOTE_BUF, D(c, n)->text + N(c, n)->start + 1, N(c, n)->name_len);
}

/* a value quoted for a message (am_quote) into q */
static const char* val(const char* v, char q[AM_QUOTE_BUF]) { return am_quote(q, AM_QUOTE_BUF, v, -1); }

static int is_blank(char ch);

/* notes an ignored item that changes the physics (info->differ: names, comma separated, each once;
 * "..." when no more fit) */
static void differs(vctx* c, const char* what)
{
    char* d = c->info->differ;
    const size_t cap = sizeof c->info->differ, len = strlen(d), w = strlen(what);
    for (const char* p = d; (p = strstr(p, what)) != NULL; p += w)
        if ((p == d || p[-1] == ' ') && (p[w] == ',' || p[w] == 0)) return;
    if (len >= 3 && !strcmp(d + len - 3, "...")) return;
    if (len + w + 2 + 5 < cap) snprintf(d + len, cap - len, "%s%s", len ? ", " : "", what);
    else snprintf(d + len, cap - len, "%s...", len ? ", " : "");
}

/* tags amorph does not read whose non-zero value changes how the robot moves in the reference
 * simulators (evosoro's water robots, VoxCAD's features, voxcraft's materials), and per-voxel
 * layers and fields it does not read (voxcraft's cilia, volvox's <ForceField>: named when present) */
static const char* const physics_value_tags[] = {"FluidEnvironment", "FluidDampEnabled", "MaxVelLimitEnabled", "BlendingEnabled",
                                                 "VolumeEffectsEnabled", "PoissonKickBackEnabled", "EnforceLatticeEnabled",
                                                 "EquilibriumModeEnabled", "FloorSlope", "Sticky", "Cilia"};
static const char* const physics_layer_tags[] = {"BaseCiliaForce", "ShiftCiliaForce", "ForceField"};

/* element k is a physics tag of those tables that is on */
static void physics_check(vctx* c, int k)
{
    char qn[AM_QUOTE_BUF], v[64];
    for (size_t i = 0; i < sizeof physics_layer_tags / sizeof physics_layer_tags[0]; i++)
        if (is(c, k, physics_layer_tags[i])) differs(c, physics_layer_tags[i]);
    for (size_t i = 0; i < sizeof physics_value_tags / sizeof physics_value_tags[0]; i++) {
        if (!is(c, k, physics_value_tags[i])) continue;
        long len = 0;
        char* end = NULL;
        if (N(c, k)->child >= 0 || am_xml_text(D(c, k), IX(k), v, sizeof v, &len) != AM_OK) continue;
        double x = strtod(v, &end);
        while (end && is_blank(*end)) end++;
        if (end != v && end && !*end && x != 0) differs(c, tag(c, k, qn));
    }
}

/* an element amorph does not read: a warning, and a note when it (or a child: <Features> holds
 * VoxCAD's switches) changes the physics */
static void unsupported(vctx* c, int n)
{
    char qn[AM_QUOTE_BUF];
    warn(c, n, "unsupported tag <%s> ignored", tag(c, n, qn));
    physics_check(c, n);
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) physics_check(c, k);
}

/* ---- values ------------------------------------------------------------------------------ */

static int is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; }

/* the text of element n without leading and trailing blanks; an element with elements inside is
 * not a value */
static am_status text_of(const vctx* c, int n, char* buf, long cap, long* len)
{
    char qn[AM_QUOTE_BUF];
    if (N(c, n)->child >= 0) return verr(c, n, AM_ERR_PARSE, "<%s> must hold a value, not elements", tag(c, n, qn));
    long k = 0;
    if (am_xml_text(D(c, n), IX(n), buf, cap, &k) != AM_OK)
        return verr(c, n, AM_ERR_CAPACITY, "<%s>: its text is longer than %ld bytes", tag(c, n, qn), cap - 1);
    long s = 0;
    while (s < k && is_blank(buf[s])) s++;
    while (k > s && is_blank(buf[k - 1])) k--;
    memmove(buf, buf + s, (size_t)(k - s));
    buf[k - s] = 0;
    if (len) *len = k - s;
    return AM_OK;
}

static am_status double_of(const vctx* c, int n, double* out)
{
    char qn[AM_QUOTE_BUF], qv[AM_QUOTE_BUF];
    char v[VXA_VALUE_MAX];
    am_status st = text_of(c, n, v, sizeof v, NULL);
    if (st != AM_OK) return st;
    char* end = NULL;
    double x = v[0] ? strtod(v, &end) : 0;
    if (!v[0] || *end || !(x - x == 0))
        return verr(c, n, AM_ERR_PARSE, "<%s>: '%s' is not a finite number", tag(c, n, qn), val(v, qv));
    *out = x;
    return AM_OK;
}

/* read as am_param the way the lattice format reads it (strtof in the float build) */
static am_status real_of(const vctx* c, int n, am_param* out)
{
    char qn[AM_QUOTE_BUF], qv[AM_QUOTE_BUF];
    char v[VXA_VALUE_MAX];
    am_status st = text_of(c, n, v, sizeof v, NULL);
    if (st != AM_OK) return st;
    char* end = NULL;
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
    am_param x = v[0] ? strtod(v, &end) : 0;
#else
    am_param x = v[0] ? strtof(v, &end) : 0;
#endif
    if (!v[0] || *end || !am_param_finite(x))
        return verr(c, n, AM_ERR_PARSE, "<%s>: '%s' is not a finite number", tag(c, n, qn), val(v, qv));
    *out = x;
    return AM_OK;
}

/* a real with a range: lo <= x (or lo < x when open) and x <= hi; what says the range ("must be
 * in [0, 1]"), or only its lower bound ("must be 0 or more"), and then a value above hi is "too
 * large" */
static am_status real_in(const vctx* c, int n, am_param* out, double lo, int open, double hi, const char* what)
{
    char qn[AM_QUOTE_BUF];
    am_param x = AM_P(0);
    am_status st = real_of(c, n, &x);
    if (st != AM_OK) return st;
    const int whole = strchr(what, '[') || strchr(what, '(');
    if ((open ? !((double)x > lo) : !((double)x >= lo)) || ((double)x > hi && whole))
        return verr(c, n, AM_ERR_RANGE, "<%s> %.9g %s", tag(c, n, qn), (double)x, what);
    if ((double)x > hi) return verr(c, n, AM_ERR_RANGE, "<%s> %.9g is too large (at most %g)", tag(c, n, qn), (double)x, hi);
    *out = x;
    return AM_OK;
}

static am_status int_of(const vctx* c, int n, long lo, long hi, long* out)
{
    char qn[AM_QUOTE_BUF], qv[AM_QUOTE_BUF];
    char v[VXA_VALUE_MAX];
    am_status st = text_of(c, n, v, sizeof v, NULL);
    if (st != AM_OK) return st;
    char* end = NULL;
    errno = 0;
    long x = v[0] ? strtol(v, &end, 10) : 0;
    if (!v[0] || *end) return verr(c, n, AM_ERR_PARSE, "<%s>: '%s' is not a whole number", tag(c, n, qn), val(v, qv));
    /* the text as written: strtol clamps a number past a long's range */
    if (errno == ERANGE || x < lo || x > hi) return verr(c, n, AM_ERR_RANGE, "<%s> %s is outside %ld..%ld", tag(c, n, qn), val(v, qv), lo, hi);
    *out = x;
    return AM_OK;
}

/* VoxCAD writes booleans as 0 or 1; "true" and "false" are read too */
static am_status bool_of(const vctx* c, int n, int* out)
{
    char qn[AM_QUOTE_BUF], qv[AM_QUOTE_BUF];
    char v[VXA_VALUE_MAX];
    am_status st = text_of(c, n, v, sizeof v, NULL);
    if (st != AM_OK) return st;
    if (!strcmp(v, "1") || !strcmp(v, "true")) *out = 1;
    else if (!strcmp(v, "0") || !strcmp(v, "false")) *out = 0;
    else return verr(c, n, AM_ERR_PARSE, "<%s>: '%s' is not 0 or 1", tag(c, n, qn), val(v, qv));
    return AM_OK;
}

/* ---- the children of one element --------------------------------------------------------- */

enum { MAX_TAGS = 16 };

/* the path of base element n ("VXA.VXC.Structure") into out; empty when longer than cap */
static void path_of(const vctx* c, int n, char* out, size_t cap)
{
    int chain[AM_XML_MAX_DEPTH + 2], depth = 0;
    size_t len = 0;
    for (int k = n; k >= 0 && depth < AM_XML_MAX_DEPTH + 2; k = c->d->node[k].parent) chain[depth++] = k;
    out[0] = 0;
    for (int i = depth - 1; i >= 0; i--) {
        const am_xml_node* e = &c->d->node[chain[i]];
        if (len + e->name_len + 2 > cap) {
            out[0] = 0;
            return;
        }
        if (len) out[len++] = '.';
        memcpy(out + len, c->d->text + e->start + 1, e->name_len);
        len += e->name_len;
        out[len] = 0;
    }
}

/* the unused replacement for the child named like element k (or, k < 0, any unused one) of the
 * element at path; -1 when none */
static int replacement(const vctx* c, const char* path, int k)
{
    const size_t pl = strlen(path);
    for (int r = 0; r < c->nrep; r++) {
        const char* rp = c->rep_path[r];
        if (c->rep_used[r] || strncmp(rp, path, pl) != 0 || rp[pl] != '.' || strchr(rp + pl + 1, '.')) continue;
        if (k < 0 || is(c, k, rp + pl + 1)) return r;
    }
    return -1;
}

/* one child k of element n for children() */
static am_status take(vctx* c, int n, int k, const char* const* tags, int ntags, int at[MAX_TAGS], const char* repeat)
{
    char qn[AM_QUOTE_BUF];
    int i = 0;
    while (i < ntags && !is(c, k, tags[i])) i++;
    if (i < ntags) {
        if (at[i] >= 0)
            return verr(c, k, AM_ERR_PARSE, "<%s> given twice in <%s> (first on line %d)", tags[i], tag(c, n, qn),
                        (int)N(c, at[i])->line);
        at[i] = k;
    } else if (!repeat || !is(c, k, repeat))
        unsupported(c, k);
    return AM_OK;
}

/* walks the children of element n: each one named in tags[] is stored in at[] (index, or -1 when
 * absent; a second one is an error), each other one is a warning unless it is named `repeat`
 * (those are left for the caller to walk). With a VXD, an element of the VXD replacing a child
 * stands in its place, and one replacing an element the base file lacks comes after them. */
static am_status children(vctx* c, int n, const char* const* tags, int ntags, int at[MAX_TAGS], const char* repeat)
{
    char path[VXD_PATH_MAX] = "";
    am_status st;
    const int merge = c->nrep > 0 && n < VXD_BIAS;
    if (merge) path_of(c, n, path, sizeof path);
    for (int i = 0; i < ntags; i++) at[i] = -1;
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) {
        int use = k, r = merge && path[0] ? replacement(c, path, k) : -1;
        if (r >= 0) {
            use = c->rep_node[r];
            c->rep_used[r] = 1;
        }
        if ((st = take(c, n, use, tags, ntags, at, repeat)) != AM_OK) return st;
    }
    for (int r; merge && path[0] && (r = replacement(c, path, -1)) >= 0;) {
        c->rep_used[r] = 1;
        if ((st = take(c, n, c->rep_node[r], tags, ntags, at, repeat)) != AM_OK) return st;
    }
    return AM_OK;
}

/* ---- VXC: lattice, voxel, palette, structure --------------------------------------------- */

static am_status read_lattice(vctx* c, int n, am_lattice* lat)
{
    static const char* const tags[] = {"Lattice_Dim", "X_Dim_Adj", "Y_Dim_Adj", "Z_Dim_Adj",
                                       "X_Line_Offset", "Y_Line_Offset", "X_Layer_Offset", "Y_Layer_Offset"};
    int at[MAX_TAGS];
    am_status st = children(c, n, tags, 8, at, NULL);
    if (st != AM_OK) return st;
    /* the configuration's voxel_size range */
    if (at[0] >= 0 && (st = real_in(c, at[0], &lat->voxel_size, 0, 1, AM_VOXEL_SIZE_MAX, "must be greater than 0")) != AM_OK) return st;
    if (at[0] >= 0 && !(lat->voxel_size >= AM_P(AM_VOXEL_SIZE_MIN)))
        return verr(c, at[0], AM_ERR_RANGE, "<Lattice_Dim> %.9g is too small (at least %g m)", (double)lat->voxel_size, AM_VOXEL_SIZE_MIN);
    for (int i = 1; i < 8; i++) {
        double v, want = i <= 3 ? 1 : 0;
        if (at[i] < 0) continue;
        if ((st = double_of(c, at[i], &v)) != AM_OK) return st;
        if (v != want) {
            warn(c, at[i], "<%s> %.9g not supported (amorph lattices are cubic cells on a rectangular grid); %g used", tags[i], v,
                 want);
            differs(c, tags[i]);
        }
    }
    return AM_OK;
}

static am_status read_voxel(vctx* c, int n)
{
    char qv[AM_QUOTE_BUF];
    static const char* const tags[] = {"Vox_Name", "X_Squeeze", "Y_Squeeze", "Z_Squeeze"};
    int at[MAX_TAGS];
    am_status st = children(c, n, tags, 4, at, NULL);
    if (st != AM_OK) return st;
    if (at[0] >= 0) {
        char v[VXA_VALUE_MAX];
        if ((st = text_of(c, at[0], v, sizeof v, NULL)) != AM_OK) return st;
        if (strcmp(v, "BOX") != 0) {
            warn(c, at[0], "<Vox_Name> %s not supported (amorph voxels are boxes); BOX used", val(v, qv));
            differs(c, "Vox_Name");
        }
    }
    for (int i = 1; i < 4; i++) {
        double v;
        if (at[i] < 0) continue;
        if ((st = double_of(c, at[i], &v)) != AM_OK) return st;
        if (v != 1) {
            warn(c, at[i], "<%s> %.9g not supported; 1 used", tags[i], v);
            differs(c, tags[i]);
        }
    }
    return AM_OK;
}

/* a VXA name (free text) as an amorph material name: letters, digits, '_' and '-' kept, any other
 * byte becomes '_', cut to AM_NAME_MAX - 1 */
static void clean_name(char* dst, const char* src)
{
    size_t i = 0;
    memset(dst, 0, AM_NAME_MAX);
    for (; src[i] && i < AM_NAME_MAX - 1; i++) {
        char ch = src[i];
        int ok = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
        dst[i] = ok ? ch : '_';
    }
}

static am_status read_material(vctx* c, int n, am_material* m, int id)
{
    char qv[AM_QUOTE_BUF];
    static const char* const tags[] = {"MatType", "Name", "Display", "Mechanical"};
    static const char* const disp[] = {"Red", "Green", "Blue", "Alpha"};
    static const char* const mech[] = {"MatModel", "Elastic_Mod", "Plastic_Mod", "Yield_Stress", "FailModel", "Fail_Stress",
                                       "Fail_Strain", "Density", "Poissons_Ratio", "CTE", "MaterialTempPhase", "uStatic",
                                       "uDynamic", "Fixed"};
    int at[MAX_TAGS], dt[MAX_TAGS], mt[MAX_TAGS];
    am_status st;
    long v;
    *m = am_default_material();
    memset(m->name, 0, sizeof m->name);
    snprintf(m->name, sizeof m->name, "material%d", id);
    int a = attr_find(c, n, "ID");
    if (a >= 0) {
        char idv[VXA_VALUE_MAX];
        char* end = NULL;
        if (attr_text(c, a, idv, sizeof idv, NULL) != AM_OK || strtol(idv, &end, 10) != id || !idv[0] || *end)
            warn(c, n, "<Material ID=\"%s\"> is material %d of the palette: materials are numbered by their order, as in VoxCAD",
                 val(idv, qv), id);
    }
    if ((st = children(c, n, tags, 4, at, NULL)) != AM_OK) return st;
    if (at[0] >= 0) {
        static const char* const kinds[] = {"single", "internal structure", "dither", "external file"};
        if ((st = int_of(c, at[0], 0, 1000000, &v)) != AM_OK) return st;
        if (v != 0)
            return verr(c, at[0], AM_ERR_PARSE, "material %d: MatType %ld (%s) is not supported: only single materials (MatType 0)",
                        id, v, v <= 3 ? kinds[v] : "unknown");
    }
    if (at[1] >= 0) {
        char nm[VXA_VALUE_MAX];
        if ((st = text_of(c, at[1], nm, sizeof nm, NULL)) != AM_OK) return st;
        if (nm[0]) clean_name(m->name, nm);
    }
    if (at[2] >= 0) {
        if ((st = children(c, at[2], disp, 4, dt, NULL)) != AM_OK) return st;
        for (int i = 0; i < 4; i++) {
            am_param x = AM_P(0);
            if (dt[i] < 0) continue;
            if ((st = real_in(c, dt[i], &x, 0, 0, 1, "must be in [0, 1]")) != AM_OK) return st;
            m->color[i] = (uint8_t)floor((double)x * 255.0 + 0.5);
        }
    }
    if (at[3] < 0) return AM_OK;
    if ((st = children(c, at[3], mech, 14, mt, NULL)) != AM_OK) return st;
    if (mt[0] >= 0) {
        if ((st = int_of(c, mt[0], 0, 1000000, &v)) != AM_OK) return st;
        if (v != 0) {
            warn(c, mt[0], "<MatModel> %ld (non-linear) not supported: material %d is linear elastic here", v, id);
            differs(c, "MatModel");
        }
    }
    for (int i = 2; i <= 6; i++) { /* parameters of the non-linear models: checked, no effect */
        double x;
        if (mt[i] >= 0 && (st = double_of(c, mt[i], &x)) != AM_OK) return st;
    }
    if (mt[1] >= 0 && (st = real_in(c, mt[1], &m->E, 0, 1, 1e30, "must be greater than 0")) != AM_OK) return st;
    if (mt[7] >= 0 && (st = real_in(c, mt[7], &m->density, 0, 1, 1e30, "must be greater than 0")) != AM_OK) return st;
    if (mt[8] >= 0 && (st = real_in(c, mt[8], &m->poisson, 0, 0, 0.5, "must be in [0, 0.5]")) != AM_OK) return st;
    if (mt[8] >= 0 && !(m->poisson < AM_P(0.5))) {
        /* the incompressible limit, which amorph's model does not take (nor Voxelyze's volume
         * effects): the largest ratio below it, as voxcraft-sim clamps it */
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
        m->poisson = nextafter(0.5, 0.0);
#else
        m->poisson = nextafterf(0.5f, 0.0f);
#endif
        warn(c, mt[8], "<Poissons_Ratio> 0.5 (incompressible) is beyond amorph's model: the largest ratio below 0.5 used for "
                       "material %d", id);
    }
    if (mt[9] >= 0 && (st = real_in(c, mt[9], &m->cte, -1, 0, 1, "must be in [-1, 1] (the key cte's range)")) != AM_OK) return st;
    if (mt[10] >= 0 && (st = real_of(c, mt[10], &m->phase)) != AM_OK) return st;
    if (mt[11] >= 0 && (st = real_in(c, mt[11], &m->mu_static, 0, 0, 100, "must be in [0, 100] (the key mu_static's range)")) != AM_OK)
        return st;
    if (mt[12] >= 0 && (st = real_in(c, mt[12], &m->mu_kinetic, 0, 0, 100, "must be in [0, 100] (the key mu_kinetic's range)")) != AM_OK)
        return st;
    if (mt[13] >= 0 && (st = bool_of(c, mt[13], &m->fixed)) != AM_OK) return st; /* voxcraft-sim's fixed material */
    return AM_OK;
}

static am_status read_palette(vctx* c, int n, am_palette* pal)
{
    am_status st;
    pal->count = 0;
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) {
        if (!is(c, k, "Material")) {
            unsupported(c, k);
            continue;
        }
        if (pal->count >= AM_MAX_MATERIALS)
            return verr(c, k, AM_ERR_CAPACITY, "more than %d materials (the palette's capacity)", AM_MAX_MATERIALS);
        if ((st = read_material(c, k, &pal->mat[pal->count], pal->count + 1)) != AM_OK) return st;
        pal->count++;
    }
    if (pal->count == 0) return verr(c, n, AM_ERR_PARSE, "<Palette> has no <Material>");
    /* names unique, as amorph looks materials up by name */
    for (int i = 1; i < pal->count; i++) {
        char base[AM_NAME_MAX];
        memcpy(base, pal->mat[i].name, sizeof base);
        for (int suffix = 2, clash = 1; clash && suffix < 100; suffix++) {
            clash = 0;
            for (int j = 0; j < i; j++) clash |= strcmp(pal->mat[j].name, pal->mat[i].name) == 0;
            if (clash) {
                char tail[8];
                int tl = snprintf(tail, sizeof tail, "_%d", suffix);
                int bl = (int)strlen(base);
                if (bl + tl > AM_NAME_MAX - 1) bl = AM_NAME_MAX - 1 - tl;
                memset(pal->mat[i].name, 0, sizeof pal->mat[i].name);
                memcpy(pal->mat[i].name, base, (size_t)bl);
                memcpy(pal->mat[i].name + bl, tail, (size_t)tl);
            }
        }
    }
    return AM_OK;
}

static int b64_value(char ch)
{
    if (ch >= 'A' && ch <= 'Z') return ch - 'A';
    if (ch >= 'a' && ch <= 'z') return ch - 'a' + 26;
    if (ch >= '0' && ch <= '9') return ch - '0' + 52;
    if (ch == '+') return 62;
    if (ch == '/') return 63;
    return -1;
}

/* base64 text -> bytes in place (blanks skipped, '=' padding ends it); -1 on a bad character */
static long b64_decode(char* s, long n)
{
    long o = 0;
    unsigned acc = 0;
    int bits = 0;
    for (long i = 0; i < n; i++) {
        if (is_blank(s[i])) continue;
        if (s[i] == '=') break;
        int v = b64_value(s[i]);
        if (v < 0) return -1;
        acc = (acc << 6) | (unsigned)v;
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            s[o++] = (char)((acc >> bits) & 0xFF);
        }
    }
    return o;
}

enum { COMP_ASCII, COMP_BASE64, COMP_ZLIB, COMP_QT_ZLIB };

/* the cells of one compressed layer (base64 already decoded in buf[0..len)): a zlib stream
 * (ZLIB), or Qt's qCompress form, the uncompressed length as 4 big-endian bytes then the stream
 * (QT_ZLIB); *len becomes the cells' count, the cells replace buf's bytes */
static am_status inflate_layer(const vctx* c, int k, int z, int comp, char* buf, long* len, long per)
{
    am_inflate_work w;
    uint8_t cells[AM_MAX_DIM * AM_MAX_DIM];
    char msg[AM_ERR_MAX];
    long skip = 0, want = -1, got = 0;
    if (comp == COMP_QT_ZLIB) {
        if (*len < 4) return verr(c, k, AM_ERR_PARSE, "layer %d: %ld bytes, too short for QT_ZLIB data (a length and a zlib stream)", z, *len);
        const unsigned char* u = (const unsigned char*)buf;
        want = (long)((unsigned long)u[0] << 24 | (unsigned long)u[1] << 16 | (unsigned long)u[2] << 8 | u[3]);
        skip = 4;
    }
    am_status st = am_zlib_inflate((const uint8_t*)buf + skip, *len - skip, cells, per, &got, &w, msg, sizeof msg);
    if (st == AM_ERR_CAPACITY)
        return verr(c, k, AM_ERR_PARSE, "layer %d inflates to more than %ld cells (X_Voxels x Y_Voxels)", z, per);
    if (st != AM_OK) return verr(c, k, AM_ERR_PARSE, "layer %d: %s", z, msg);
    if (want >= 0 && want != got)
        return verr(c, k, AM_ERR_PARSE, "layer %d inflates to %ld bytes, its QT_ZLIB header says %ld", z, got, want);
    memcpy(buf, cells, (size_t)got);
    *len = got;
    return AM_OK;
}

static am_status read_phase(vctx* c, int n, const am_lattice* lat);
static am_status read_stiffness(vctx* c, int n, const am_lattice* lat);

static am_status read_structure(vctx* c, int n, am_lattice* lat)
{
    char qv[AM_QUOTE_BUF];
    static const char* const tags[] = {"X_Voxels", "Y_Voxels", "Z_Voxels", "Data", "PhaseOffset", "Stiffness"};
    int at[MAX_TAGS];
    am_status st;
    int comp = COMP_BASE64; /* VoxCAD's reader: no Compression attribute means BASE64 */
    int a = attr_find(c, n, "Compression");
    if (a >= 0) {
        char v[VXA_VALUE_MAX];
        if (attr_text(c, a, v, sizeof v, NULL) != AM_OK) v[0] = 0;
        if (!strcmp(v, "ASCII_READABLE")) comp = COMP_ASCII;
        else if (!strcmp(v, "BASE64")) comp = COMP_BASE64;
        else if (!strcmp(v, "ZLIB")) comp = COMP_ZLIB;
        else if (!strcmp(v, "QT_ZLIB")) comp = COMP_QT_ZLIB;
        else
            return verr(c, n, AM_ERR_PARSE, "Compression=\"%s\" is not supported (ASCII_READABLE, BASE64, ZLIB or QT_ZLIB)",
                        val(v, qv));
    }
    if ((st = children(c, n, tags, 6, at, NULL)) != AM_OK) return st;
    long dim[3];
    for (int i = 0; i < 3; i++) {
        if (at[i] < 0) return verr(c, n, AM_ERR_PARSE, "<Structure> has no <%s>", tags[i]);
        if ((st = int_of(c, at[i], 1, 1000000000L, &dim[i])) != AM_OK) return st;
        if (dim[i] > AM_MAX_DIM)
            return verr(c, at[i], AM_ERR_CAPACITY, "<%s> %ld exceeds the %s profile's %d cells per side", tags[i], dim[i],
                        AM_PROFILE_NAME, AM_MAX_DIM);
    }
    if (at[3] < 0) return verr(c, n, AM_ERR_PARSE, "<Structure> has no <Data>");
    lat->nx = (int)dim[0];
    lat->ny = (int)dim[1];
    lat->nz = (int)dim[2];
    long per = dim[0] * dim[1];
    int z = 0;
    char buf[VXA_LAYER_MAX];
    for (int k = first_child(c, at[3]); k >= 0; k = next_sib(c, k)) {
        if (!is(c, k, "Layer")) {
            unsupported(c, k);
            continue;
        }
        if (z >= lat->nz) return verr(c, k, AM_ERR_PARSE, "more <Layer> elements than Z_Voxels = %d", lat->nz);
        long len = 0;
        if ((st = text_of(c, k, buf, sizeof buf, &len)) != AM_OK) return st;
        if (comp != COMP_ASCII && (len = b64_decode(buf, len)) < 0)
            return verr(c, k, AM_ERR_PARSE, "layer %d: bad base64 data", z);
        if ((comp == COMP_ZLIB || comp == COMP_QT_ZLIB) && (st = inflate_layer(c, k, z, comp, buf, &len, per)) != AM_OK) return st;
        if (len != per)
            return verr(c, k, AM_ERR_PARSE, "layer %d has %ld cells, expected %ld (X_Voxels x Y_Voxels = %d x %d)", z, len, per,
                        lat->nx, lat->ny);
        for (long i = 0; i < per; i++) {
            int v = comp == COMP_ASCII ? buf[i] - '0' : (unsigned char)buf[i];
            if (v < 0 || v > lat->palette.count) {
                char shown[16];
                unsigned char u = (unsigned char)buf[i];
                if (comp == COMP_ASCII && u > 0x20 && u < 0x7f) snprintf(shown, sizeof shown, "'%c'", buf[i]);
                else snprintf(shown, sizeof shown, "byte %d", u);
                return verr(c, k, AM_ERR_RANGE,
                            "layer %d: cell %ld (x = %ld, y = %ld) is %s, not a material number 0..%d%s", z, i, i % dim[0],
                            i / dim[0], shown, lat->palette.count, comp == COMP_ASCII ? " (written as '0' + number)" : "");
            }
            lat->cell[per * z + i] = (uint8_t)v;
        }
        z++;
    }
    if (z < lat->nz) return verr(c, at[3], AM_ERR_PARSE, "<Data> has %d <Layer> elements, Z_Voxels says %d", z, lat->nz);
    if (at[4] >= 0 && (st = read_phase(c, at[4], lat)) != AM_OK) return st;
    if (at[5] >= 0) return read_stiffness(c, at[5], lat);
    return AM_OK;
}

/* the numbers of a <Layer> of reals (evosoro writes "0.1, 0.25, ... , " in CDATA): read from the
 * element's raw text, CDATA markers skipped, separated by commas and blanks; exactly `per` of them
 * into out, each finite */
static am_status number_layer(const vctx* c, int k, int z, am_param* out, long per, const char* what)
{
    char qv[AM_QUOTE_BUF];
    const am_xml_node* e = N(c, k);
    const char* t = D(c, k)->text;
    long i = e->content, end = e->content_end, count = 0;
    if (e->child >= 0) return verr(c, k, AM_ERR_PARSE, "<Layer> must hold a value, not elements");
    while (i < end) {
        if (!strncmp(t + i, "<![CDATA[", 9)) {
            i += 9;
            continue;
        }
        if (!strncmp(t + i, "]]>", 3)) {
            i += 3;
            continue;
        }
        if (is_blank(t[i]) || t[i] == ',') {
            i++;
            continue;
        }
        char tok[64];
        long n = 0;
        while (i + n < end && !is_blank(t[i + n]) && t[i + n] != ',' && t[i + n] != ']' && t[i + n] != '<' && n < 64) n++;
        if (n == 64) /* no number is that long: one value, not two pieces of it */
            return verr(c, k, AM_ERR_PARSE, "%s layer %d: value %ld is longer than 63 characters", what, z, count);
        memcpy(tok, t + i, (size_t)n);
        tok[n] = 0;
        char* stop = NULL;
        double v = n > 0 ? strtod(tok, &stop) : 0;
        if (n == 0 || *stop || !(v - v == 0))
            return verr(c, k, AM_ERR_PARSE, "%s layer %d: value %ld '%s' is not a finite number", what, z, count, val(tok, qv));
        if (count == per)
            return verr(c, k, AM_ERR_PARSE, "%s layer %d has more than %ld values (X_Voxels x Y_Voxels)", what, z, per);
        out[count++] = (am_param)v;
        i += n;
    }
    if (count != per)
        return verr(c, k, AM_ERR_PARSE, "%s layer %d has %ld values, expected %ld (X_Voxels x Y_Voxels)", what, z, count, per);
    return AM_OK;
}

/* evosoro's <PhaseOffset>: one <Layer> of reals per z, a phase per cell in periods */
static am_status read_phase(vctx* c, int n, const am_lattice* lat)
{
    const long per = (long)lat->nx * lat->ny;
    am_layers* ly = &c->info->layers;
    int z = 0;
    am_status st;
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) {
        if (!is(c, k, "Layer")) {
            unsupported(c, k);
            continue;
        }
        if (z >= lat->nz) return verr(c, k, AM_ERR_PARSE, "more <PhaseOffset> layers than Z_Voxels = %d", lat->nz);
        if ((st = number_layer(c, k, z, ly->phase + per * z, per, "<PhaseOffset>")) != AM_OK) return st;
        z++;
    }
    if (z < lat->nz) return verr(c, n, AM_ERR_PARSE, "<PhaseOffset> has %d <Layer> elements, Z_Voxels says %d", z, lat->nz);
    ly->has_phase = 1;
    return AM_OK;
}

/* evosoro's <Stiffness>: one <Layer> of reals per z, the elastic modulus of each cell's voxel in
 * Pa (the values of empty cells are read as numbers and not used); <MinElasticMod> and
 * <MaxElasticMod>, the bounds evosoro drew them from, are checked to be numbers, no effect */
static am_status read_stiffness(vctx* c, int n, const am_lattice* lat)
{
    const long per = (long)lat->nx * lat->ny;
    am_layers* ly = &c->info->layers;
    int z = 0, layer_at[AM_MAX_DIM];
    am_status st;
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) {
        if (is(c, k, "MinElasticMod") || is(c, k, "MaxElasticMod")) {
            double v;
            if ((st = double_of(c, k, &v)) != AM_OK) return st;
            continue;
        }
        if (!is(c, k, "Layer")) {
            unsupported(c, k);
            continue;
        }
        if (z >= lat->nz) return verr(c, k, AM_ERR_PARSE, "more <Stiffness> layers than Z_Voxels = %d", lat->nz);
        if ((st = number_layer(c, k, z, ly->stiffness + per * z, per, "<Stiffness>")) != AM_OK) return st;
        layer_at[z++] = k;
    }
    if (z < lat->nz) return verr(c, n, AM_ERR_PARSE, "<Stiffness> has %d <Layer> elements, Z_Voxels says %d", z, lat->nz);
    /* a voxel's modulus: the range of <Elastic_Mod> */
    for (z = 0; z < lat->nz; z++)
        for (long i = 0; i < per; i++) {
            const am_param e = ly->stiffness[per * z + i];
            if (lat->cell[per * z + i] && !(e > AM_P(0) && (double)e <= 1e30))
                return verr(c, layer_at[z], AM_ERR_RANGE, "<Stiffness> layer %d: value %ld (x = %ld, y = %ld, a voxel) is %.9g Pa: it must "
                            "be greater than 0 and at most 1e+30", z, i, i % lat->nx, i / lat->nx, (double)e);
        }
    ly->has_stiffness = 1;
    return AM_OK;
}

static am_status read_vxc(vctx* c, int n, am_lattice* lat)
{
    char qv[AM_QUOTE_BUF];
    static const char* const tags[] = {"Lattice", "Voxel", "Palette", "Structure"};
    int at[MAX_TAGS];
    am_status st;
    int a = attr_find(c, n, "Version");
    if (a >= 0) {
        char v[VXA_VALUE_MAX];
        if (attr_text(c, a, v, sizeof v, NULL) != AM_OK) v[0] = 0;
        double ver = atof(v);
        if (ver < 0.925)
            return verr(c, n, AM_ERR_PARSE, "<VXC Version=\"%s\">: only versions 0.93 and 0.94 are read", val(v, qv));
        if (ver > 0.945) warn(c, n, "<VXC Version=\"%s\"> is newer than 0.94: read as 0.94", val(v, qv));
    }
    if ((st = children(c, n, tags, 4, at, NULL)) != AM_OK) return st;
    if (at[0] >= 0 && (st = read_lattice(c, at[0], lat)) != AM_OK) return st;
    if (at[1] >= 0 && (st = read_voxel(c, at[1])) != AM_OK) return st;
    if (at[2] < 0) return verr(c, n, AM_ERR_PARSE, "<VXC> has no <Palette>");
    if ((st = read_palette(c, at[2], &lat->palette)) != AM_OK) return st;
    if (at[3] < 0) return verr(c, n, AM_ERR_PARSE, "<VXC> has no <Structure>");
    return read_structure(c, at[3], lat);
}

/* ---- Simulator and Environment ----------------------------------------------------------- */

/* VoxCAD's StopCondition types (its StopCondition enum; 7 and 8 are evosoro's) */
static const char* const stop_kinds[] = {"none: the run goes on until stopped",
                                         "time steps",
                                         "seconds",
                                         "actuation periods",
                                         "until the total energy is constant within a threshold",
                                         "until the kinetic energy is below a threshold",
                                         "until no voxel moves more than a threshold per step",
                                         "seconds, or sooner when no voxel moves (evosoro)",
                                         "until the pointing error is small (evosoro)"};

/* <StopCondition> (VoxCAD's, in <Simulator>): when the run stops, and evosoro's InitCmTime (the
 * transient before the centre of mass is recorded and the actuation starts). What amorph's
 * evaluation can say (a length in time steps, seconds or periods; a least relaxation) is kept in
 * info for am_vxa_stop_settings; a stop amorph's evaluation has no counterpart for is a warning
 * and is named in the summary line */
static am_status read_stop(vctx* c, int n)
{
    static const char* const tags[] = {"StopConditionType", "StopConditionValue", "InitCmTime", "AfterlifeTime", "MidLifeFreezeTime"};
    int at[MAX_TAGS];
    double v[5] = {0, 0, 0, 0, 0};
    long type = 0; /* VoxCAD's default: SC_NONE */
    am_status st = children(c, n, tags, 5, at, NULL);
    if (st != AM_OK) return st;
    if (at[0] >= 0 && (st = int_of(c, at[0], 0, 1000000, &type)) != AM_OK) return st;
    for (int i = 1; i < 5; i++)
        if (at[i] >= 0 && (st = double_of(c, at[i], &v[i])) != AM_OK) return st;
    for (int i = 1; i < 5; i++)
        if (at[i] >= 0 && !(v[i] >= 0 && v[i] <= 1e30))
            return verr(c, at[i], AM_ERR_RANGE, "<%s> %.9g must be 0 or more", tags[i], v[i]);
    am_vxa_info* info = c->info;
    info->stop_type = (int)type;
    info->stop_value = v[1] + (type == 2 ? v[3] : 0); /* evosoro runs AfterlifeTime beyond a time stop */
    info->init_cm_time = v[2];
    info->stop_file = D(c, n)->fname;
    info->stop_line = (int)N(c, n)->line;
    const int at_type = at[0] >= 0 ? at[0] : n;
    if (type == 7) {
        /* its time bound is kept (as a stop in seconds), not its early stop */
        warn(c, at_type, "<StopConditionType> 7 (%s): amorph runs its %.9g s, without the early stop", stop_kinds[7], v[1]);
        differs(c, "StopConditionType 7's early stop");
        info->stop_type = 2;
    } else if (type == 0 || type >= 4) {
        char what[96];
        warn(c, at_type, "<StopConditionType> %ld (%s) is not simulated: amorph runs whole actuation cycles (%d unless --cycles N "
                         "says how many)", type, type < 9 ? stop_kinds[type] : "unknown", info->eval.cycles);
        snprintf(what, sizeof what, "StopConditionType %ld (cycles = %d run: --cycles N)", type, info->eval.cycles);
        if (type != 0) differs(c, what); /* VoxCAD's default, a run without an end, has no result to differ from */
        info->stop_type = -1;
    }
    if (at[4] >= 0 && v[4] != 0) {
        warn(c, at[4], "<MidLifeFreezeTime> %.9g not supported (evosoro's development is not simulated): ignored", v[4]);
        differs(c, "MidLifeFreezeTime");
    }
    return AM_OK;
}

static am_status read_simulator(vctx* c, int n, am_lattice* lat)
{
    static const char* const tags[] = {"Integration", "Damping", "Collisions", "StopCondition"};
    static const char* const integ[] = {"Integrator", "DtFrac"};
    static const char* const damp[] = {"BondDampingZ", "ColDampingZ", "SlowDampingZ"};
    static const char* const coll[] = {"SelfColEnabled", "ColSystem", "CollisionHorizon"};
    int at[MAX_TAGS], it[MAX_TAGS];
    am_status st;
    long v;
    am_env* env = &c->info->env;
    if ((st = children(c, n, tags, 4, at, NULL)) != AM_OK) return st;
    if (at[3] >= 0 && (st = read_stop(c, at[3])) != AM_OK) return st;
    if (at[0] >= 0) {
        if ((st = children(c, at[0], integ, 2, it, NULL)) != AM_OK) return st;
        if (it[0] >= 0) {
            if ((st = int_of(c, it[0], 0, 1000000, &v)) != AM_OK) return st;
            if (v != 0) warn(c, it[0], "<Integrator> %ld not supported: amorph integrates with semi-implicit Euler", v);
        }
        if (it[1] >= 0) {
            /* a setting of Voxelyze's integrator: amorph's default (0.9 of its dt_rec) keeps a margin
             * of two below where the seed's sphere diverges (docs/physics.md), so a larger fraction
             * keeps the default */
            am_param f = AM_P(0);
            if ((st = real_in(c, it[1], &f, (double)(am_param)1e-6, 0, 10, "must be in [1e-06, 10] (the key dt_frac's range)")) != AM_OK) return st;
            note_key(c, it[1], "dt_frac");
            if (f > env->dt_frac)
                warn(c, it[1], "<DtFrac> %g is above amorph's default step, kept with a margin below its stability limit: %g "
                               "used (amorph sim --dt-frac overrides)", (double)f, (double)env->dt_frac);
            else
                env->dt_frac = f;
        }
    }
    if (at[1] >= 0) {
        if ((st = children(c, at[1], damp, 3, it, NULL)) != AM_OK) return st;
        for (int i = 0; i < 3; i++) {
            am_param z = AM_P(0);
            if (it[i] < 0) continue;
            if ((st = real_in(c, it[i], &z, 0, 0, 1e30, "must be 0 or more")) != AM_OK) return st;
            for (int k = 0; k < lat->palette.count; k++) {
                am_material* m = &lat->palette.mat[k];
                if (i == 0) m->zeta_internal = z;
                else if (i == 1) m->zeta_collision = z;
                else m->zeta_global = z;
            }
        }
    }
    if (at[2] >= 0) {
        if ((st = children(c, at[2], coll, 3, it, NULL)) != AM_OK) return st;
        if (it[0] >= 0 && (st = bool_of(c, it[0], &env->collisions)) != AM_OK) return st;
        for (int i = 1; i < 3; i++) /* how Voxelyze finds collision pairs: checked, no effect here */
            if (it[i] >= 0 && (st = int_of(c, it[i], 0, 1000000000L, &v)) != AM_OK) return st;
    }
    return AM_OK;
}

/* one cell that a region touches (VoxCAD's rule, as Voxelyze applies its boundary conditions):
 * a region that fixes degrees of freedom clamps the cell and prescribes its displacement along
 * each fixed one (m, from its lattice place: the last such region's), a clamped cell takes no
 * force; a region that fixes none adds its force shared among its count voxels. The cell's one
 * slot (am_layers.force) holds the displacement of a clamped cell, the force of a free one */
static void region_cell(am_layers* ly, int cell, int dof, const double force[3], const double disp[3], long count)
{
    if (dof) {
        if (!ly->fixed[cell])
            for (int k = 0; k < 3; k++) ly->force[k][cell] = AM_P(0); /* a force before the clamp: gone */
        ly->fixed[cell] = 1;
        for (int k = 0; k < 3; k++)
            if (dof >> k & 1) ly->force[k][cell] = (am_param)disp[k];
    } else if (!ly->fixed[cell]) {
        for (int k = 0; k < 3; k++) ly->force[k][cell] += (am_param)(force[k] / (double)count);
    }
}

/* how far (relative to the workspace) a cell must reach into a region's box to touch it: faces that
 * only meet, up to rounding, do not count */
#define REGION_TOL 1e-9

/* one <FRegion> (VoxCAD's boundary condition): a box in coordinates relative to the workspace
 * (0..1 along each axis, X_Voxels x Lattice_Dim and so on), its fixed degrees of freedom and its
 * force. Every filled cell that touches the box (VoxCAD's and Voxelyze's rule: the cell, not only
 * its centre, overlaps it) is clamped when the region fixes it, and the region's force is shared
 * equally among them (VoxCAD's meaning: a force on the region). fixed_list: a region of
 * <Fixed_Regions> without DofFixed or Fixed is fixed. */
static am_status read_region(vctx* c, int n, const am_lattice* lat, int fixed_list)
{
    static const char* const tags[] = {"PrimType", "X", "Y", "Z", "dX", "dY", "dZ", "Radius", "R", "G", "B", "alpha",
                                       "DofFixed", "Fixed", "ForceX", "ForceY", "ForceZ", "TorqueX", "TorqueY", "TorqueZ",
                                       "DisplaceX", "DisplaceY", "DisplaceZ", "AngDisplaceX", "AngDisplaceY", "AngDisplaceZ"};
    enum { NT = 26 };
    int at[NT];
    double v[NT];
    am_status st;
    char qn[AM_QUOTE_BUF];
    /* the children() of a long table */
    for (int i = 0; i < NT; i++) at[i] = -1, v[i] = 0;
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) {
        int i = 0;
        while (i < NT && !is(c, k, tags[i])) i++;
        if (i == NT) {
            unsupported(c, k);
            continue;
        }
        if (at[i] >= 0)
            return verr(c, k, AM_ERR_PARSE, "<%s> given twice in <FRegion> (first on line %d)", tag(c, k, qn),
                        (int)N(c, at[i])->line);
        at[i] = k;
        if ((st = double_of(c, k, &v[i])) != AM_OK) return st;
    }
    if (at[0] >= 0 && v[0] != 0) {
        warn(c, n, "<FRegion> of PrimType %.9g not supported (amorph reads box regions, PrimType 0): ignored", v[0]);
        differs(c, "FRegion PrimType");
        return AM_OK;
    }
    int dof = 0;
    if (at[12] >= 0) {
        if (!(v[12] >= 0 && v[12] <= 63 && v[12] == floor(v[12])))
            return verr(c, at[12], AM_ERR_RANGE, "<DofFixed> %.9g is not a set of the six degrees of freedom (0..63)", v[12]);
        dof = (int)v[12];
    } else if (at[13] >= 0) dof = v[13] != 0 ? 63 : 0;
    else if (fixed_list) dof = 63;
    if (dof != 0 && dof != 63) {
        warn(c, at[12], "<DofFixed> %d fixes some degrees of freedom only: amorph clamps all six of the region's voxels", dof);
        differs(c, "DofFixed");
    }
    for (int i = 17; i < NT; i++) {
        if (at[i] < 0 || v[i] == 0) continue;
        if (i >= 20 && i <= 22 && (dof >> (i - 20) & 1)) { /* a prescribed displacement of a fixed degree of freedom */
            if (!(fabs(v[i]) <= AM_MAX_DISPLACE * (double)lat->voxel_size))
                return verr(c, at[i], AM_ERR_RANGE, "<%s> %.9g m is more than %d voxel edges (Lattice_Dim %g m)", tags[i], v[i],
                            AM_MAX_DISPLACE, (double)lat->voxel_size);
            continue;
        }
        if (i >= 20 && i <= 22) { /* VoxCAD moves only the degrees of freedom a region fixes */
            warn(c, at[i], "<%s> %.9g of a free degree of freedom (DofFixed %d): ignored, as VoxCAD ignores it", tags[i], v[i], dof);
            continue;
        }
        warn(c, at[i], "<%s> %.9g not supported (amorph's boundary conditions are clamps, forces and displacements): ignored", tags[i],
             v[i]);
        differs(c, tags[i]);
    }
    for (int i = 14; i < 17; i++)
        if (!(fabs(v[i]) < 1e30)) return verr(c, at[i], AM_ERR_RANGE, "<%s> %.9g is not a finite force", tags[i], v[i]);
    /* the box, corners in either order */
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        double p = v[1 + a], d = v[4 + a];
        if (!(fabs(p) < 1e30) || !(fabs(d) < 1e30))
            return verr(c, n, AM_ERR_RANGE, "<FRegion>: its box must be finite numbers");
        lo[a] = d < 0 ? p + d : p;
        hi[a] = d < 0 ? p : p + d;
    }
    am_layers* ly = &c->info->layers;
    const int nx = lat->nx, ny = lat->ny, nz = lat->nz;
    long count = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int cell = 0; cell < nx * ny * nz; cell++) {
            if (!lat->cell[cell]) continue;
            const int idx[3] = {cell % nx, cell / nx % ny, cell / (nx * ny)}, dim[3] = {nx, ny, nz};
            int touch = 1;
            for (int a = 0; a < 3; a++) /* the cell [i, i + 1] / n overlaps [lo, hi] */
                touch &= (double)(idx[a] + 1) / dim[a] > lo[a] + REGION_TOL && (double)idx[a] / dim[a] < hi[a] - REGION_TOL;
            if (!touch) continue;
            if (pass == 0) {
                count++;
                continue;
            }
            region_cell(ly, cell, dof, v + 14, v + 20, count);
        }
    if (count == 0) warn(c, n, "<FRegion> holds no voxel (no filled cell touches its box): no effect");
    ly->has_bc = 1;
    return AM_OK;
}

/* <Boundary_Conditions>, <Fixed_Regions>, <Forced_Regions>: a count, then the regions */
static am_status read_regions(vctx* c, int n, const char* count_tag, const am_lattice* lat, int fixed_list)
{
    const char* const tags[] = {count_tag};
    int at[MAX_TAGS];
    long v;
    am_status st = children(c, n, tags, 1, at, "FRegion");
    if (st != AM_OK) return st;
    if (at[0] >= 0 && (st = int_of(c, at[0], 0, 1000000000L, &v)) != AM_OK) return st;
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k))
        if (is(c, k, "FRegion") && (st = read_region(c, k, lat, fixed_list)) != AM_OK) return st;
    return AM_OK;
}

static am_status read_environment(vctx* c, int n, const am_lattice* lat)
{
    static const char* const tags[] = {"Boundary_Conditions", "Fixed_Regions", "Forced_Regions", "Gravity", "Thermal"};
    static const char* const grav[] = {"GravEnabled", "GravAcc", "FloorEnabled"};
    static const char* const therm[] = {"TempEnabled", "TempAmplitude", "TempAmp", "TempBase", "VaryTempEnabled", "TempPeriod"};
    int at[MAX_TAGS], it[MAX_TAGS];
    am_status st;
    am_env* env = &c->info->env;
    if ((st = children(c, n, tags, 5, at, NULL)) != AM_OK) return st;
    if (at[0] >= 0 && (st = read_regions(c, at[0], "NumBCs", lat, 0)) != AM_OK) return st;
    if (at[1] >= 0 && (st = read_regions(c, at[1], "NumFixed", lat, 1)) != AM_OK) return st;
    if (at[2] >= 0 && (st = read_regions(c, at[2], "NumForced", lat, 0)) != AM_OK) return st;
    if (at[3] >= 0) {
        /* VoxCAD's reader: inside <Gravity> a missing switch is off, a missing GravAcc -9.81 */
        int on = 0;
        double acc = -9.81;
        if ((st = children(c, at[3], grav, 3, it, NULL)) != AM_OK) return st;
        if (it[0] >= 0 && (st = bool_of(c, it[0], &on)) != AM_OK) return st;
        if (it[1] >= 0 && (st = double_of(c, it[1], &acc)) != AM_OK) return st;
        env->floor = 0;
        if (it[2] >= 0 && (st = bool_of(c, it[2], &env->floor)) != AM_OK) return st;
        if (on && acc > 0)
            return verr(c, it[1], AM_ERR_RANGE, "<GravAcc> %.9g points up: amorph's gravity pulls along -z (GravAcc <= 0)", acc);
        if (on && !(acc >= -1000))
            return verr(c, it[1], AM_ERR_RANGE, "<GravAcc> %.9g: gravity is at most 1000 m/s^2 (the key gravity's range)", acc);
        env->gravity = on ? (am_param)-acc : AM_P(0);
    }
    if (at[4] >= 0) {
        /* VoxCAD's reader: missing switches are off, TempBase 25, TempPeriod 0.1 s; an old file's
         * TempAmp is the peak temperature, so its amplitude is TempAmp - TempBase */
        int enabled = 0, vary = 0;
        double amp = 0, amp_old = 0, base = 25, period = 0.1;
        if ((st = children(c, at[4], therm, 6, it, NULL)) != AM_OK) return st;
        if (it[0] >= 0 && (st = bool_of(c, it[0], &enabled)) != AM_OK) return st;
        if (it[1] >= 0 && (st = double_of(c, it[1], &amp)) != AM_OK) return st;
        if (it[2] >= 0 && (st = double_of(c, it[2], &amp_old)) != AM_OK) return st;
        if (it[3] >= 0 && (st = double_of(c, it[3], &base)) != AM_OK) return st;
        if (it[4] >= 0 && (st = bool_of(c, it[4], &vary)) != AM_OK) return st;
        if (it[5] >= 0 && (st = double_of(c, it[5], &period)) != AM_OK) return st;
        if (it[1] < 0 && it[2] >= 0) amp = amp_old - base;
        /* the key amplitude's bound (a negative amplitude is VoxCAD's, half a period later) */
        if (!(fabs(amp) <= 1e4))
            return verr(c, at[4], AM_ERR_RANGE, "<Thermal>: the temperature amplitude %.9g is too large (at most 10000, the key amplitude's)", amp);
        env->temp_base = AM_P(0);
        env->temp_amplitude = AM_P(0);
        if (enabled && vary) {
            if (!(period > 0))
                return verr(c, it[5] >= 0 ? it[5] : at[4], AM_ERR_RANGE, "<TempPeriod> %.9g must be greater than 0", period);
            /* the configuration's range (period_s, s) */
            if (period > 1e4)
                return verr(c, it[5] >= 0 ? it[5] : at[4], AM_ERR_RANGE, "<TempPeriod> %.9g is too large (at most 10000 s)", period);
            env->temp_amplitude = (am_param)amp;
            c->info->temp_period = period;
            note_key(c, it[5] >= 0 ? it[5] : at[4], "period_s");
        } else if (enabled) {
            env->temp_base = (am_param)amp; /* a constant temperature TempBase + TempAmplitude */
        }
    }
    return AM_OK;
}

/* ---- Amorph: the exact values VXA has no place for ---------------------------------------- */

/* <Evaluation> in <Amorph>: how the robot is evaluated, one element per evaluation key of the
 * configuration (<cycles>10</cycles>, ...), each read by the configuration's own rule and range */
static am_status read_evaluation(vctx* c, int n)
{
    const char* tags[MAX_TAGS];
    int at[MAX_TAGS], nt = 0;
    for (int i = 0; i < am_evo_key_count() && nt < MAX_TAGS; i++)
        if (am_evo_key_group(am_evo_key_name(i)) == AM_KEYS_EVAL) tags[nt++] = am_evo_key_name(i);
    am_status st = children(c, n, tags, nt, at, NULL);
    if (st != AM_OK) return st;
    am_evo_def d = am_default_evo();
    d.eval = c->info->eval;
    for (int i = 0; i < nt; i++) {
        if (at[i] < 0) continue;
        char v[VXA_VALUE_MAX], why[AM_ERR_MAX];
        unsigned mat = 0;
        if ((st = text_of(c, at[i], v, sizeof v, NULL)) != AM_OK) return st;
        if (am_evo_set_over(&d, tags[i], v, &mat, why, sizeof why) != AM_OK)
            return verr(c, at[i], AM_ERR_RANGE, "<%s> in <Evaluation>: %s", tags[i], why);
        note_key(c, at[i], tags[i]);
    }
    c->info->eval = d.eval;
    return AM_OK;
}

static am_status read_amorph(vctx* c, int n, am_lattice* lat)
{
    char qv[AM_QUOTE_BUF];
    static const char* const tags[] = {"CTEMode", "PeriodSteps", "TempOffset", "Lift", "ZetaInternalScale", "ZetaGlobalScale",
                                       "DtFrac", "Evaluation"};
    static const char* const mtags[] = {"CTE", "ZetaInternal", "ZetaGlobal", "ZetaCollision", "Fixed"};
    int at[MAX_TAGS], mt[MAX_TAGS];
    int cte_given[AM_MAX_MATERIALS] = {0};
    am_status st;
    long v;
    am_env* env = &c->info->env;
    int a = attr_find(c, n, "Version");
    char ver[VXA_VALUE_MAX] = "";
    if (a >= 0 && attr_text(c, a, ver, sizeof ver, NULL) != AM_OK) ver[0] = 0;
    if (strcmp(ver, "1") != 0)
        return verr(c, n, AM_ERR_PARSE, "<Amorph Version=\"%s\">: this build reads version 1", val(ver, qv));
    if ((st = children(c, n, tags, 8, at, "Material")) != AM_OK) return st;
    if (at[7] >= 0 && (st = read_evaluation(c, at[7])) != AM_OK) return st;
    if (at[0] >= 0) {
        char m[VXA_VALUE_MAX];
        if ((st = text_of(c, at[0], m, sizeof m, NULL)) != AM_OK) return st;
        if (!strcmp(m, "volumetric")) env->cte_mode = AM_CTE_VOLUMETRIC;
        else if (!strcmp(m, "linear")) env->cte_mode = AM_CTE_LINEAR;
        else return verr(c, at[0], AM_ERR_PARSE, "<CTEMode>: '%s' is not volumetric or linear", val(m, qv));
    }
    if (at[1] >= 0) {
        /* the configuration's range (period_steps) */
        if ((st = int_of(c, at[1], 2, 10000000L, &v)) != AM_OK) return st;
        env->period_steps = (int)v;
        c->info->period_steps_given = 1;
        note_key(c, at[1], "period_steps");
    }
    if (at[2] >= 0 && (st = real_in(c, at[2], &env->temp_base, -1e4, 0, 1e4, "must be in [-10000, 10000] (the key temp_base's range)")) != AM_OK)
        return st;
    if (at[3] >= 0 && (st = real_in(c, at[3], &env->lift, 0, 0, 1e30, "must be 0 or more")) != AM_OK) return st;
    if (at[4] >= 0 && (st = real_in(c, at[4], &env->zeta_internal_scale, 0, 0, 1000, "must be in [0, 1000] (the key damping_internal's range)")) != AM_OK)
        return st;
    if (at[5] >= 0 && (st = real_in(c, at[5], &env->zeta_global_scale, 0, 0, 1000, "must be in [0, 1000] (the key damping_global's range)")) != AM_OK)
        return st;
    if (at[6] >= 0 && (st = real_in(c, at[6], &env->dt_frac, (double)(am_param)1e-6, 0, 10, "must be in [1e-06, 10] (the key dt_frac's range)")) != AM_OK)
        return st;
    if (at[6] >= 0) note_key(c, at[6], "dt_frac");
    for (int k = first_child(c, n); k >= 0; k = next_sib(c, k)) {
        if (!is(c, k, "Material")) continue;
        char idv[VXA_VALUE_MAX] = "";
        int ia = attr_find(c, k, "ID");
        if (ia >= 0 && attr_text(c, ia, idv, sizeof idv, NULL) != AM_OK) idv[0] = 0;
        char* end = NULL;
        long id = idv[0] ? strtol(idv, &end, 10) : 0;
        if (!idv[0] || *end || id < 1 || id > lat->palette.count)
            return verr(c, k, AM_ERR_PARSE, "<Material ID=\"%s\"> in <Amorph>: the ID must be a material number 1..%d",
                        val(idv, qv), lat->palette.count);
        am_material* m = &lat->palette.mat[id - 1];
        if ((st = children(c, k, mtags, 5, mt, NULL)) != AM_OK) return st;
        if (mt[0] >= 0 && (st = real_in(c, mt[0], &m->cte, -1, 0, 1, "must be in [-1, 1] (the key cte's range)")) != AM_OK) return st;
        cte_given[id - 1] |= mt[0] >= 0;
        if (mt[1] >= 0 && (st = real_in(c, mt[1], &m->zeta_internal, 0, 0, 1e30, "must be 0 or more")) != AM_OK) return st;
        if (mt[2] >= 0 && (st = real_in(c, mt[2], &m->zeta_global, 0, 0, 1e30, "must be 0 or more")) != AM_OK) return st;
        if (mt[3] >= 0 && (st = real_in(c, mt[3], &m->zeta_collision, 0, 0, 1e30, "must be 0 or more")) != AM_OK) return st;
        if (mt[4] >= 0 && (st = bool_of(c, mt[4], &m->fixed)) != AM_OK) return st;
    }
    /* a volumetric CTE not given exactly: three times the linear one (the same small strains) */
    if (env->cte_mode == AM_CTE_VOLUMETRIC)
        for (int k = 0; k < lat->palette.count; k++)
            if (!cte_given[k]) lat->palette.mat[k].cte = AM_P(3) * lat->palette.mat[k].cte;
    return AM_OK;
}

/* ---- where the body starts and how long it runs (VoxCAD's, unless <Amorph> says) ---------- */

/* after the sections: a file amorph wrote (its <Amorph> element, amorph_node >= 0, holds the
 * evaluation and the lift) keeps amorph's rules; any other file's body starts where the file puts
 * it, as VoxCAD and Voxelyze place it (a voxel's centre at (k + 1/2) Lattice_Dim along each axis,
 * the floor at z = 0): its lowest filled layer kmin lies kmin layers above the floor, and a body
 * clamped or hanging there stays or falls from there (env.lift = kmin Lattice_Dim; amorph's own
 * lattices are lowered onto the floor) */
static void stop_and_place(vctx* c, int amorph_node, const am_lattice* lat)
{
    am_vxa_info* info = c->info;
    int own_eval = 0, own_lift = 0;
    for (int k = amorph_node >= 0 ? first_child(c, amorph_node) : -1; k >= 0; k = next_sib(c, k)) {
        own_eval |= is(c, k, "Evaluation");
        own_lift |= is(c, k, "Lift");
    }
    if (own_eval && (info->stop_type >= 0 || info->init_cm_time > 0)) {
        char q[AM_QUOTE_BUF];
        warn(c, amorph_node, "<%s>'s <Evaluation> says how the robot is evaluated: <StopCondition> (line %d) not used", tag(c, amorph_node, q),
             info->stop_line);
        info->stop_type = -1;
        info->init_cm_time = 0;
    }
    if (own_lift) return;
    const long per = (long)lat->nx * lat->ny;
    int kmin = 0;
    while (kmin < lat->nz) {
        long i = 0;
        while (i < per && !lat->cell[per * kmin + i]) i++;
        if (i < per) break;
        kmin++;
    }
    if (kmin > 0 && kmin < lat->nz) info->env.lift = (am_param)(kmin * (double)lat->voxel_size);
}

/* how many of a period's steps (period, s) a span t (s) is: the stop's cycles, and the text that says so */
am_status am_vxa_stop_settings(const am_vxa_info* info, double dt, double dt_ref, int period_steps, unsigned keep, am_eval_def* eval,
                               char* note, int notesz, char* err, int errsz)
{
    if (note && notesz > 0) note[0] = 0;
    if (!info || !eval || !(dt > 0) || !(dt_ref > 0) || period_steps < 1) return am_fail(err, errsz, AM_ERR_ARG, "vxa: no info, step or period");
    am_evo_def d = am_default_evo();
    d.eval = *eval;
    char v[64], why[AM_ERR_MAX], part[320];
    size_t len = 0;
    unsigned mat = 0;
    const double period = period_steps * dt, init = info->init_cm_time;
    const char* f = info->stop_file ? info->stop_file : "";
    /* (a stop in periods of a temperature that does not vary: VoxCAD runs on without end) */
    if (info->stop_type >= 1 && info->stop_type <= 3 && !(info->stop_type == 3 && !(info->temp_period > 0)) && !(keep & AM_VXA_KEEP_CYCLES)) {
        /* the movement: the run's length less the transient before the centre of mass is recorded */
        const double total = info->stop_type == 1 ? info->stop_value * dt : info->stop_type == 2 ? info->stop_value : info->stop_value * info->temp_period;
        const double x = total > init ? (total - init) / period : 0;
        snprintf(v, sizeof v, "%.0f", x < 1e15 ? floor(x + 0.5) : x);
        if (am_evo_set_over(&d, "cycles", v, &mat, why, sizeof why) != AM_OK)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s:%d: <StopCondition> %.9g %s%s is %.4g actuation periods of %.4g s: %s", f, info->stop_line,
                           info->stop_value, stop_kinds[info->stop_type], init > 0 ? " less <InitCmTime>" : "", x, period, why);
        if (info->stop_type == 1)
            snprintf(part, sizeof part, "cycles = %d (<StopCondition> %.9g time steps of amorph's %.4g s", d.eval.cycles, info->stop_value, dt);
        else if (info->stop_type == 2)
            snprintf(part, sizeof part, "cycles = %d (<StopCondition> %.9g s", d.eval.cycles, info->stop_value);
        else
            snprintf(part, sizeof part, "cycles = %d (<StopCondition> %.9g periods of <TempPeriod> %.9g s", d.eval.cycles, info->stop_value,
                     info->temp_period);
        len = strlen(part);
        if (init > 0) len += (size_t)snprintf(part + len, sizeof part - len, " less <InitCmTime> %.9g s", init);
        len += (size_t)snprintf(part + len, sizeof part - len, ": %.6g periods of %.4g s%s)", x, period,
                                fabs(x - d.eval.cycles) > 0.01 ? ", amorph runs whole ones" : "");
        if (note && notesz > 0) snprintf(note, (size_t)notesz, "%s", part);
    }
    if (init > 0 && !(keep & AM_VXA_KEEP_RELAX)) {
        /* the relaxation (amorph's transient) lasts at least InitCmTime, with its usual room after */
        const double steps = ceil(init / dt_ref - 1e-9);
        snprintf(v, sizeof v, "%.0f", steps);
        am_status st = am_evo_set_over(&d, "relax_min_steps", v, &mat, why, sizeof why);
        if (st == AM_OK) {
            snprintf(v, sizeof v, "%.0f", steps + (double)d.eval.relax_max_steps);
            st = am_evo_set_over(&d, "relax_max_steps", v, &mat, why, sizeof why);
        }
        if (st != AM_OK)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s:%d: <InitCmTime> %.9g s is %.4g steps of %.4g s: %s", f, info->stop_line, init,
                           steps, dt_ref, why);
        if (note && notesz > 0) {
            const size_t have = strlen(note);
            snprintf(note + have, (size_t)notesz - have, "%srelax_min_steps = %ld and relax_max_steps = %ld (<InitCmTime> %.9g s: the "
                     "relaxation lasts at least that long before the centre of mass is recorded)", have ? ", " : "", d.eval.relax_min_steps,
                     d.eval.relax_max_steps, init);
        }
    }
    *eval = d.eval;
    return AM_OK;
}

/* ---- reading ----------------------------------------------------------------------------- */

/* the warning lines in line order (the sections are read in a fixed order, not the file's): a
 * stable sort on (file, line), the base file's lines before a VXD's (names[0], names[1]) */
static void sort_warnings(am_vxa_info* info, const char* const names[2])
{
    enum { MAXL = AM_VXA_WARN_TEXT / 16 };
    char copy[AM_VXA_WARN_TEXT];
    long start[MAXL], line_of[MAXL];
    int file_of[MAXL];
    int n = 0;
    size_t total = strlen(info->warning);
    memcpy(copy, info->warning, total + 1);
    for (size_t p = 0; p < total && n < MAXL;) {
        const char* e = strchr(copy + p, '\n');
        size_t len = e ? (size_t)(e - (copy + p)) + 1 : total - p;
        const size_t l1 = names[1] ? strlen(names[1]) : 0;
        int f = names[1] && !strncmp(copy + p, names[1], l1) && copy[p + l1] == ':' ? 1 : 0;
        const char* colon = copy + p + strlen(names[f]);
        long line = *colon == ':' ? strtol(colon + 1, NULL, 10) : 0;
        start[n] = (long)p;
        file_of[n] = f;
        line_of[n++] = line;
        p += len;
    }
    long w = 0;
    for (int done = 0; done < n; done++) {
        int best = -1;
        for (int i = 0; i < n; i++)
            if (start[i] >= 0 && (best < 0 || file_of[i] < file_of[best] || (file_of[i] == file_of[best] && line_of[i] < line_of[best])))
                best = i;
        const char* l = copy + start[best];
        const char* e = strchr(l, '\n');
        size_t len = e ? (size_t)(e - l) + 1 : strlen(l);
        memcpy(info->warning + w, l, len);
        w += (long)len;
        start[best] = -1;
    }
    info->warning[w] = 0;
}

int am_vxa_sniff(const char* text)
{
    if (!text) return 0;
    const char* p = text;
    if ((unsigned char)p[0] == 0xEF && (unsigned char)p[1] == 0xBB && (unsigned char)p[2] == 0xBF) p += 3;
    while (is_blank(*p)) p++;
    return *p == '<';
}

am_status am_vxa_parse(am_lattice* lat, am_vxa_info* info, am_xml_doc* work, const char* text, const char* fname, char* err,
                       int errsz)
{
    return am_vxa_parse_vxd(lat, info, work, text, fname, NULL, NULL, NULL, err, errsz);
}

/* the VXD's elements: each with replace="VXA...." becomes a replacement */
static am_status read_vxd(vctx* c)
{
    char qv[AM_QUOTE_BUF], qn[AM_QUOTE_BUF];
    const int root = VXD_BIAS;
    if (!is(c, root, "VXD"))
        return verr(c, root, AM_ERR_PARSE, "not a VXD file: the root element is <%s>, expected <VXD>", tag(c, root, qv));
    for (int k = first_child(c, root); k >= 0; k = next_sib(c, k)) {
        char p[VXD_PATH_MAX + 1];
        int a = attr_find(c, k, "replace");
        if (a < 0) {
            warn(c, k, "unsupported tag <%s> ignored (amorph reads the elements of a VXD that replace=\"VXA...\" a part of the base)",
                 tag(c, k, qn));
            continue;
        }
        long len = 0;
        if (attr_text(c, a, p, sizeof p, &len) != AM_OK) {
            /* too long to decode here: its first bytes as written, for the message */
            const am_xml_doc* d = D(c, a);
            long v = d->attr[IX(a)].value, ve = d->attr[IX(a)].value_end;
            len = ve - v < VXD_PATH_MAX ? ve - v : VXD_PATH_MAX;
            memcpy(p, d->text + v, (size_t)len);
            p[len] = 0;
            len = VXD_PATH_MAX;
        }
        if (len >= VXD_PATH_MAX || strncmp(p, "VXA.", 4) != 0 || strchr(p, ' ')) {
            warn(c, k, "<%s replace=\"%s\">: not a path of a VXA file (VXA.A.B, under %d bytes): ignored", tag(c, k, qn), val(p, qv),
                 VXD_PATH_MAX);
            continue;
        }
        for (int r = 0; r < c->nrep; r++)
            if (!strcmp(c->rep_path[r], p))
                return verr(c, k, AM_ERR_PARSE, "replace=\"%s\" given twice (first on line %d)", val(p, qv), (int)N(c, c->rep_node[r])->line);
        if (c->nrep == VXD_MAX_REPLACE)
            return verr(c, k, AM_ERR_CAPACITY, "more than %d replaced elements in a VXD", VXD_MAX_REPLACE);
        c->rep_node[c->nrep] = k;
        memcpy(c->rep_path[c->nrep], p, (size_t)len + 1);
        c->rep_used[c->nrep++] = 0;
    }
    return AM_OK;
}

am_status am_vxa_robot(am_robot* r, const am_vxa_info* info, char* err, int errsz)
{
    const am_layers* ly = &info->layers;
    if (!r->layers && (ly->has_phase || ly->has_stiffness || ly->has_bc))
        return am_fail(err, errsz, AM_ERR_CAPACITY, "the robot has no room for the file's per-cell layers");
    r->env = info->env;
    if (!info->period_steps_given && info->temp_period > 0) r->env.period_s = AM_PARAM_FROM_DOUBLE(info->temp_period);
    r->eval = info->eval;
    if (r->layers) *r->layers = *ly;
    return AM_OK;
}

am_status am_vxa_parse_vxd(am_lattice* lat, am_vxa_info* info, am_xml_doc* work, const char* text, const char* fname,
                           am_xml_doc* vxd_work, const char* vxd_text, const char* vxd_fname, char* err, int errsz)
{
    char qv[AM_QUOTE_BUF], qn[AM_QUOTE_BUF];
    if (!lat || !info || !work || !text || (vxd_text && !vxd_work))
        return am_fail(err, errsz, AM_ERR_ARG, "vxa: no lattice, info, workspace or text");
    memset(lat, 0, sizeof *lat);
    memset(info, 0, sizeof *info);
    lat->voxel_size = AM_P(0.001); /* VoxCAD's default Lattice_Dim */
    info->env = am_default_env();
    info->eval = am_default_eval();
    info->env.cte_mode = AM_CTE_LINEAR; /* VXA's CTE is linear */
    info->env.temp_amplitude = AM_P(0); /* no <Thermal>: no actuation, as in VoxCAD */
    info->stop_type = -1;               /* no <StopCondition> */
    am_status st = am_xml_parse(work, text, (long)strlen(text), fname, err, errsz);
    if (st != AM_OK) return st;
    vctx c;
    memset(&c, 0, sizeof c);
    c.d = work, c.info = info, c.err = err, c.errsz = errsz;
    if (am_xml_is(work, 0, "VXD"))
        return verr(&c, 0, AM_ERR_PARSE, "a VXD file (voxcraft-sim's robot: elements that replace parts of a base VXA file) is not "
                                          "read alone: give its base VXA file first, then the VXD (amorph sim BASE.vxa ROBOT.vxd, or a "
                                          "folder holding base.vxa and one .vxd)");
    if (!am_xml_is(work, 0, "VXA"))
        return verr(&c, 0, AM_ERR_PARSE, "not a VXA file: the root element is <%s>, expected <VXA>", tag(&c, 0, qv));
    if (vxd_text) {
        if ((st = am_xml_parse(vxd_work, vxd_text, (long)strlen(vxd_text), vxd_fname, err, errsz)) != AM_OK) return st;
        c.d2 = vxd_work;
        if ((st = read_vxd(&c)) != AM_OK) return st;
    }
    int a = am_xml_attr_find(work, 0, "Version");
    if (a >= 0) {
        char v[VXA_VALUE_MAX];
        if (am_xml_attr_text(work, a, v, sizeof v, NULL) != AM_OK) v[0] = 0;
        if (strcmp(v, "1.0") != 0 && strcmp(v, "1.1") != 0)
            warn(&c, 0, "<VXA Version=\"%s\">: this reader knows versions 1.0 and 1.1", val(v, qv));
    }
    static const char* const tags[] = {"VXC", "Simulator", "Environment", "Amorph"};
    int at[MAX_TAGS];
    if ((st = children(&c, 0, tags, 4, at, NULL)) != AM_OK) return st;
    if (at[0] < 0) return verr(&c, 0, AM_ERR_PARSE, "<VXA> has no <VXC> element (the robot)");
    if ((st = read_vxc(&c, at[0], lat)) != AM_OK) return st;
    if (at[1] >= 0 && (st = read_simulator(&c, at[1], lat)) != AM_OK) return st;
    if (at[2] >= 0 && (st = read_environment(&c, at[2], lat)) != AM_OK) return st;
    if (at[3] >= 0 && (st = read_amorph(&c, at[3], lat)) != AM_OK) return st;
    stop_and_place(&c, at[3], lat);
    for (int r = 0; r < c.nrep; r++)
        if (!c.rep_used[r])
            warn(&c, c.rep_node[r], "<%s replace=\"%s\">: amorph reads no element at that path: ignored", tag(&c, c.rep_node[r], qn),
                 val(c.rep_path[r], qv));
    const char* const names[2] = {fname ? fname : "", vxd_text ? (vxd_fname ? vxd_fname : "") : NULL};
    sort_warnings(info, names);
    return AM_OK;
}

int am_vxa_period_steps(double period_s, double dt)
{
    return dt > 0 ? am_period_steps_si(period_s, dt) : 2; /* the simulator's rounding (am_period_steps) */
}

/* ---- writing ----------------------------------------------------------------------------- */

/* the bounded text buffer of amorph/base.h */
typedef am_text wbuf;
#define put am_text_put

/* the shortest "%.Ng" that reads back (as am_param when real, else as double) to the same value,
 * preferring a form without an exponent (1000000 rather than 1e+06, but 1e-30 as is) */
static const char* num(char out[40], double v, int real)
{
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
    const int max = 17;
    (void)real; /* am_param is double: one kind of number */
#else
    const int max = real ? 9 : 17;
#endif
    int first = 0;
    for (int digits = 1; digits <= max; digits++) {
        snprintf(out, 40, "%.*g", digits, v);
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
        int same = strtod(out, NULL) == v;
#else
        int same = real ? strtof(out, NULL) == (am_param)v : strtod(out, NULL) == v;
#endif
        if (!same) continue;
        if (!strchr(out, 'e')) return out;
        if (!first) first = digits;
    }
    int digits = first >= 1 && first <= 17 ? first : 17;
    snprintf(out, 40, "%.*g", digits, v);
    return out;
}

static int name_ok(const char* s)
{
    const char* nul = memchr(s, 0, AM_NAME_MAX);
    if (!nul || nul == s) return 0;
    for (; s < nul; s++) {
        char ch = *s;
        if (!((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-'))
            return 0;
    }
    return 1;
}

/* the checks of am_lattice_format and am_model_build, so what is written reads back */
static am_status check_input(const am_lattice* lat, const am_env* env, double dt, char* err, int errsz)
{
    if (lat->nx < 1 || lat->ny < 1 || lat->nz < 1 || lat->nx > AM_MAX_DIM || lat->ny > AM_MAX_DIM || lat->nz > AM_MAX_DIM)
        return am_fail(err, errsz, AM_ERR_ARG, "vxa format: size %d %d %d outside 1..%d", lat->nx, lat->ny, lat->nz, AM_MAX_DIM);
    if (!am_param_finite(lat->voxel_size) || !(lat->voxel_size > AM_P(0)))
        return am_fail(err, errsz, AM_ERR_ARG, "vxa format: the voxel size must be a positive finite number");
    const am_palette* pal = &lat->palette;
    if (pal->count < 1 || pal->count > AM_MAX_MATERIALS)
        return am_fail(err, errsz, AM_ERR_ARG, "vxa format: palette count %d outside 1..%d", pal->count, AM_MAX_MATERIALS);
    for (int i = 0; i < pal->count; i++) {
        const am_material* m = &pal->mat[i];
        if (!name_ok(m->name)) return am_fail(err, errsz, AM_ERR_ARG, "vxa format: material %d has a bad name", i + 1);
        if (!(m->E > AM_P(0)) || !am_param_finite(m->E) || !(m->density > AM_P(0)) || !am_param_finite(m->density) ||
            !(m->poisson >= AM_P(0) && m->poisson < AM_P(0.5)) || !am_param_finite(m->cte) || !am_param_finite(m->phase) ||
            !(m->mu_static >= AM_P(0)) || !am_param_finite(m->mu_static) || !(m->mu_kinetic >= AM_P(0)) || !am_param_finite(m->mu_kinetic) ||
            !(m->zeta_internal >= AM_P(0)) || !am_param_finite(m->zeta_internal) || !(m->zeta_global >= AM_P(0)) ||
            !am_param_finite(m->zeta_global) || !(m->zeta_collision >= AM_P(0)) || !am_param_finite(m->zeta_collision) ||
            (m->fixed != 0 && m->fixed != 1))
            return am_fail(err, errsz, AM_ERR_ARG, "vxa format: material '%s' has a value outside its range", m->name);
    }
    int cells = lat->nx * lat->ny * lat->nz;
    for (int i = 0; i < cells; i++)
        if (lat->cell[i] > pal->count)
            return am_fail(err, errsz, AM_ERR_ARG, "vxa format: cell %d holds material id %d, the palette has %d", i, lat->cell[i],
                           pal->count);
    if (!(env->gravity >= AM_P(0)) || !am_param_finite(env->gravity) || env->period_steps < 1 || !(env->dt_frac > AM_P(0)) ||
        !am_param_finite(env->dt_frac) || !am_param_finite(env->temp_base) || !am_param_finite(env->temp_amplitude) || !am_param_finite(env->lift) ||
        !(env->lift >= AM_P(0)) || !(env->zeta_internal_scale >= AM_P(0)) || !am_param_finite(env->zeta_internal_scale) ||
        !(env->zeta_global_scale >= AM_P(0)) || !am_param_finite(env->zeta_global_scale) ||
        (env->cte_mode != AM_CTE_VOLUMETRIC && env->cte_mode != AM_CTE_LINEAR))
        return am_fail(err, errsz, AM_ERR_ARG, "vxa format: an environment value is outside its range");
    if (!(dt > 0) || !(dt < 1e30)) return am_fail(err, errsz, AM_ERR_ARG, "vxa format: the time step must be a positive number");
    return AM_OK;
}

am_status am_vxa_format(const am_lattice* lat, const am_env* env, double dt, char* buf, long cap, long* len, char* err,
                        int errsz)
{
    return am_vxa_format_layers(lat, NULL, env, dt, buf, cap, len, err, errsz);
}

/* the voxels with a boundary condition: one box <FRegion> each, its own cell */
static am_status put_regions(wbuf* w, const am_lattice* lat, const am_layers* ly, char* err, int errsz)
{
    const int nx = lat->nx, ny = lat->ny, nz = lat->nz;
    char a[40], b[40];
    int count = 0;
    for (int c = 0; c < nx * ny * nz; c++)
        count += lat->cell[c] && (ly->fixed[c] || ly->force[0][c] != AM_P(0) || ly->force[1][c] != AM_P(0) || ly->force[2][c] != AM_P(0));
    if (count == 0) return AM_OK;
    if (count > AM_VXA_MAX_BC_VOXELS)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "vxa format: %d voxels with boundary conditions, more than the %d it writes", count,
                       AM_VXA_MAX_BC_VOXELS);
    put(w, "    <Boundary_Conditions>\n      <NumBCs>%d</NumBCs>\n", count);
    for (int c = 0; c < nx * ny * nz; c++) {
        if (!lat->cell[c] || !(ly->fixed[c] || ly->force[0][c] != AM_P(0) || ly->force[1][c] != AM_P(0) || ly->force[2][c] != AM_P(0)))
            continue;
        const int idx[3] = {c % nx, c / nx % ny, c / (nx * ny)}, n[3] = {nx, ny, nz};
        static const char* const ax[3] = {"X", "Y", "Z"};
        put(w, "      <FRegion>\n        <PrimType>0</PrimType>\n");
        /* the middle half of the cell: that cell alone by any reader's rule (its centre, or touching) */
        for (int k = 0; k < 3; k++)
            put(w, "        <%s>%s</%s>\n        <d%s>%s</d%s>\n", ax[k], num(a, (idx[k] + 0.25) / n[k], 0), ax[k], ax[k],
                num(b, 0.5 / n[k], 0), ax[k]);
        put(w, "        <DofFixed>%d</DofFixed>\n", ly->fixed[c] ? 63 : 0);
        /* a clamped cell's slot is its prescribed displacement, a free one's its force */
        const int fixed = ly->fixed[c] != 0, moved = fixed && (ly->force[0][c] != AM_P(0) || ly->force[1][c] != AM_P(0) || ly->force[2][c] != AM_P(0));
        for (int k = 0; k < 3; k++) put(w, "        <Force%s>%s</Force%s>\n", ax[k], num(a, fixed ? 0.0 : (double)ly->force[k][c], 1), ax[k]);
        for (int k = 0; moved && k < 3; k++) put(w, "        <Displace%s>%s</Displace%s>\n", ax[k], num(a, (double)ly->force[k][c], 1), ax[k]);
        put(w, "      </FRegion>\n");
    }
    put(w, "    </Boundary_Conditions>\n");
    return AM_OK;
}

static am_status format_vxa(const am_lattice* lat, const am_layers* layers, const am_env* env, const am_eval_def* eval, double dt,
                            char* buf, long cap, long* len, char* err, int errsz);

am_status am_vxa_format_layers(const am_lattice* lat, const am_layers* layers, const am_env* env, double dt, char* buf, long cap,
                               long* len, char* err, int errsz)
{
    return format_vxa(lat, layers, env, NULL, dt, buf, cap, len, err, errsz);
}

am_status am_vxa_format_robot(const am_robot* r, double dt, char* buf, long cap, long* len, char* err, int errsz)
{
    if (!r) return am_fail(err, errsz, AM_ERR_ARG, "vxa format: no robot");
    return format_vxa(r->lattice, r->layers, &r->env, &r->eval, dt, buf, cap, len, err, errsz);
}

/* the whole file: lat, its layers (NULL: none), env, and eval (NULL: no <Evaluation>) */
static am_status format_vxa(const am_lattice* lat, const am_layers* layers, const am_env* env, const am_eval_def* eval, double dt,
                            char* buf, long cap, long* len, char* err, int errsz)
{
    if (len) *len = 0;
    if (!lat || !env || !buf || cap < 1) return am_fail(err, errsz, AM_ERR_ARG, "vxa format: no lattice, environment or buffer");
    buf[0] = 0;
    am_status st = check_input(lat, env, dt, err, errsz);
    if (st != AM_OK) return st;
    const am_palette* pal = &lat->palette;
    const am_material* m0 = &pal->mat[0];
    int vol = env->cte_mode == AM_CTE_VOLUMETRIC;
    char a[40], b[40];
    wbuf w = {buf, cap, 0, 0, NULL, NULL, 0};

    put(&w, "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n<VXA Version=\"1.1\">\n");
    put(&w, "  <!-- written by amorph (docs/vxa.md); VoxCAD ignores the <Amorph> element at the end -->\n");
    put(&w, "  <Simulator>\n    <Integration>\n      <Integrator>0</Integrator>\n");
    put(&w, "      <DtFrac>%s</DtFrac>\n    </Integration>\n", num(a, (double)env->dt_frac, 1));
    /* one damping ratio per kind in VXA: material 1's, scaled as the simulator scales it */
    put(&w, "    <Damping>\n      <BondDampingZ>%s</BondDampingZ>\n",
        num(a, (double)(m0->zeta_internal * env->zeta_internal_scale), 1));
    put(&w, "      <ColDampingZ>%s</ColDampingZ>\n", num(a, (double)m0->zeta_collision, 1));
    put(&w, "      <SlowDampingZ>%s</SlowDampingZ>\n    </Damping>\n",
        num(a, (double)(m0->zeta_global * env->zeta_global_scale), 1));
    put(&w, "    <Collisions>\n      <SelfColEnabled>%d</SelfColEnabled>\n      <ColSystem>3</ColSystem>\n"
            "      <CollisionHorizon>3</CollisionHorizon>\n    </Collisions>\n  </Simulator>\n",
        env->collisions ? 1 : 0);

    put(&w, "  <Environment>\n");
    if (layers && layers->has_bc && (st = put_regions(&w, lat, layers, err, errsz)) != AM_OK) {
        buf[0] = 0;
        return st;
    }
    put(&w, "    <Gravity>\n      <GravEnabled>%d</GravEnabled>\n", env->gravity > AM_P(0) ? 1 : 0);
    put(&w, "      <GravAcc>%s</GravAcc>\n      <FloorEnabled>%d</FloorEnabled>\n    </Gravity>\n",
        env->gravity > AM_P(0) ? num(a, -(double)env->gravity, 1) : "-9.81", env->floor ? 1 : 0);
    /* VoxCAD's temperature: TempBase + TempAmplitude sin(2 pi t / TempPeriod + phase); expansion
     * follows the difference to TempBase. A constant offset alone is VaryTempEnabled 0. */
    int vary = env->temp_amplitude != AM_P(0) || env->temp_base == AM_P(0);
    double amp = vary ? (double)env->temp_amplitude : (double)env->temp_base;
    put(&w, "    <Thermal>\n      <TempEnabled>1</TempEnabled>\n      <TempAmplitude>%s</TempAmplitude>\n", num(a, amp, 1));
    put(&w, "      <TempAmp>%s</TempAmp>\n      <TempBase>%s</TempBase>\n", num(a, VXA_TEMP_BASE + amp, 0),
        num(b, VXA_TEMP_BASE, 0));
    put(&w, "      <VaryTempEnabled>%d</VaryTempEnabled>\n      <TempPeriod>%s</TempPeriod>\n    </Thermal>\n  </Environment>\n",
        vary, num(a, (double)env->period_steps * dt, 0));

    put(&w, "  <VXC Version=\"0.94\">\n    <Lattice>\n      <Lattice_Dim>%s</Lattice_Dim>\n", num(a, (double)lat->voxel_size, 1));
    put(&w, "      <X_Dim_Adj>1</X_Dim_Adj>\n      <Y_Dim_Adj>1</Y_Dim_Adj>\n      <Z_Dim_Adj>1</Z_Dim_Adj>\n"
            "      <X_Line_Offset>0</X_Line_Offset>\n      <Y_Line_Offset>0</Y_Line_Offset>\n"
            "      <X_Layer_Offset>0</X_Layer_Offset>\n      <Y_Layer_Offset>0</Y_Layer_Offset>\n    </Lattice>\n");
    put(&w, "    <Voxel>\n      <Vox_Name>BOX</Vox_Name>\n      <X_Squeeze>1</X_Squeeze>\n      <Y_Squeeze>1</Y_Squeeze>\n"
            "      <Z_Squeeze>1</Z_Squeeze>\n    </Voxel>\n    <Palette>\n");
    for (int i = 0; i < pal->count; i++) {
        const am_material* m = &pal->mat[i];
        put(&w, "      <Material ID=\"%d\">\n        <MatType>0</MatType>\n        <Name>%s</Name>\n        <Display>\n", i + 1,
            m->name);
        static const char* const rgba[4] = {"Red", "Green", "Blue", "Alpha"};
        for (int k = 0; k < 4; k++) /* 6 digits of c / 255 read back to c */
            put(&w, "          <%s>%.6g</%s>\n", rgba[k], m->color[k] / 255.0, rgba[k]);
        put(&w, "        </Display>\n        <Mechanical>\n          <MatModel>0</MatModel>\n");
        put(&w, "          <Elastic_Mod>%s</Elastic_Mod>\n", num(a, (double)m->E, 1));
        put(&w, "          <Plastic_Mod>0</Plastic_Mod>\n          <Yield_Stress>0</Yield_Stress>\n          <FailModel>0</FailModel>\n"
                "          <Fail_Stress>0</Fail_Stress>\n          <Fail_Strain>0</Fail_Strain>\n");
        put(&w, "          <Density>%s</Density>\n", num(a, (double)m->density, 1));
        put(&w, "          <Poissons_Ratio>%s</Poissons_Ratio>\n", num(a, (double)m->poisson, 1));
        /* VXA's CTE is linear: a volumetric one is written as its small-strain equivalent / 3 */
        put(&w, "          <CTE>%s</CTE>\n", num(a, vol ? (double)m->cte / 3.0 : (double)m->cte, vol ? 0 : 1));
        put(&w, "          <MaterialTempPhase>%s</MaterialTempPhase>\n", num(a, (double)m->phase, 1));
        put(&w, "          <uStatic>%s</uStatic>\n", num(a, (double)m->mu_static, 1));
        put(&w, "          <uDynamic>%s</uDynamic>\n", num(a, (double)m->mu_kinetic, 1));
        if (m->fixed) put(&w, "          <Fixed>1</Fixed>\n"); /* voxcraft-sim's fixed material */
        put(&w, "        </Mechanical>\n      </Material>\n");
    }
    put(&w, "    </Palette>\n    <Structure Compression=\"ASCII_READABLE\">\n");
    put(&w, "      <X_Voxels>%d</X_Voxels>\n      <Y_Voxels>%d</Y_Voxels>\n      <Z_Voxels>%d</Z_Voxels>\n      <Data>\n",
        lat->nx, lat->ny, lat->nz);
    long per = (long)lat->nx * lat->ny;
    for (int z = 0; z < lat->nz && !w.full; z++) {
        put(&w, "        <Layer><![CDATA[");
        if (w.full || w.cap - w.len < per + 1) {
            w.full = 1;
            break;
        }
        for (long i = 0; i < per; i++) w.buf[w.len++] = (char)('0' + lat->cell[per * z + i]);
        w.buf[w.len] = 0;
        put(&w, "]]></Layer>\n");
    }
    put(&w, "      </Data>\n");
    if (layers && layers->has_phase) {
        /* evosoro's form: one CDATA list of reals per layer, in periods */
        put(&w, "      <PhaseOffset>\n");
        for (int z = 0; z < lat->nz && !w.full; z++) {
            put(&w, "        <Layer><![CDATA[");
            for (long i = 0; i < per; i++) put(&w, "%s%s", i ? ", " : "", num(a, (double)layers->phase[per * z + i], 1));
            put(&w, "]]></Layer>\n");
        }
        put(&w, "      </PhaseOffset>\n");
    }
    if (layers && layers->has_stiffness) {
        /* evosoro's form: the elastic modulus of each cell's voxel, Pa */
        put(&w, "      <Stiffness>\n");
        for (int z = 0; z < lat->nz && !w.full; z++) {
            put(&w, "        <Layer><![CDATA[");
            for (long i = 0; i < per; i++) put(&w, "%s%s", i ? ", " : "", num(a, (double)layers->stiffness[per * z + i], 1));
            put(&w, "]]></Layer>\n");
        }
        put(&w, "      </Stiffness>\n");
    }
    put(&w, "    </Structure>\n  </VXC>\n");

    put(&w, "  <Amorph Version=\"1\">\n    <CTEMode>%s</CTEMode>\n    <PeriodSteps>%d</PeriodSteps>\n",
        vol ? "volumetric" : "linear", env->period_steps);
    put(&w, "    <TempOffset>%s</TempOffset>\n", num(a, (double)env->temp_base, 1));
    put(&w, "    <Lift>%s</Lift>\n", num(a, (double)env->lift, 1));
    put(&w, "    <ZetaInternalScale>%s</ZetaInternalScale>\n", num(a, (double)env->zeta_internal_scale, 1));
    put(&w, "    <ZetaGlobalScale>%s</ZetaGlobalScale>\n", num(a, (double)env->zeta_global_scale, 1));
    put(&w, "    <DtFrac>%s</DtFrac>\n", num(a, (double)env->dt_frac, 1));
    if (eval) {
        /* every evaluation key as the configuration writes it */
        am_evo_def d = am_default_evo();
        d.eval = *eval;
        put(&w, "    <Evaluation>");
        for (int i = 0; i < am_evo_key_count(); i++) {
            const char* key = am_evo_key_name(i);
            if (am_evo_key_group(key) != AM_KEYS_EVAL) continue;
            char v[64];
            am_evo_key_value(&d, i, v, sizeof v);
            put(&w, "<%s>%s</%s>", key, v, key);
        }
        put(&w, "</Evaluation>\n");
    }
    for (int i = 0; i < pal->count; i++) {
        const am_material* m = &pal->mat[i];
        put(&w, "    <Material ID=\"%d\">", i + 1);
        if (vol) put(&w, "<CTE>%s</CTE>", num(a, (double)m->cte, 1));
        put(&w, "<ZetaInternal>%s</ZetaInternal>", num(a, (double)m->zeta_internal, 1));
        put(&w, "<ZetaGlobal>%s</ZetaGlobal>", num(a, (double)m->zeta_global, 1));
        put(&w, "<ZetaCollision>%s</ZetaCollision>", num(a, (double)m->zeta_collision, 1));
        put(&w, "<Fixed>%d</Fixed></Material>\n", m->fixed);
    }
    put(&w, "  </Amorph>\n</VXA>\n");
    if (w.full) {
        buf[0] = 0;
        return am_fail(err, errsz, AM_ERR_CAPACITY, "vxa format: the text needs more than the %ld bytes given", cap);
    }
    if (len) *len = w.len;
    return AM_OK;
}
