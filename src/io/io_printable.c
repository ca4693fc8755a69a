/* The printable files of a mesh (include/amorph/io.h, docs/formats.md): ASCII STL of one solid
 * (a material's surface, or the body's), and AMF (ISO/ASTM 52915) with one volume per material.
 * Both in millimetres. */
#include "amorph/io.h"

#include <math.h>

#define MM 1000.0 /* file units per metre */

static am_status done(am_text* out, const char* what, char* err, int errsz)
{
    am_status st = am_text_flush(out);
    if (st == AM_ERR_CAPACITY) return am_fail(err, errsz, st, "%s: the text does not fit", what);
    if (st != AM_OK) return am_fail(err, errsz, st, "%s: could not be written", what);
    return AM_OK;
}

am_status am_mesh_write_stl(const am_mesh* m, const double* pos, const am_palette* pal, int mat, am_text* out, char* err,
                            int errsz)
{
    if (mat >= pal->count) return am_fail(err, errsz, AM_ERR_ARG, "STL: no material %d in the palette", mat);
    const char* name = mat >= 0 ? pal->mat[mat].name : "body";
    am_text_put(out, "solid %s\n", name);
    for (long t = 0; t < m->ntri && !out->full; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        const double *a = pos + 3 * m->tri[t][0], *b = pos + 3 * m->tri[t][1], *c = pos + 3 * m->tri[t][2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int j = 0; j < 3; j++) n[j] = len > 0 ? n[j] / len : 0;
        am_text_put(out, "  facet normal %.7g %.7g %.7g\n    outer loop\n", n[0] + 0.0, n[1] + 0.0, n[2] + 0.0);
        for (int j = 0; j < 3; j++) {
            const double* p = pos + 3 * m->tri[t][j];
            am_text_put(out, "      vertex %.7g %.7g %.7g\n", p[0] * MM, p[1] * MM, p[2] * MM);
        }
        am_text_put(out, "    endloop\n  endfacet\n");
    }
    am_text_put(out, "endsolid %s\n", name);
    return done(out, "STL", err, errsz);
}

/* text with the five XML special characters escaped */
static void put_xml(am_text* out, const char* s)
{
    for (; *s; s++) {
        if (*s == '<') am_text_put(out, "&lt;");
        else if (*s == '>') am_text_put(out, "&gt;");
        else if (*s == '&') am_text_put(out, "&amp;");
        else if (*s == '"') am_text_put(out, "&quot;");
        else if (*s == '\'') am_text_put(out, "&apos;");
        else am_text_write(out, s, 1);
    }
}

am_status am_mesh_write_amf(const am_mesh* m, const double* pos, const am_palette* pal, const char* title, am_text* out,
                            char* err, int errsz)
{
    am_text_put(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<amf unit=\"millimeter\" version=\"1.1\">\n");
    if (title) {
        am_text_put(out, "  <metadata type=\"name\">");
        put_xml(out, title);
        am_text_put(out, "</metadata>\n");
    }
    am_text_put(out, "  <metadata type=\"producer\">amorph</metadata>\n");
    for (int k = 0; k < pal->count; k++) {
        if (!am_mesh_holds(m, k)) continue;
        const uint8_t* c = pal->mat[k].color;
        am_text_put(out, "  <material id=\"%d\">\n    <metadata type=\"name\">", k + 1);
        put_xml(out, pal->mat[k].name);
        am_text_put(out, "</metadata>\n    <color><r>%.4g</r><g>%.4g</g><b>%.4g</b></color>\n  </material>\n", c[0] / 255.0,
                    c[1] / 255.0, c[2] / 255.0);
    }
    am_text_put(out, "  <object id=\"1\">\n    <mesh>\n      <vertices>\n");
    for (long v = 0; v < m->nvert && !out->full; v++)
        am_text_put(out, "        <vertex><coordinates><x>%.7g</x><y>%.7g</y><z>%.7g</z></coordinates></vertex>\n",
                    pos[3 * v] * MM, pos[3 * v + 1] * MM, pos[3 * v + 2] * MM);
    am_text_put(out, "      </vertices>\n");
    for (int k = 0; k < pal->count && !out->full; k++) {
        if (!am_mesh_holds(m, k)) continue;
        am_text_put(out, "      <volume materialid=\"%d\">\n        <metadata type=\"name\">", k + 1);
        put_xml(out, pal->mat[k].name);
        am_text_put(out, "</metadata>\n");
        for (long t = 0; t < m->ntri && !out->full; t++)
            if (m->tmat[t] == k)
                am_text_put(out, "        <triangle><v1>%ld</v1><v2>%ld</v2><v3>%ld</v3></triangle>\n", (long)m->tri[t][0],
                            (long)m->tri[t][1], (long)m->tri[t][2]);
        am_text_put(out, "      </volume>\n");
    }
    am_text_put(out, "    </mesh>\n  </object>\n</amf>\n");
    return done(out, "AMF", err, errsz);
}
