/* Tests of the XML reader (src/io/io_xml.c) and the VXA format (src/io/io_vxa.c): parser edge cases,
 * exact round trips, VoxCAD conventions (legacy TempAmp, names, damping, BASE64 layers), warnings,
 * and one check per malformed input with its status and exact "fname:line: problem" message. */
#include "amorph.h"
#include "cmd.h"
#include "harness.h"
#include "picture.h"
#include "robot.h"

#include <math.h>
#include <stdint.h>

static am_xml_doc doc;
static am_lattice lat_a, lat_b;
static am_vxa_info info_a, info_b;
static char text[AM_VXA_TEXT_MAX];
static char text2[AM_VXA_TEXT_MAX];
static char big[1L << 20];
static char msg[512];

/* ---- the XML reader ---------------------------------------------------------------------- */

static am_status xml(const char* t, char* err)
{
    err[0] = 0;
    return am_xml_parse(&doc, t, (long)strlen(t), "t.xml", err, AM_ERR_MAX);
}

static void expect_xml(const char* t, am_status code, const char* want)
{
    char err[AM_ERR_MAX];
    am_status st = xml(t, err);
    CHECK(st == code && strcmp(err, want) == 0, "'%.60s': status %d (want %d), message '%s' (want '%s')", t, st, code, err, want);
}

static void test_xml_basics(void)
{
    char err[AM_ERR_MAX], out[256];
    long len = -1;
    const char* t = "\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n<!-- top -->\n"
                    "<a x=\"1\" y = 'two &amp; &quot;three&quot;'>\n  <b>t&lt;&#65;&#x42;&gt;&apos;</b><!-- c -->\n"
                    "  <c/><?pi data?>\n  <![CDATA[<raw & text>]]>\n</a>\n<!-- after -->\n";
    CHECK(xml(t, err) == AM_OK, "%s", err);
    CHECK(doc.nnodes == 3, "nodes %d", doc.nnodes);
    CHECK(am_xml_is(&doc, 0, "a") && am_xml_is(&doc, 1, "b") && am_xml_is(&doc, 2, "c") && !am_xml_is(&doc, 0, "ab"), "names");
    CHECK(doc.node[0].child == 1 && doc.node[1].next == 2 && doc.node[2].next == -1 && doc.node[1].parent == 0, "tree links");
    CHECK(doc.node[0].line == 3 && doc.node[1].line == 4 && doc.node[2].line == 5, "lines %d %d %d", (int)doc.node[0].line,
          (int)doc.node[1].line, (int)doc.node[2].line);
    int a = am_xml_attr_find(&doc, 0, "y");
    CHECK(a >= 0 && am_xml_attr_find(&doc, 0, "z") < 0, "attribute lookup");
    CHECK(am_xml_attr_text(&doc, a, out, sizeof out, &len) == AM_OK && !strcmp(out, "two & \"three\"") && len == 13, "attr '%s'", out);
    CHECK(am_xml_text(&doc, 1, out, sizeof out, &len) == AM_OK && !strcmp(out, "t<AB>'") && len == 6, "text '%s'", out);
    /* the root's own character data: blanks and the CDATA, not the children's text */
    CHECK(am_xml_text(&doc, 0, out, sizeof out, NULL) == AM_OK && strstr(out, "<raw & text>") && !strstr(out, "t<"), "root '%s'", out);
    CHECK(am_xml_text(&doc, 2, out, sizeof out, &len) == AM_OK && len == 0, "empty element");
    /* too small an output buffer: a capacity status and an empty string */
    CHECK(am_xml_text(&doc, 1, out, 4, &len) == AM_ERR_CAPACITY && out[0] == 0, "short buffer");
    /* UTF-8 from a character reference; tabs and newlines in attributes read as spaces */
    CHECK(xml("<a v=\"x\ty\nz\">&#233;&#x1F600;</a>", err) == AM_OK, "%s", err);
    CHECK(am_xml_text(&doc, 0, out, sizeof out, NULL) == AM_OK && !strcmp(out, "\xC3\xA9\xF0\x9F\x98\x80"), "utf-8");
    CHECK(am_xml_attr_text(&doc, 0, out, sizeof out, NULL) == AM_OK && !strcmp(out, "x y z"), "attr blanks '%s'", out);
    /* CRLF line ends count as one line and read as '\n' */
    CHECK(xml("<a>\r\n<b>x\r\ny</b>\r\n</a>", err) == AM_OK && doc.node[1].line == 2, "crlf");
    CHECK(am_xml_text(&doc, 1, out, sizeof out, NULL) == AM_OK && !strcmp(out, "x\ny"), "crlf text");
}

static void test_xml_errors(void)
{
    expect_xml("", AM_ERR_PARSE, "t.xml:1: no root element (the file is empty or holds only comments)");
    expect_xml("<!-- only -->\n", AM_ERR_PARSE, "t.xml:1: no root element (the file is empty or holds only comments)");
    expect_xml("<a>\n<b>\n</a>", AM_ERR_PARSE, "t.xml:3: </a> does not close <b> (opened on line 2)");
    expect_xml("<a>\n<b></b>\n", AM_ERR_PARSE, "t.xml:2: the file ends inside <a> (opened on line 1)");
    expect_xml("</a>", AM_ERR_PARSE, "t.xml:1: end tag </a> without a start tag");
    expect_xml("<a>\n&foo;</a>", AM_ERR_PARSE, "t.xml:2: unknown entity (XML predefines only &lt; &gt; &amp; &quot; &apos;)");
    expect_xml("<a>x & y</a>", AM_ERR_PARSE, "t.xml:1: '&' must start a reference such as &amp; (write &amp; for a literal '&')");
    expect_xml("<a>&#0;</a>", AM_ERR_PARSE, "t.xml:1: character reference to a character XML does not allow");
    expect_xml("<a>&#xD800;</a>", AM_ERR_PARSE, "t.xml:1: character reference to a character XML does not allow");
    expect_xml("<a>&#12a;</a>", AM_ERR_PARSE, "t.xml:1: bad digit in a character reference");
    expect_xml("<a>&#x110000;</a>", AM_ERR_PARSE, "t.xml:1: character reference beyond U+10FFFF");
    expect_xml("<a>]]></a>", AM_ERR_PARSE, "t.xml:1: ']]>' is not allowed in text (write ]]&gt;)");
    expect_xml("<a x=\"1\" x=\"2\"/>", AM_ERR_PARSE, "t.xml:1: attribute 'x' given twice in <a>");
    expect_xml("<a x=1/>", AM_ERR_PARSE, "t.xml:1: the value of attribute 'x' must be quoted (\" or ')");
    expect_xml("<a x/>", AM_ERR_PARSE, "t.xml:1: attribute 'x' of <a> has no '=' and value");
    expect_xml("<a x=\"1\"y=\"2\"/>", AM_ERR_PARSE, "t.xml:1: expected a blank before attribute 'y' in <a>");
    expect_xml("<a x=\"<\"/>", AM_ERR_PARSE, "t.xml:1: '<' in the value of attribute 'x' (write &lt;)");
    expect_xml("<a x=\"1/>", AM_ERR_PARSE, "t.xml:1: the value of attribute 'x' is not closed");
    expect_xml("<a\n", AM_ERR_PARSE, "t.xml:1: start tag <a> not closed (the file ends)");
    expect_xml("<a / >", AM_ERR_PARSE, "t.xml:1: expected '/>' after '/' in <a>");
    expect_xml("<a>< b</a>", AM_ERR_PARSE, "t.xml:1: '<' followed by 0x20 does not start a tag (write &lt; for a literal '<')");
    expect_xml("<a>\n<!-- x -- y -->\n</a>", AM_ERR_PARSE, "t.xml:2: '--' inside a comment");
    expect_xml("<a>\n<!-- x </a>", AM_ERR_PARSE, "t.xml:2: comment not closed (no '-->')");
    expect_xml("<a><![CDATA[x</a>", AM_ERR_PARSE, "t.xml:1: CDATA section not closed (no ']]>')");
    expect_xml("<![CDATA[x]]><a/>", AM_ERR_PARSE, "t.xml:1: CDATA section outside the root element");
    expect_xml("<!DOCTYPE a [<!ENTITY e \"x\">]>\n<a>&e;</a>", AM_ERR_PARSE, "t.xml:1: DOCTYPE declarations are not supported");
    expect_xml("<a><!ELEMENT a></a>", AM_ERR_PARSE, "t.xml:1: unexpected '<!' (expected a comment <!-- --> or a CDATA section)");
    expect_xml("<a/>\n<?xml version=\"1.0\"?>", AM_ERR_PARSE, "t.xml:2: the XML declaration <?xml ...?> must come first in the file");
    expect_xml("<?xml version=\"1.0\"", AM_ERR_PARSE, "t.xml:1: the XML declaration is not closed with '?>'");
    expect_xml("<a><? x?></a>", AM_ERR_PARSE, "t.xml:1: a processing instruction '<?' needs a target name");
    expect_xml("<a/>\n<b/>", AM_ERR_PARSE, "t.xml:2: a second root element <b> (an XML document has exactly one)");
    expect_xml("x<a/>", AM_ERR_PARSE, "t.xml:1: text before the root element");
    expect_xml("<a/>\n\nx", AM_ERR_PARSE, "t.xml:3: text after the root element");
    expect_xml("<a>\x01</a>", AM_ERR_PARSE, "t.xml:1: control character 0x01 is not allowed in XML");
    expect_xml("<a></a >", AM_OK, "");
    expect_xml("<a></a", AM_ERR_PARSE, "t.xml:1: end tag </a> not closed with '>'");
    expect_xml("<a></>", AM_ERR_PARSE, "t.xml:1: '</' must be followed by an element name");
    /* a NUL byte inside the given length */
    char err[AM_ERR_MAX];
    CHECK(am_xml_parse(&doc, "<a>\0</a>", 8, "t.xml", err, sizeof err) == AM_ERR_PARSE &&
              !strcmp(err, "t.xml:1: a NUL byte (binary data) in an XML file"), "%s", err);
    /* a short message buffer is cut, never overrun */
    char tiny[12];
    memset(tiny, 'x', sizeof tiny);
    CHECK(am_xml_parse(&doc, "<a>", 3, "t.xml", tiny, 8) == AM_ERR_PARSE && strlen(tiny) == 7 && tiny[8] == 'x', "cut message");
}

/* the fixed memory: depth, element count and text size are each refused with a capacity status */
static void test_xml_limits(void)
{
    char want[AM_ERR_MAX];
    long n = 0;
    /* nesting one deeper than allowed: fine at the limit, refused past it */
    for (int i = 0; i < AM_XML_MAX_DEPTH; i++) n += sprintf(big + n, "<d>");
    for (int i = 0; i < AM_XML_MAX_DEPTH; i++) n += sprintf(big + n, "</d>");
    expect_xml(big, AM_OK, "");
    n = 0;
    for (int i = 0; i < 10000; i++) n += sprintf(big + n, "<d>");
    snprintf(want, sizeof want, "t.xml:1: elements nested deeper than %d levels (the XML reader's limit, %s profile)",
             AM_XML_MAX_DEPTH, AM_PROFILE_NAME);
    expect_xml(big, AM_ERR_CAPACITY, want);
    /* one element more than the capacity, on its own line */
    n = sprintf(big, "<r>\n");
    for (int i = 0; i < AM_XML_MAX_NODES; i++) n += sprintf(big + n, "<e/>\n");
    sprintf(big + n, "</r>\n");
    snprintf(want, sizeof want, "t.xml:%d: more than %d elements (the XML reader's capacity, %s profile)", AM_XML_MAX_NODES + 1,
             AM_XML_MAX_NODES, AM_PROFILE_NAME);
    expect_xml(big, AM_ERR_CAPACITY, want);
    /* attributes past their capacity */
    n = sprintf(big, "<r>");
    for (int i = 0; i <= AM_XML_MAX_ATTRS; i++) n += sprintf(big + n, "<e a=\"1\"/>");
    sprintf(big + n, "</r>");
    snprintf(want, sizeof want, "t.xml:1: more than %d attributes (the XML reader's capacity, %s profile)", AM_XML_MAX_ATTRS,
             AM_PROFILE_NAME);
    expect_xml(big, AM_ERR_CAPACITY, want);
    /* a text longer than the reader takes is refused before any byte is read (the length is
     * checked first, so a short buffer with a long claimed length is a fair probe) */
    char err[AM_ERR_MAX];
    snprintf(want, sizeof want, "t.xml:1: %ld bytes of XML: more than the %ld the reader takes (%s profile)",
             (long)AM_XML_MAX_BYTES + 1, (long)AM_XML_MAX_BYTES, AM_PROFILE_NAME);
    CHECK(am_xml_parse(&doc, "<a/>", AM_XML_MAX_BYTES + 1, "t.xml", err, sizeof err) == AM_ERR_CAPACITY && !strcmp(err, want),
          "%s", err);
    /* a name longer than 255 bytes */
    memset(big, 'n', 300);
    big[0] = '<';
    strcpy(big + 300, "/>");
    CHECK(xml(big, err) == AM_ERR_CAPACITY && strstr(err, "t.xml:1: element name 'nnn") && strstr(err, "longer than 255 bytes"),
          "%s", err);
}

/* ---- VXA: round trips --------------------------------------------------------------------- */

static int same_env(const am_env* a, const am_env* b)
{
    return a->gravity == b->gravity && a->floor == b->floor && a->collisions == b->collisions && a->cte_mode == b->cte_mode &&
           a->temp_base == b->temp_base && a->temp_amplitude == b->temp_amplitude && a->period_steps == b->period_steps &&
           a->dt_frac == b->dt_frac && a->lift == b->lift && a->zeta_internal_scale == b->zeta_internal_scale &&
           a->zeta_global_scale == b->zeta_global_scale;
}

/* write lat and env, read them back, compare, and check a second write gives the same text */
static void round_trip(const am_lattice* lat, const am_env* env, const char* what)
{
    char err[AM_ERR_MAX] = "";
    long len = -1, len2 = -1;
    am_status st = am_vxa_format(lat, env, 2.5e-5, text, sizeof text, &len, err, sizeof err);
    CHECK(st == AM_OK && len == (long)strlen(text), "%s: format: %s", what, err);
    st = am_vxa_parse(&lat_b, &info_b, &doc, text, what, err, sizeof err);
    CHECK(st == AM_OK, "%s: parse: %s", what, err);
    CHECK(info_b.warnings == 0, "%s: %d warnings: %s", what, info_b.warnings, info_b.warning);
    CHECK(am_lattice_equal(lat, &lat_b), "%s: the lattice differs after a round trip", what);
    CHECK(same_env(env, &info_b.env) && info_b.period_steps_given, "%s: the environment differs after a round trip", what);
    /* the period in seconds, unless the temperature is constant (VaryTempEnabled 0) */
    if (env->temp_amplitude != AM_P(0) || env->temp_base == AM_P(0)) NEAR_REL(info_b.temp_period, env->period_steps * 2.5e-5, 1e-15);
    else CHECK(info_b.temp_period == 0, "%s: constant temperature has no period", what);
    st = am_vxa_format(&lat_b, &info_b.env, 2.5e-5, text2, sizeof text2, &len2, err, sizeof err);
    CHECK(st == AM_OK && len2 == len && strcmp(text, text2) == 0, "%s: second format differs", what);
}

static void test_vxa_round_trip_scenes(void)
{
    static const char* const scenes[] = {"cube:1", "cube:3", "sphere:7", "sphere:20", "cantilever:5", "chain:4", "cube:20"};
    char err[AM_ERR_MAX] = "";
    am_env env = am_default_env();
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        int side = atoi(strchr(scenes[i], ':') + 1);
        if (side > AM_MAX_DIM || (test_quick() && side > 8)) continue; /* the board profile; valgrind */
        CHECK(am_scene_build(&lat_a, scenes[i], err, sizeof err) == AM_OK, "%s", err);
        round_trip(&lat_a, &env, scenes[i]);
    }
}

/* every material field and every environment field away from its default, both CTE conventions,
 * all 16 materials in use, and values that need every digit */
static void test_vxa_round_trip_everything(void)
{
    char err[AM_ERR_MAX] = "";
    CHECK(am_lattice_init(&lat_a, AM_MAX_DIM, AM_MAX_DIM > 3 ? 3 : AM_MAX_DIM, 2, AM_P(0.0123456789), err, sizeof err) == AM_OK,
          "%s", err);
    lat_a.palette.count = AM_MAX_MATERIALS;
    for (int k = 0; k < AM_MAX_MATERIALS; k++) {
        am_material* m = &lat_a.palette.mat[k];
        *m = am_default_material();
        memset(m->name, 0, sizeof m->name);
        if (k == 3) strcpy(m->name, "m-3_the_longest_name_23"); /* AM_NAME_MAX - 1 characters */
        else snprintf(m->name, sizeof m->name, "m-%d_x", k);
        m->E = AM_P(1.2345678e6) * (am_param)(k + 1);
        m->density = AM_P(987.654321) + (am_param)k;
        m->poisson = AM_P(0.49) - AM_P(0.03) * (am_param)k;
        m->cte = AM_P(0.0123456) * (am_param)(k - 5);
        m->phase = AM_P(-3.14159265) + AM_P(0.3) * (am_param)k;
        m->mu_static = AM_P(0.1) * (am_param)k;
        m->mu_kinetic = AM_P(0.07) * (am_param)k;
        m->zeta_internal = AM_P(0.11) * (am_param)k;
        m->zeta_global = AM_P(0.013) * (am_param)k;
        m->zeta_collision = AM_P(0.17) * (am_param)k;
        for (int c = 0; c < 4; c++) m->color[c] = (uint8_t)(k * 16 + c * 50);
        m->fixed = k % 5 == 4;
    }
    int cells = lat_a.nx * lat_a.ny * lat_a.nz;
    for (int i = 0; i < cells; i++) lat_a.cell[i] = (uint8_t)((i * 7) % (AM_MAX_MATERIALS + 1));
    am_env env = am_default_env();
    env.gravity = AM_P(1.625);
    env.floor = 0;
    env.collisions = 0;
    env.temp_base = AM_P(-2.5);
    env.temp_amplitude = AM_P(17.25);
    env.period_steps = 777;
    env.dt_frac = AM_P(0.123);
    env.lift = AM_P(0.002);
    env.zeta_internal_scale = AM_P(0.5);
    env.zeta_global_scale = AM_P(2);
    round_trip(&lat_a, &env, "everything-volumetric");
    env.cte_mode = AM_CTE_LINEAR;
    round_trip(&lat_a, &env, "everything-linear");
    /* a constant temperature alone is VoxCAD's VaryTempEnabled 0 */
    env.temp_amplitude = AM_P(0);
    round_trip(&lat_a, &env, "constant-temperature");
    env.gravity = AM_P(0);
    round_trip(&lat_a, &env, "no-gravity");
}

/* the same robot and environment simulate to the same state after a round trip */
static void test_vxa_round_trip_simulates_the_same(void)
{
    static am_model m1, m2;
    static am_state s1, s2;
    char err[AM_ERR_MAX] = "";
    am_env env = am_default_env();
    long len;
    CHECK(am_scene_build(&lat_a, AM_MAX_DIM >= 6 ? "sphere:6" : "cube:3", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_vxa_format(&lat_a, &env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text, "s.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_build(&m1, &lat_a, &env, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_build(&m2, &lat_b, &info_b.env, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&m1, &s1);
    am_state_reset(&m2, &s2);
    s1.actuate = s2.actuate = 1;
    am_steps(&m1, &s1, 300);
    am_steps(&m2, &s2, 300);
    CHECK(am_state_hash(&m1, &s1) == am_state_hash(&m2, &s2), "hashes differ after 300 steps");
}

/* ---- VXA: reading what VoxCAD writes ----------------------------------------------------- */

static void test_vxa_voxcad_conventions(void)
{
    char err[AM_ERR_MAX] = "";
    const char* t =
        "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n"
        "<VXA Version=\"1.0\">\n"
        "<Simulator><Damping><BondDampingZ>0.5</BondDampingZ><ColDampingZ>0.25</ColDampingZ>"
        "<SlowDampingZ>1.7378e-005</SlowDampingZ></Damping><Collisions><SelfColEnabled>0</SelfColEnabled></Collisions>"
        "<Integration><DtFrac>0.2</DtFrac></Integration></Simulator>\n"
        "<Environment><Gravity><GravEnabled>1</GravEnabled><GravAcc>-9.81</GravAcc><FloorEnabled>1</FloorEnabled></Gravity>"
        "<Thermal><TempEnabled>1</TempEnabled><TempAmp>39</TempAmp><TempBase>25</TempBase><VaryTempEnabled>1</VaryTempEnabled>"
        "<TempPeriod>0.025</TempPeriod></Thermal></Environment>\n"
        "<VXC Version=\"0.93\"><Lattice><Lattice_Dim>0.001</Lattice_Dim></Lattice><Palette>\n"
        "<Material ID=\"1\"><MatType>0</MatType><Name>Active_+</Name><Display><Red>1</Red><Green>0.5</Green><Blue>0</Blue>"
        "<Alpha>1</Alpha></Display><Mechanical><MatModel>0</MatModel><Elastic_Mod>1e+007</Elastic_Mod><Density>1e+006</Density>"
        "<Poissons_Ratio>0.35</Poissons_Ratio><CTE>0.01</CTE><MaterialTempPhase>1.5</MaterialTempPhase><uStatic>1</uStatic>"
        "<uDynamic>0.5</uDynamic></Mechanical></Material>\n"
        "<Material ID=\"2\"><Name>Active_-</Name><Mechanical><Elastic_Mod>2e6</Elastic_Mod><Density>1000</Density></Mechanical>"
        "</Material>\n"
        "<Material ID=\"3\"><Name>Active_+</Name></Material>\n"
        "</Palette><Structure Compression=\"BASE64\"><X_Voxels>3</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>2</Z_Voxels><Data>\n"
        "<Layer><![CDATA[AQID]]></Layer><Layer>AAEA</Layer></Data></Structure></VXC>\n"
        "</VXA>\n";
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, t, "v.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_a.warnings == 0, "warnings: %s", info_a.warning);
    const am_material* m = &lat_a.palette.mat[0];
    CHECK(lat_a.palette.count == 3 && !strcmp(m->name, "Active__") && !strcmp(lat_a.palette.mat[1].name, "Active_-") &&
              !strcmp(lat_a.palette.mat[2].name, "Active___2"),
          "names '%s' '%s' '%s'", m->name, lat_a.palette.mat[1].name, lat_a.palette.mat[2].name);
    CHECK(m->E == AM_P(1e7) && m->density == AM_P(1e6) && m->poisson == AM_P(0.35) && m->cte == AM_P(0.01) &&
              m->phase == AM_P(1.5) && m->mu_static == AM_P(1) && m->mu_kinetic == AM_P(0.5),
          "mechanical values");
    CHECK(m->color[0] == 255 && m->color[1] == 128 && m->color[2] == 0 && m->color[3] == 255, "colour %d %d %d %d", m->color[0],
          m->color[1], m->color[2], m->color[3]);
    /* damping from <Simulator> on every material */
    for (int k = 0; k < 3; k++)
        CHECK(lat_a.palette.mat[k].zeta_internal == AM_P(0.5) && lat_a.palette.mat[k].zeta_collision == AM_P(0.25) &&
                  lat_a.palette.mat[k].zeta_global == AM_P(1.7378e-5),
              "damping of material %d", k + 1);
    /* the environment: gravity -GravAcc, linear CTE, old TempAmp is the peak (39 - 25 = 14) */
    const am_env* e = &info_a.env;
    CHECK(e->gravity == AM_P(9.81) && e->floor == 1 && e->collisions == 0 && e->cte_mode == AM_CTE_LINEAR, "gravity, floor, cte");
    CHECK(e->temp_amplitude == AM_P(14) && e->temp_base == AM_P(0) && e->dt_frac == AM_P(0.2), "amplitude %g", (double)e->temp_amplitude);
    CHECK(info_a.temp_period == 0.025 && !info_a.period_steps_given, "period %g", info_a.temp_period);
    CHECK(am_vxa_period_steps(info_a.temp_period, 5e-5) == 500 && am_vxa_period_steps(1e-9, 1e-3) == 2 &&
              am_vxa_period_steps(1, 0) == 2 && am_vxa_period_steps(1e12, 1e-3) == 10000000,
          "period in steps");
    /* BASE64 layers: bytes 1 2 3, then 0 1 0 */
    CHECK(lat_a.nx == 3 && lat_a.ny == 1 && lat_a.nz == 2 && lat_a.voxel_size == AM_P(0.001), "size");
    CHECK(lat_a.cell[0] == 1 && lat_a.cell[1] == 2 && lat_a.cell[2] == 3 && lat_a.cell[3] == 0 && lat_a.cell[4] == 1 &&
              lat_a.cell[5] == 0,
          "cells");
    /* a constant temperature (VaryTempEnabled 0) is an offset; TempEnabled 0 is none */
    const char* c2 = "<VXA><Environment><Thermal><TempEnabled>1</TempEnabled><TempAmplitude>7</TempAmplitude>"
                     "<VaryTempEnabled>0</VaryTempEnabled></Thermal><Gravity/></Environment><VXC><Palette><Material/></Palette>"
                     "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>1</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels>"
                     "<Data><Layer>1</Layer></Data></Structure></VXC></VXA>";
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, c2, "c.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_a.env.temp_base == AM_P(7) && info_a.env.temp_amplitude == AM_P(0) && info_a.temp_period == 0, "constant temperature");
    /* VoxCAD: inside <Gravity> a missing switch is off */
    CHECK(info_a.env.gravity == AM_P(0) && info_a.env.floor == 0, "empty <Gravity>");
    CHECK(!strcmp(lat_a.palette.mat[0].name, "material1") && lat_a.palette.mat[0].E == AM_P(1e6), "defaults of an empty material");
}

static void test_vxa_warnings(void)
{
    char err[AM_ERR_MAX] = "";
    const char* t = "<VXA Version=\"1.1\">\n"
                    "<GPU><HeapSize>0.5</HeapSize></GPU>\n"
                    "<Simulator><Integration><Integrator>1</Integrator><DtFrac>1.5</DtFrac></Integration></Simulator>\n"
                    "<Environment><Boundary_Conditions><NumBCs>1</NumBCs>\n<FRegion><X>0</X><Wobble/></FRegion></Boundary_Conditions>"
                    "</Environment>\n"
                    "<VXC><Lattice><X_Dim_Adj>0.5</X_Dim_Adj></Lattice><Palette><Material ID=\"7\">\n"
                    "<Mechanical><MatModel>1</MatModel><IsConductive>1</IsConductive></Mechanical></Material></Palette>\n"
                    "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>1</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels>"
                    "<Data><Layer>1</Layer></Data><BaseCiliaForce/></Structure></VXC>\n"
                    "</VXA>\n";
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, t, "w.vxa", err, sizeof err) == AM_OK, "%s", err);
    /* in line order, though <VXC> is read first */
    const char* want =
        "w.vxa:2: warning: unsupported tag <GPU> ignored\n"
        "w.vxa:3: warning: <Integrator> 1 not supported: amorph integrates with semi-implicit Euler\n"
        "w.vxa:3: warning: <DtFrac> 1.5 is above amorph's default step, kept with a margin below its stability limit: 0.9 "
        "used (amorph sim --dt-frac overrides)\n"
        "w.vxa:5: warning: unsupported tag <Wobble> ignored\n"
        "w.vxa:5: warning: <FRegion> holds no voxel (no filled cell touches its box): no effect\n"
        "w.vxa:6: warning: <X_Dim_Adj> 0.5 not supported (amorph lattices are cubic cells on a rectangular grid); 1 used\n"
        "w.vxa:6: warning: <Material ID=\"7\"> is material 1 of the palette: materials are numbered by their order, as in VoxCAD\n"
        "w.vxa:7: warning: unsupported tag <IsConductive> ignored\n"
        "w.vxa:7: warning: <MatModel> 1 (non-linear) not supported: material 1 is linear elastic here\n"
        "w.vxa:8: warning: unsupported tag <BaseCiliaForce> ignored\n";
    CHECK(!strcmp(info_a.warning, want) && info_a.warnings == 10, "%d warnings:\n%s", info_a.warnings, info_a.warning);
    /* those that change the motion, once each in reading order (VXC first); the integrator, the
     * step and the unknown <Wobble> do not */
    CHECK(!strcmp(info_a.differ, "X_Dim_Adj, MatModel, BaseCiliaForce"), "differ '%s'", info_a.differ);
    CHECK(info_a.env.dt_frac == am_default_env().dt_frac, "dt_frac kept");
    /* many warnings: all counted, the text stays within its buffer */
    long n = sprintf(big, "<VXA>");
    for (int i = 0; i < 500; i++) n += sprintf(big + n, "<Unknown%d/>", i);
    sprintf(big + n, "<VXC><Palette><Material/></Palette><Structure Compression=\"ASCII_READABLE\"><X_Voxels>1</X_Voxels>"
                     "<Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels><Data><Layer>1</Layer></Data></Structure></VXC></VXA>");
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, big, "m.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_a.warnings == 500 && strlen(info_a.warning) < sizeof info_a.warning, "%d warnings", info_a.warnings);
    CHECK(!strncmp(info_a.warning, "m.vxa:1: warning: unsupported tag <Unknown0> ignored\n", 52), "first warning");
}

/* ---- VXA: malformed files ---------------------------------------------------------------- */

/* a small VXA text, one piece per line: 1 <VXA>, 2 extra, 3 <VXC>, 4 <Palette>, 5 the material,
 * 6 </Palette>, 7 the structure's head, 8 the layer, 9 the tail, 10 </VXA> */
static const char* vxa(const char* extra, const char* material, const char* shead, const char* layer)
{
    snprintf(big, sizeof big, "<VXA Version=\"1.1\">\n%s\n<VXC Version=\"0.94\">\n<Palette>\n%s\n</Palette>\n%s\n%s\n"
                              "</Data></Structure></VXC>\n</VXA>\n",
             extra ? extra : "<!-- -->",
             material ? material
                      : "<Material ID=\"1\"><Name>m</Name><Mechanical><Elastic_Mod>1e6</Elastic_Mod><Density>1000</Density>"
                        "</Mechanical></Material>",
             shead ? shead
                   : "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>2</X_Voxels><Y_Voxels>1</Y_Voxels>"
                     "<Z_Voxels>1</Z_Voxels><Data>",
             layer ? layer : "<Layer><![CDATA[11]]></Layer>");
    return big;
}

static void expect_vxa(const char* t, am_status code, const char* want)
{
    char err[AM_ERR_MAX] = "";
    am_status st = am_vxa_parse(&lat_a, &info_a, &doc, t, "t.vxa", err, sizeof err);
    CHECK(st == code && strcmp(err, want) == 0, "status %d (want %d), message '%s' (want '%s')", st, code, err, want);
}

#define SH(x, y, z) "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>" x "</X_Voxels><Y_Voxels>" y "</Y_Voxels><Z_Voxels>" z \
                    "</Z_Voxels><Data>"
#define MAT(mech) "<Material><Mechanical>" mech "</Mechanical></Material>"

static void test_vxa_errors(void)
{
    char want[AM_ERR_MAX];
    expect_vxa(vxa(0, 0, 0, 0), AM_OK, "");
    expect_vxa("<?xml version=\"1.0\"?>\n<Robot/>\n", AM_ERR_PARSE, "t.vxa:2: not a VXA file: the root element is <Robot>, expected <VXA>");
    expect_vxa("<VXA>\n<Simulator/>\n</VXA>", AM_ERR_PARSE, "t.vxa:1: <VXA> has no <VXC> element (the robot)");
    expect_vxa("<VXA>\n<VXC/></VXA>", AM_ERR_PARSE, "t.vxa:2: <VXC> has no <Palette>");
    expect_vxa("<VXA><VXC Version=\"0.92\"/></VXA>", AM_ERR_PARSE, "t.vxa:1: <VXC Version=\"0.92\">: only versions 0.93 and 0.94 are read");
    expect_vxa("<VXA><VXC><Palette/></VXC></VXA>", AM_ERR_PARSE, "t.vxa:1: <Palette> has no <Material>");
    expect_vxa("<VXA><VXC><Palette><Material/></Palette></VXC></VXA>", AM_ERR_PARSE, "t.vxa:1: <VXC> has no <Structure>");
    expect_vxa("<VXA><VXC></VXC><VXC/></VXA>", AM_ERR_PARSE, "t.vxa:1: <VXC> given twice in <VXA> (first on line 1)");
    /* XML errors come through with their line */
    expect_vxa(vxa(0, 0, 0, "<Layer>11</Lay>"), AM_ERR_PARSE, "t.vxa:8: </Lay> does not close <Layer> (opened on line 8)");
    /* structure */
    /* ZLIB and QT_ZLIB layers (base64 of a zlib stream; QT_ZLIB with a 4-byte length first) */
#define ZH(comp) "<Structure Compression=\"" comp "\"><X_Voxels>2</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels><Data>"
    expect_vxa(vxa(0, 0, ZH("ZLIB"), "<Layer><![CDATA[eNpjZAQAAAUAAw==]]></Layer>"), AM_OK, "");
    CHECK(lat_a.cell[0] == 1 && lat_a.cell[1] == 1 && lat_a.nx == 2, "ZLIB layer cells %d %d", lat_a.cell[0], lat_a.cell[1]);
    expect_vxa(vxa(0, 0, ZH("QT_ZLIB"), "<Layer>AAAAAnjaY2QEAAAFAAM=</Layer>"), AM_OK, "");
    CHECK(lat_a.cell[0] == 1 && lat_a.cell[1] == 1, "QT_ZLIB layer cells");
    expect_vxa(vxa(0, 0, ZH("ZLIB"), "<Layer>eNpjZAQAAAUAAg==</Layer>"), AM_ERR_PARSE,
               "t.vxa:8: layer 0: bad Adler-32: the stream says 00050002, the data gives 00050003");
    expect_vxa(vxa(0, 0, ZH("ZLIB"), "<Layer>eJ1jZAQAAAUAAw==</Layer>"), AM_ERR_PARSE,
               "t.vxa:8: layer 0: bad zlib header: check bits 0x789d not a multiple of 31");
    expect_vxa(vxa(0, 0, ZH("ZLIB"), "<Layer>eNpjZGQEAAAJAAQ=</Layer>"), AM_ERR_PARSE,
               "t.vxa:8: layer 0 inflates to more than 2 cells (X_Voxels x Y_Voxels)");
    expect_vxa(vxa(0, 0, ZH("ZLIB"), "<Layer>eNpjZAQAAAU</Layer>"), AM_ERR_PARSE,
               "t.vxa:8: layer 0: the zlib stream ends before its Adler-32 checksum");
    expect_vxa(vxa(0, 0, ZH("ZLIB"), "<Layer>eN*</Layer>"), AM_ERR_PARSE, "t.vxa:8: layer 0: bad base64 data");
    expect_vxa(vxa(0, 0, ZH("QT_ZLIB"), "<Layer>AAAAA3jaY2QEAAAFAAM=</Layer>"), AM_ERR_PARSE,
               "t.vxa:8: layer 0 inflates to 2 bytes, its QT_ZLIB header says 3");
    expect_vxa(vxa(0, 0, ZH("QT_ZLIB"), "<Layer>AAA=</Layer>"), AM_ERR_PARSE,
               "t.vxa:8: layer 0: 2 bytes, too short for QT_ZLIB data (a length and a zlib stream)");
    expect_vxa(vxa(0, 0, "<Structure Compression=\"RLE\"><Data>", 0), AM_ERR_PARSE,
               "t.vxa:7: Compression=\"RLE\" is not supported (ASCII_READABLE, BASE64, ZLIB or QT_ZLIB)");
    expect_vxa(vxa(0, 0, "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>2</X_Voxels><Z_Voxels>1</Z_Voxels><Data>", 0),
               AM_ERR_PARSE, "t.vxa:7: <Structure> has no <Y_Voxels>");
    expect_vxa(vxa(0, 0, SH("2", "1", "x"), 0), AM_ERR_PARSE, "t.vxa:7: <Z_Voxels>: 'x' is not a whole number");
    expect_vxa(vxa(0, 0, SH("0", "1", "1"), 0), AM_ERR_RANGE, "t.vxa:7: <X_Voxels> 0 is outside 1..1000000000");
    snprintf(want, sizeof want, "t.vxa:7: <Y_Voxels> 99 exceeds the %s profile's %d cells per side", AM_PROFILE_NAME, AM_MAX_DIM);
    expect_vxa(vxa(0, 0, SH("2", "99", "1"), 0), AM_ERR_CAPACITY, want);
    expect_vxa(vxa(0, 0, 0, "<Layer>111</Layer>"), AM_ERR_PARSE, "t.vxa:8: layer 0 has 3 cells, expected 2 (X_Voxels x Y_Voxels = 2 x 1)");
    expect_vxa(vxa(0, 0, 0, "<Layer>1Z</Layer>"), AM_ERR_RANGE,
               "t.vxa:8: layer 0: cell 1 (x = 1, y = 0) is 'Z', not a material number 0..1 (written as '0' + number)");
    expect_vxa(vxa(0, 0, 0, "<Layer>12</Layer>"), AM_ERR_RANGE,
               "t.vxa:8: layer 0: cell 1 (x = 1, y = 0) is '2', not a material number 0..1 (written as '0' + number)");
    expect_vxa(vxa(0, 0, 0, "<Layer>11</Layer><Layer>11</Layer>"), AM_ERR_PARSE, "t.vxa:8: more <Layer> elements than Z_Voxels = 1");
    expect_vxa(vxa(0, 0, SH("2", "1", "2"), "<Layer>11</Layer>"), AM_ERR_PARSE, "t.vxa:7: <Data> has 1 <Layer> elements, Z_Voxels says 2");
    expect_vxa(vxa(0, 0, "<Structure><X_Voxels>2</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels><Data>", "<Layer>AQ*</Layer>"),
               AM_ERR_PARSE, "t.vxa:8: layer 0: bad base64 data");
    expect_vxa(vxa(0, 0, "<Structure><X_Voxels>2</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels><Data>", "<Layer>AQc=</Layer>"),
               AM_ERR_RANGE, "t.vxa:8: layer 0: cell 1 (x = 1, y = 0) is byte 7, not a material number 0..1");
    expect_vxa(vxa(0, 0, 0, "<Layer><b>11</b></Layer>"), AM_ERR_PARSE, "t.vxa:8: <Layer> must hold a value, not elements");
    /* materials */
    expect_vxa(vxa(0, "<Material><MatType>2</MatType></Material>", 0, 0), AM_ERR_PARSE,
               "t.vxa:5: material 1: MatType 2 (dither) is not supported: only single materials (MatType 0)");
    expect_vxa(vxa(0, MAT("<Elastic_Mod>0</Elastic_Mod>"), 0, 0), AM_ERR_RANGE, "t.vxa:5: <Elastic_Mod> 0 must be greater than 0");
    expect_vxa(vxa(0, MAT("<Density>-1</Density>"), 0, 0), AM_ERR_RANGE, "t.vxa:5: <Density> -1 must be greater than 0");
    expect_vxa(vxa(0, MAT("<Poissons_Ratio>0.75</Poissons_Ratio>"), 0, 0), AM_ERR_RANGE,
               "t.vxa:5: <Poissons_Ratio> 0.75 must be in [0, 0.5]");
    expect_vxa(vxa(0, MAT("<uStatic>-0.5</uStatic>"), 0, 0), AM_ERR_RANGE, "t.vxa:5: <uStatic> -0.5 must be in [0, 100] (the key mu_static's range)");
    expect_vxa(vxa(0, MAT("<uStatic>1267650600228229401496703205376</uStatic>"), 0, 0), AM_ERR_RANGE,
               "t.vxa:5: <uStatic> 1.2676506e+30 must be in [0, 100] (the key mu_static's range)");
    /* issue 46: one range per quantity, the configuration key's, wherever it is given */
    expect_vxa(vxa(0, MAT("<uDynamic>101</uDynamic>"), 0, 0), AM_ERR_RANGE, "t.vxa:5: <uDynamic> 101 must be in [0, 100] (the key mu_kinetic's range)");
    expect_vxa(vxa(0, MAT("<CTE>2</CTE>"), 0, 0), AM_ERR_RANGE, "t.vxa:5: <CTE> 2 must be in [-1, 1] (the key cte's range)");
    expect_vxa(vxa("<Amorph Version=\"1\"><ZetaInternalScale>1001</ZetaInternalScale></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <ZetaInternalScale> 1001 must be in [0, 1000] (the key damping_internal's range)");
    expect_vxa(vxa("<Amorph Version=\"1\"><ZetaGlobalScale>1e6</ZetaGlobalScale></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <ZetaGlobalScale> 1000000 must be in [0, 1000] (the key damping_global's range)");
    expect_vxa(vxa("<Amorph Version=\"1\"><TempOffset>-2e4</TempOffset></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <TempOffset> -20000 must be in [-10000, 10000] (the key temp_base's range)");
    expect_vxa(vxa("<Environment><Gravity><GravEnabled>1</GravEnabled><GravAcc>-2000</GravAcc></Gravity></Environment>", 0, 0, 0),
               AM_ERR_RANGE, "t.vxa:2: <GravAcc> -2000: gravity is at most 1000 m/s^2 (the key gravity's range)");
    expect_vxa(vxa("<Environment><Thermal><TempEnabled>1</TempEnabled><TempAmplitude>2e4</TempAmplitude></Thermal></Environment>", 0, 0, 0),
               AM_ERR_RANGE, "t.vxa:2: <Thermal>: the temperature amplitude 20000 is too large (at most 10000, the key amplitude's)");
    /* the cell edge: the configuration's voxel_size range (a subnormal one made NaN scales); 2^-140,
     * a float subnormal, reads and prints alike in every build */
    expect_vxa(vxa(0, 0, "<Lattice><Lattice_Dim>7.1746481373430634031294734590792e-43</Lattice_Dim></Lattice>" SH("2", "1", "1"), 0), AM_ERR_RANGE,
               "t.vxa:7: <Lattice_Dim> 7.17464814e-43 is too small (at least 1e-05 m)");
    expect_vxa(vxa(0, MAT("<CTE>abc</CTE>"), 0, 0), AM_ERR_PARSE, "t.vxa:5: <CTE>: 'abc' is not a finite number");
    expect_vxa(vxa(0, MAT("<CTE>nan</CTE>"), 0, 0), AM_ERR_PARSE, "t.vxa:5: <CTE>: 'nan' is not a finite number");
    expect_vxa(vxa(0, MAT("<CTE></CTE>"), 0, 0), AM_ERR_PARSE, "t.vxa:5: <CTE>: '' is not a finite number");
    /* a quoted value keeps the message on one line */
    expect_vxa(vxa(0, MAT("<CTE><![CDATA[1\n2]]></CTE>"), 0, 0), AM_ERR_PARSE, "t.vxa:5: <CTE>: '1\\n2' is not a finite number");
    expect_vxa(vxa(0, MAT("<Density>1e999</Density>"), 0, 0), AM_ERR_PARSE, "t.vxa:5: <Density>: '1e999' is not a finite number");
    expect_vxa(vxa(0, "<Material><Display><Red>1.5</Red></Display></Material>", 0, 0), AM_ERR_RANGE, "t.vxa:5: <Red> 1.5 must be in [0, 1]");
    expect_vxa(vxa(0, MAT("<CTE>1</CTE><CTE>2</CTE>"), 0, 0), AM_ERR_PARSE, "t.vxa:5: <CTE> given twice in <Mechanical> (first on line 5)");
    long n = 0;
    char mats[4096];
    for (int k = 0; k <= AM_MAX_MATERIALS; k++) n += snprintf(mats + n, sizeof mats - (size_t)n, "<Material/>");
    snprintf(want, sizeof want, "t.vxa:5: more than %d materials (the palette's capacity)", AM_MAX_MATERIALS);
    expect_vxa(vxa(0, mats, 0, 0), AM_ERR_CAPACITY, want);
    /* simulator and environment */
    expect_vxa(vxa("<Simulator><Integration><DtFrac>0</DtFrac></Integration></Simulator>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <DtFrac> 0 must be in [1e-06, 10] (the key dt_frac's range)");
    /* the key dt_frac's range, in <Simulator> and in <Amorph> alike (issue 46: 1e-20 ran for ever) */
    /* (the value as the build's am_param holds it: a float's 1e-20 is 9.99999968e-21, a double's 1e-20) */
    snprintf(want, sizeof want, "t.vxa:2: <DtFrac> %.9g must be in [1e-06, 10] (the key dt_frac's range)", (double)(am_param)1e-20);
    expect_vxa(vxa("<Simulator><Integration><DtFrac>1e-20</DtFrac></Integration></Simulator>", 0, 0, 0), AM_ERR_RANGE, want);
    expect_vxa(vxa("<Simulator><Integration><DtFrac>50</DtFrac></Integration></Simulator>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <DtFrac> 50 must be in [1e-06, 10] (the key dt_frac's range)");
    snprintf(want, sizeof want, "t.vxa:2: <DtFrac> %.9g must be in [1e-06, 10] (the key dt_frac's range)", (double)(am_param)1e-7);
    expect_vxa(vxa("<Amorph Version=\"1\"><DtFrac>1e-7</DtFrac></Amorph>", 0, 0, 0), AM_ERR_RANGE, want);
    /* the lines of the elements that set a key's value, for messages about the setting */
    expect_vxa(vxa("<Simulator><Integration><DtFrac>1e-6</DtFrac></Integration></Simulator>\n<Environment><Thermal>"
                   "<TempEnabled>1</TempEnabled><VaryTempEnabled>1</VaryTempEnabled>\n<TempPeriod>0.5</TempPeriod></Thermal>"
                   "</Environment>\n<Amorph Version=\"1\"><Evaluation><cycles>7</cycles></Evaluation></Amorph>",
                   0, 0, 0),
               AM_OK, "");
    int lines[3] = {-1, -1, -1};
    for (int i = 0; i < am_evo_key_count(); i++) {
        if (!strcmp(am_evo_key_name(i), "dt_frac")) lines[0] = info_a.key_line[i];
        if (!strcmp(am_evo_key_name(i), "period_s")) lines[1] = info_a.key_line[i];
        if (!strcmp(am_evo_key_name(i), "cycles")) lines[2] = info_a.key_line[i];
    }
    CHECK(lines[0] == 2 && lines[1] == 4 && lines[2] == 5 && info_a.env.dt_frac == AM_P(1e-6) && info_a.eval.cycles == 7,
          "key lines dt_frac %d period_s %d cycles %d (want 2, 4, 5)", lines[0], lines[1], lines[2]);
    expect_vxa(vxa("<Simulator><Damping><BondDampingZ>-1</BondDampingZ></Damping></Simulator>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <BondDampingZ> -1 must be 0 or more");
    expect_vxa(vxa("<Simulator><Collisions><SelfColEnabled>yes</SelfColEnabled></Collisions></Simulator>", 0, 0, 0), AM_ERR_PARSE,
               "t.vxa:2: <SelfColEnabled>: 'yes' is not 0 or 1");
    expect_vxa(vxa("<Environment><Gravity><GravEnabled>1</GravEnabled><GravAcc>9.81</GravAcc></Gravity></Environment>", 0, 0, 0),
               AM_ERR_RANGE, "t.vxa:2: <GravAcc> 9.81 points up: amorph's gravity pulls along -z (GravAcc <= 0)");
    expect_vxa(vxa("<Environment><Thermal><TempEnabled>1</TempEnabled><VaryTempEnabled>1</VaryTempEnabled>"
                   "<TempPeriod>0</TempPeriod></Thermal></Environment>", 0, 0, 0),
               AM_ERR_RANGE, "t.vxa:2: <TempPeriod> 0 must be greater than 0");
    expect_vxa(vxa("<Amorph Version=\"2\"/>", 0, 0, 0), AM_ERR_PARSE, "t.vxa:2: <Amorph Version=\"2\">: this build reads version 1");
    expect_vxa(vxa("<Amorph Version=\"1\"><CTEMode>cubic</CTEMode></Amorph>", 0, 0, 0), AM_ERR_PARSE,
               "t.vxa:2: <CTEMode>: 'cubic' is not volumetric or linear");
    expect_vxa(vxa("<Amorph Version=\"1\"><Material ID=\"2\"/></Amorph>", 0, 0, 0), AM_ERR_PARSE,
               "t.vxa:2: <Material ID=\"2\"> in <Amorph>: the ID must be a material number 1..1");
    /* one range per setting wherever it comes from (issue 31): the configuration's period_steps
     * (2..10^7), period_s (at most 10^4 s) and voxel_size (1e-5..10 m); a number past a long is
     * shown as written, not clamped; a value above a bound that has no upper text is "too large" */
    expect_vxa(vxa("<Amorph Version=\"1\"><PeriodSteps>1000000000</PeriodSteps></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <PeriodSteps> 1000000000 is outside 2..10000000");
    expect_vxa(vxa("<Amorph Version=\"1\"><PeriodSteps>99999999999999999999</PeriodSteps></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <PeriodSteps> 99999999999999999999 is outside 2..10000000");
    expect_vxa(vxa("<Environment><Thermal><TempEnabled>1</TempEnabled><VaryTempEnabled>1</VaryTempEnabled>"
                   "<TempPeriod>1e30</TempPeriod></Thermal></Environment>", 0, 0, 0),
               AM_ERR_RANGE, "t.vxa:2: <TempPeriod> 1e+30 is too large (at most 10000 s)");
    expect_vxa(vxa("<Amorph Version=\"1\"><Lift>1267650600228229401496703205376</Lift></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <Lift> 1.2676506e+30 is too large (at most 1e+30)");
    CHECK(am_vxa_period_steps(1e30, 1e-5) == 10000000, "a period in seconds is at most 10^7 steps");
    expect_vxa(vxa("<Amorph Version=\"1\"><PeriodSteps>0</PeriodSteps></Amorph>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <PeriodSteps> 0 is outside 2..10000000");
    /* a value too long for the reader's value buffer */
    memset(mats, '1', 1000);
    mats[1000] = 0;
    char longv[4200];
    snprintf(longv, sizeof longv, "<Material><Name>%s</Name></Material>", mats);
    expect_vxa(vxa(0, longv, 0, 0), AM_ERR_CAPACITY, "t.vxa:5: <Name>: its text is longer than 255 bytes");
}

/* a bad name or value shows cut and escaped (am_quote): one line of printable ASCII */
static void test_vxa_bad_tokens_quoted(void)
{
    static char t[2048];
    char err[AM_ERR_MAX], want[AM_ERR_MAX], tok[301];
    /* a newline (CDATA), DEL and UTF-8 in a value */
    expect_vxa(vxa(0, MAT("<CTE><![CDATA[1\n2\x7f\xc3\xa9]]></CTE>"), 0, 0), AM_ERR_PARSE,
               "t.vxa:5: <CTE>: '1\\n2\\x7f\\xc3\\xa9' is not a finite number");
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, vxa(0, MAT("<CTE><![CDATA[1\n2\x7f]]></CTE>"), 0, 0), "t.vxa", err, sizeof err) ==
                  AM_ERR_PARSE && printable_line(err), "'%s' is not one line of printable ASCII", err);
    /* character references to a tab and a single quote */
    expect_vxa(vxa("<Amorph Version=\"1\"><CTEMode>lin&#9;ear&apos;</CTEMode></Amorph>", 0, 0, 0), AM_ERR_PARSE,
               "t.vxa:2: <CTEMode>: 'lin\\tear\\'' is not volumetric or linear");
    expect_vxa(vxa("<Amorph Version=\"&#127;[31m\"/>", 0, 0, 0), AM_ERR_PARSE,
               "t.vxa:2: <Amorph Version=\"\\x7f[31m\">: this build reads version 1");
    /* element names: bytes from 0x80 up escaped */
    expect_vxa("<R\xc3\xa9" "bot/>", AM_ERR_PARSE,
               "t.vxa:1: not a VXA file: the root element is <R\\xc3\\xa9bot>, expected <VXA>");
    /* long values and names: their first 40 bytes and "..." */
    memset(tok, 'x', 300);
    tok[300] = 0;
    snprintf(t, sizeof t, "<Material><Mechanical><CTE>x&#10;%.250s</CTE></Mechanical></Material>", tok);
    snprintf(want, sizeof want, "t.vxa:5: <CTE>: 'x\\n%.38s...' is not a finite number", tok);
    expect_vxa(vxa(0, t, 0, 0), AM_ERR_PARSE, want);
    snprintf(t, sizeof t, "<VXA><\xc3\xa9%.200s/><VXC/></VXA>", tok);
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, t, "t.vxa", err, sizeof err) == AM_ERR_PARSE, "%s", err);
    snprintf(want, sizeof want, "t.vxa:1: warning: unsupported tag <\\xc3\\xa9%.38s...> ignored\n", tok);
    CHECK(!strcmp(info_a.warning, want), "warning '%s', want '%s'", info_a.warning, want);
    snprintf(t, sizeof t, "<a>\n<%s/></a>", tok);
    snprintf(want, sizeof want, "t.xml:2: element name '%.40s...' longer than 255 bytes", tok);
    expect_xml(t, AM_ERR_CAPACITY, want);
    snprintf(t, sizeof t, "<a %s=\"1\"/>", tok);
    snprintf(want, sizeof want, "t.xml:1: attribute name '%.40s...' longer than 255 bytes", tok);
    expect_xml(t, AM_ERR_CAPACITY, want);
}

static void test_vxa_format_errors(void)
{
    char err[AM_ERR_MAX] = "";
    long len = 7;
    am_env env = am_default_env();
    CHECK(am_scene_build(&lat_a, "cube:2", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_vxa_format(&lat_a, &env, 0, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG && len == 0 && text[0] == 0,
          "dt 0: %s", err);
    CHECK(am_vxa_format(&lat_a, &env, 1e-5, text, 100, &len, err, sizeof err) == AM_ERR_CAPACITY && text[0] == 0 &&
              !strcmp(err, "vxa format: the text needs more than the 100 bytes given"),
          "short buffer: %s", err);
    lat_a.cell[0] = 42;
    CHECK(am_vxa_format(&lat_a, &env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG &&
              !strcmp(err, "vxa format: cell 0 holds material id 42, the palette has 9"),
          "bad cell: %s", err);
    lat_a.cell[0] = 1;
    strcpy(lat_a.palette.mat[0].name, "bad name");
    CHECK(am_vxa_format(&lat_a, &env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "bad name");
    strcpy(lat_a.palette.mat[0].name, "ok");
    env.period_steps = 0;
    CHECK(am_vxa_format(&lat_a, &env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "bad environment");
    CHECK(am_vxa_parse(NULL, &info_a, &doc, "<VXA/>", "x", err, sizeof err) == AM_ERR_ARG, "no lattice");
    CHECK(am_vxa_sniff("\xEF\xBB\xBF \n<VXA>") && am_vxa_sniff("<?xml") && !am_vxa_sniff("amorph-lattice 1") && !am_vxa_sniff(""),
          "sniff");
    (void)msg;
}

/* every command loads a VXA robot through tool_robot_load: its period, given in seconds, must
 * become steps of the robot's own time step in every build (the fixed-point build once took the
 * step in model units and actuated with a period of 1 step); a period_steps setting wins over the
 * file, and --dt changes the step the period is counted in */
static void test_vxa_period_for_commands(void)
{
#if TOOL_VXA
    static tool_ctx ctx;
    static am_lattice lat;
    static am_model m;
    static am_xml_doc xdoc;
    static am_vxa_info info;
    static char vtext[1 << 16];
    char err[AM_ERR_MAX];
    long len = 0;
    CHECK(am_port_read_file("tests/data/voxcad_quadruped.vxa", vtext, sizeof vtext, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_vxa_parse(&lat, &info, &xdoc, vtext, "q", err, sizeof err) == AM_OK, "%s", err);
    const double period_s = info.temp_period;
    CHECK(period_s > 0 && !info.period_steps_given, "the quadruped has a period in seconds");

    tool_robot_args a;
    memset(&a, 0, sizeof a);
    a.name = "tests/data/voxcad_quadruped.vxa";
    am_robot r;
    CHECK(tool_robot_load(&ctx, &a, &lat, &r, err, sizeof err) == AM_OK, "%s", err);
    CHECK(r.lattice == &lat && r.env.cte_mode == AM_CTE_LINEAR, "read as a VXA file (linear CTE) into the caller's lattice");
    CHECK(am_model_build(&m, &lat, &r.env, err, sizeof err) == AM_OK, "%s", err);
    double dt = am_dt_si(&m, r.env.dt_frac);
    CHECK(fabs((double)r.env.period_steps * dt - period_s) <= dt, "period %d steps of %g s, the file says %g s", r.env.period_steps, dt, period_s);
    CHECK(r.env.period_steps > 100, "period %d steps", r.env.period_steps);

    /* --dt twice the step: half as many steps per period */
    const int steps1 = r.env.period_steps;
    a.dt_s = 2 * dt;
    CHECK(tool_robot_load(&ctx, &a, &lat, &r, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_build(&m, &lat, &r.env, err, sizeof err) == AM_OK, "%s", err);
    CHECK(fabs(am_dt_si(&m, r.env.dt_frac) / dt - 2) < 1e-3, "--dt %g s gives a step of %g s", 2 * dt, am_dt_si(&m, r.env.dt_frac));
    CHECK(abs(2 * r.env.period_steps - steps1) <= 2, "--dt doubled: %d steps, was %d", r.env.period_steps, steps1);

    /* a setting of period_steps wins over the file's seconds; later settings win over earlier ones */
    a.dt_s = 0;
    a.nset = 2;
    a.key[0] = "period_steps", a.val[0] = "77";
    a.key[1] = "gravity", a.val[1] = "0";
    CHECK(tool_robot_load(&ctx, &a, &lat, &r, err, sizeof err) == AM_OK, "%s", err);
    CHECK(r.env.period_steps == 77, "period_steps %d", r.env.period_steps);
    CHECK(r.env.gravity == AM_P(0), "gravity set by the flag");
#endif
}

/* settings over a robot file's own values: the environment and evaluation keys replace them, the
 * materials keys change the robot's palette (cte only where it actuates) */
static void test_robot_settings(void)
{
    static tool_ctx ctx;
    static am_lattice lat;
    char err[AM_ERR_MAX];
    tool_robot_args a;
    memset(&a, 0, sizeof a);
    a.name = "cube:3";
    a.is_scene = 1;
    const char* keys[] = {"mu_static", "mu_kinetic", "cte", "voxel_size", "cycles", "relax_max_steps", "floor", "cte_mode"};
    const char* vals[] = {"2.5", "0.7", "0.02", "0.005", "3", "50", "off", "linear"};
    for (int k = 0; k < 8; k++) a.key[k] = keys[k], a.val[k] = vals[k];
    a.nset = 8;
    am_robot r;
    CHECK(tool_robot_load(&ctx, &a, &lat, &r, err, sizeof err) == AM_OK, "%s", err);
    for (int m = 0; m < lat.palette.count; m++) {
        CHECK(lat.palette.mat[m].mu_static == AM_P(2.5) && lat.palette.mat[m].mu_kinetic == AM_P(0.7), "friction of %d", m);
    }
    CHECK(lat.voxel_size == AM_P(0.005), "voxel size");
    CHECK(r.eval.cycles == 3 && r.eval.relax_max_steps == 50 && r.eval.relax_min_steps <= 50, "evaluation settings");
    CHECK(r.env.floor == 0 && r.env.cte_mode == AM_CTE_LINEAR, "environment settings");
    /* cte changes the actuated materials only: compared with the scene loaded without settings */
    tool_robot_args b;
    memset(&b, 0, sizeof b);
    b.name = "cube:3", b.is_scene = 1;
    am_robot r0;
    static am_lattice lat0;
    CHECK(tool_robot_load(&ctx, &b, &lat0, &r0, err, sizeof err) == AM_OK, "%s", err);
    for (int m = 0; m < lat0.palette.count; m++)
        CHECK(lat0.palette.mat[m].cte != AM_P(0) ? lat.palette.mat[m].cte == AM_P(0.02) : lat.palette.mat[m].cte == AM_P(0),
              "cte of material %d follows its actuation", m);
}

/* the evaluation travels with the robot: am_vxa_format_robot writes every evaluation key into
 * <Amorph>'s <Evaluation>, am_vxa_parse and am_vxa_robot give it back field for field; a file
 * without one has the default evaluation; a bad value is refused with its line, an unknown key is
 * a warning */
static void test_vxa_evaluation(void)
{
    char err[AM_ERR_MAX] = "";
    long len = 0;
    CHECK(am_scene_build(&lat_a, "cube:3", err, sizeof err) == AM_OK, "%s", err);
    am_robot r;
    am_robot_init(&r, &lat_a, NULL);
    am_eval_def* e = &r.eval;
    e->cycles = 4, e->fitness = AM_FIT_3D, e->score = AM_SCORE_SUSTAINED, e->sustained_from = 2, e->dt_search = 1;
    e->relax_min_steps = 300, e->relax_max_steps = 20000, e->settle_speed = AM_P(3.25e-5), e->relax_dt_frac = AM_P(1.5);
    e->release_steps = 250;
    CHECK(am_vxa_format_robot(&r, 2.5e-5, text, sizeof text, &len, err, sizeof err) == AM_OK && len == (long)strlen(text), "%s", err);
    CHECK(strstr(text, "<Evaluation><cycles>4</cycles>") != NULL, "no <Evaluation> written");
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text, "e.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_b.warnings == 0, "warnings %d: %s", info_b.warnings, info_b.warning);
    am_robot r2;
    am_robot_init(&r2, &lat_b, NULL);
    CHECK(am_vxa_robot(&r2, &info_b, err, sizeof err) == AM_OK, "%s", err);
    const am_eval_def* g = &r2.eval;
    CHECK(g->cycles == 4 && g->fitness == AM_FIT_3D && g->score == AM_SCORE_SUSTAINED && g->sustained_from == 2 && g->dt_search == 1,
          "cycles %d fitness %d score %d sustained_from %d dt_search %d", g->cycles, g->fitness, g->score, g->sustained_from, g->dt_search);
    CHECK(g->relax_min_steps == 300 && g->relax_max_steps == 20000 && g->release_steps == 250, "relaxation steps %ld %ld %ld",
          g->relax_min_steps, g->relax_max_steps, g->release_steps);
    CHECK(g->settle_speed == AM_P(3.25e-5) && g->relax_dt_frac == AM_P(1.5), "settle_speed %.9g relax_dt_frac %.9g", (double)g->settle_speed,
          (double)g->relax_dt_frac);
    /* without an evaluation (am_vxa_format_layers, other programs' files): the default one */
    CHECK(am_vxa_format_layers(&lat_a, NULL, &r.env, 2.5e-5, text2, sizeof text2, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(strstr(text2, "<Evaluation>") == NULL, "an <Evaluation> without an evaluation");
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text2, "e.vxa", err, sizeof err) == AM_OK, "%s", err);
    am_eval_def d = am_default_eval();
    CHECK(info_b.eval.cycles == d.cycles && info_b.eval.relax_max_steps == d.relax_max_steps &&
              info_b.eval.relax_dt_frac == d.relax_dt_frac && info_b.eval.fitness == d.fitness,
          "a file without <Evaluation>: not the default evaluation");
    /* a bad value: its line and the configuration's own words; an unknown key: a warning */
    const char* ev = strstr(text, "<Evaluation>");
    int line = 1;
    for (const char* t = text; t < ev; t++) line += *t == '\n';
    char want[AM_ERR_MAX];
    snprintf(big, sizeof big, "%.*s<Evaluation><cycles>x</cycles></Evaluation>%s", (int)(ev - text), text, strstr(ev, "</Evaluation>") + 13);
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, big, "e.vxa", err, sizeof err) == AM_ERR_RANGE, "cycles x read");
    snprintf(want, sizeof want, "e.vxa:%d: <cycles> in <Evaluation>: ", line);
    CHECK(strncmp(err, want, strlen(want)) == 0 && strchr(err, '\n') == NULL, "message '%s' (want '%s...')", err, want);
    snprintf(big, sizeof big, "%.*s<Evaluation><release_steps>-1</release_steps></Evaluation>%s", (int)(ev - text), text,
             strstr(ev, "</Evaluation>") + 13);
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, big, "e.vxa", err, sizeof err) == AM_ERR_RANGE, "release_steps -1 read");
    snprintf(want, sizeof want, "e.vxa:%d: <release_steps> in <Evaluation>: ", line);
    CHECK(strncmp(err, want, strlen(want)) == 0, "message '%s' (want '%s...')", err, want);
    snprintf(big, sizeof big, "%.*s<Evaluation><cycles>3</cycles><population>5</population></Evaluation>%s", (int)(ev - text), text,
             strstr(ev, "</Evaluation>") + 13);
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, big, "e.vxa", err, sizeof err) == AM_OK, "%s", err);
    snprintf(want, sizeof want, "e.vxa:%d: warning: unsupported tag <population> ignored", line);
    CHECK(info_b.eval.cycles == 3 && info_b.warnings == 1 && strstr(info_b.warning, want) != NULL, "cycles %d, warnings '%s' (want '%s')",
          info_b.eval.cycles, info_b.warning, want);
}

/* ---- per-cell layers: evosoro's PhaseOffset, VoxCAD's boundary conditions --------------- */

static char ftext[1 << 16];
static am_model pm1, pm2;
static am_state ps1, ps2;
static am_layers lay;

static int read_data(const char* path)
{
    char err[AM_ERR_MAX];
    long len = 0;
    am_status st = am_port_read_file(path, ftext, sizeof ftext, &len, err, sizeof err);
    CHECK(st == AM_OK, "%s", err);
    return st == AM_OK;
}

/* the voxel of cell (x, y, z), -1 if none */
static int voxel_of(const am_model* m, int x, int y, int z)
{
    return m->cell_voxel[x + m->nx * (y + m->ny * z)];
}

/* a robot is one unit (am_robot): a VXA file's layers come with the robot that carries them and
 * its model is built from it alone; a robot loaded after it carries none */
static void test_robot_carries_its_layers(void)
{
#if !defined(AM_COMPACT)
    static tool_ctx ctx;
    static am_lattice lat, lat2;
    static am_model m1, m2;
    char err[AM_ERR_MAX];
    tool_robot_args a;
    memset(&a, 0, sizeof a);
    a.name = "tests/data/evosoro_phase.vxa";
    am_robot r;
    CHECK(tool_robot_load(&ctx, &a, &lat, &r, err, sizeof err) == AM_OK, "%s", err);
    CHECK(r.lattice == &lat && r.layers && r.layers->has_phase && r.layers->has_stiffness, "the file's layers with the robot");
    CHECK(am_robot_build(&m1, &r, err, sizeof err) == AM_OK && m1.voxel_phase == 1, "%s", err);
    CHECK(am_model_build_layers(&m2, &lat, &r.env, r.layers, err, sizeof err) == AM_OK && m2.dt_rec == m1.dt_rec, "%s", err);
    /* a scene loaded next carries no layers: its model has no phase per voxel */
    tool_robot_args b;
    memset(&b, 0, sizeof b);
    b.name = "cube:3", b.is_scene = 1;
    am_robot r2;
    CHECK(tool_robot_load(&ctx, &b, &lat2, &r2, err, sizeof err) == AM_OK, "%s", err);
    CHECK(!r2.layers || (!r2.layers->has_phase && !r2.layers->has_stiffness && !r2.layers->has_bc), "a scene with layers");
    CHECK(am_robot_build(&m2, &r2, err, sizeof err) == AM_OK && m2.voxel_phase == 0, "%s", err);
    /* am_vxa_robot refuses a file's layers when the robot has no room for them */
    static am_vxa_info info;
    static am_xml_doc xdoc;
    if (!read_data("tests/data/evosoro_phase.vxa")) return;
    CHECK(am_vxa_parse(&lat2, &info, &xdoc, ftext, "e.vxa", err, sizeof err) == AM_OK, "%s", err);
    am_robot_init(&r2, &lat2, NULL);
    CHECK(am_vxa_robot(&r2, &info, err, sizeof err) == AM_ERR_CAPACITY, "layers dropped silently");
#endif
}



static void test_vxa_phase_offset(void)
{
#if !defined(AM_COMPACT)
    char err[AM_ERR_MAX] = "";
    if (!read_data("tests/data/evosoro_phase.vxa")) return;
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, ftext, "e.vxa", err, sizeof err) == AM_OK, "%s", err);
    const am_layers* ly = &info_a.layers;
    CHECK(ly->has_phase && !ly->has_bc, "layers %d %d", ly->has_phase, ly->has_bc);
    CHECK(ly->phase[1] == AM_P(0.25) && ly->phase[3 + 4 * (2 + 3 * 1)] == AM_P(0.82) && ly->phase[0] == AM_P(0),
          "phases %g %g", (double)ly->phase[1], (double)ly->phase[3 + 4 * (2 + 3 * 1)]);
    CHECK(ly->has_stiffness && ly->stiffness[0] == AM_P(1e6) && ly->stiffness[23] == AM_P(1e6) && !strstr(info_a.warning, "Stiffness"),
          "the fixture's stiffness layer: %d %g\n%s", ly->has_stiffness, (double)ly->stiffness[0], info_a.warning);
    /* the voxels actuate with their own phases: after a quarter period the columns differ */
    lay = info_a.layers;
    am_env env = info_a.env;
    env.period_steps = 40;
    CHECK(am_model_build_layers(&pm1, &lat_a, &env, &lay, err, sizeof err) == AM_OK, "%s", err);
    CHECK(pm1.voxel_phase == 1, "voxel_phase");
    am_state_reset(&pm1, &ps1);
    ps1.actuate = 1;
    am_steps(&pm1, &ps1, 10);
    int v0 = voxel_of(&pm1, 0, 0, 0), v1 = voxel_of(&pm1, 1, 0, 0), v4 = voxel_of(&pm1, 0, 1, 0);
    CHECK(ps1.s[v0] != ps1.s[v1], "columns 0 and 1 actuate alike: %g %g", AM_TO_DOUBLE(ps1.s[v0]), AM_TO_DOUBLE(ps1.s[v1]));
    /* phases 0.25 apart, the last actuation at step 9 of 40: column 0 near sin(pi/2) (the largest
     * scale), column 1 a quarter period later, near sin(pi) */
    const double s0 = AM_TO_DOUBLE(ps1.s[v0]), s1 = AM_TO_DOUBLE(ps1.s[v1]);
    CHECK(s0 > s1 && s1 > 1 && s0 - 1 > 4 * (s1 - 1), "scales %g %g", s0, s1);
    CHECK(ps1.s[v4] != ps1.s[v0], "y = 1 has its own phase");
    /* every phase 0 simulates exactly as the per-material path does (same state, bit for bit) */
    lay.has_phase = 0;
    CHECK(am_model_build_layers(&pm2, &lat_a, &env, &lay, err, sizeof err) == AM_OK && pm2.voxel_phase == 0, "%s", err);
    memset(lay.phase, 0, sizeof lay.phase);
    lay.has_phase = 1;
    CHECK(am_model_build_layers(&pm1, &lat_a, &env, &lay, err, sizeof err) == AM_OK && pm1.voxel_phase == 1, "%s", err);
    am_state_reset(&pm1, &ps1);
    am_state_reset(&pm2, &ps2);
    ps1.actuate = ps2.actuate = 1;
    am_steps(&pm1, &ps1, 300);
    am_steps(&pm2, &ps2, 300);
    CHECK(am_state_hash(&pm1, &ps1) == am_state_hash(&pm2, &ps2) && !ps1.diverged, "zero phases differ from none");
    /* and the file's phases move it otherwise */
    CHECK(am_model_build_layers(&pm1, &lat_a, &env, &info_a.layers, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&pm1, &ps1);
    ps1.actuate = 1;
    am_steps(&pm1, &ps1, 300);
    CHECK(am_state_hash(&pm1, &ps1) != am_state_hash(&pm2, &ps2) && !ps1.diverged, "the phases changed nothing");

    /* round trip: the phases come back bit for bit, and a second write is the same text */
    long len = 0, len2 = 0;
    CHECK(am_vxa_format_layers(&lat_a, &info_a.layers, &info_a.env, 2.5e-5, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(strstr(text, "<PhaseOffset>") && strstr(text, "0.25, 0.5, 0.75, 0.01, 0.26"), "written phases");
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text, "p.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_b.layers.has_phase && am_lattice_equal(&lat_a, &lat_b), "phases back");
    int same = 1;
    for (int c = 0; c < 24; c++) same &= info_b.layers.phase[c] == info_a.layers.phase[c];
    CHECK(same, "phases differ after a round trip");
    CHECK(am_vxa_format_layers(&lat_b, &info_b.layers, &info_b.env, 2.5e-5, text2, sizeof text2, &len2, err, sizeof err) == AM_OK &&
              len == len2 && !strcmp(text, text2),
          "second write differs");
#endif
    /* malformed layers: one line each */
#define PH(layers) "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>2</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels>" \
                   "<Data><Layer>11</Layer></Data><PhaseOffset>" layers "</PhaseOffset>"
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH("<Layer>0.5, 0.25, </Layer>"));
    expect_vxa(big, AM_OK, "");
    CHECK(info_a.layers.has_phase && info_a.layers.phase[0] == AM_P(0.5) && info_a.layers.phase[1] == AM_P(0.25), "two phases");
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH("\n<Layer>0.5</Layer>"));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:3: <PhaseOffset> layer 0 has 1 values, expected 2 (X_Voxels x Y_Voxels)");
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH("\n<Layer>0.5, x1, 3</Layer>"));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:3: <PhaseOffset> layer 0: value 1 'x1' is not a finite number");
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH("\n<Layer>1,2,3</Layer>"));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:3: <PhaseOffset> layer 0 has more than 2 values (X_Voxels x Y_Voxels)");
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH("<Layer>1 2</Layer>\n<Layer>1 2</Layer>"));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:3: more <PhaseOffset> layers than Z_Voxels = 1");
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH(""));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:2: <PhaseOffset> has 0 <Layer> elements, Z_Voxels says 1");
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>", PH("<Layer>1 inf</Layer>"));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:2: <PhaseOffset> layer 0: value 1 'inf' is not a finite number");
    /* a number of 64 characters is one (too long) value, not two pieces read as two values
     * (issue 31: it was split at 63) */
    snprintf(big, sizeof big, "<VXA><VXC><Palette><Material/></Palette>\n%s</Structure></VXC></VXA>",
             PH("<Layer>0.25000000000000000000000000000000000000000000000000000000000001</Layer>"));
    expect_vxa(big, AM_ERR_PARSE, "t.vxa:2: <PhaseOffset> layer 0: value 0 is longer than 63 characters");
}

/* VoxCAD's cantilever: the clamp and the tip load come from its regions; the tip deflects as the
 * Euler-Bernoulli beam does. The beam's links are exact Euler-Bernoulli frame elements between
 * voxel centres (docs/physics.md), so for a point load P at the tip centre the deflection is
 * P l^3 / (3 E I) with l = 5 L from the clamped voxel's centre and E I = E L^4 / 12, 0.5 mm here
 * (1% of l: small enough for linear theory, whose geometric error is of order (w / l)^2, 1e-4).
 * The file's global damping gives the first bending mode a damping ratio of 0.3 and the run lasts
 * 16 / (0.3 omega_1), leaving e^-16 of the initial swing: the 1% tolerance is the one of
 * test_sim_step.c's cantilevers (float positions and the fixed-point force unit, 0.2% of this load). */
static void test_vxa_cantilever(void)
{
    char err[AM_ERR_MAX] = "";
    if (!read_data("tests/data/voxcad_cantilever.vxa")) return;
    CHECK(am_vxa_parse(&lat_a, &info_a, &doc, ftext, "c.vxa", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_a.warnings == 0, "%s", info_a.warning);
    const am_layers* ly = &info_a.layers;
    CHECK(ly->has_bc && ly->fixed[0] && !ly->fixed[1] && !ly->fixed[5] && ly->force[2][5] == AM_P(-0.1) && ly->force[2][4] == AM_P(0) &&
              ly->force[0][5] == AM_P(0),
          "regions: fixed %d %d, force %g", ly->fixed[0], ly->fixed[5], (double)ly->force[2][5]);
    const double L = 0.01, E = 1e7, rho = 1000, l = 5 * L, EI = E * L * L * L * L / 12, P = 0.1;
    const double omega1 = 1.8751 * 1.8751 * sqrt(EI / (rho * L * L * l * l * l * l));
    CHECK(am_model_build_layers(&pm1, &lat_a, &info_a.env, ly, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&pm1, &ps1);
    const int root = voxel_of(&pm1, 0, 0, 0), tip = voxel_of(&pm1, 5, 0, 0);
    CHECK(pm1.fixed[root] && !pm1.fixed[tip] && pm1.any_force, "model: clamp and load");
    long steps = (long)ceil(16.0 / (0.3 * omega1 * am_to_si(&pm1, ps1.dt, AM_DIM_TIME)));
    am_steps(&pm1, &ps1, steps);
    const double w = -am_to_si(&pm1, ps1.x[2][tip], AM_DIM_LENGTH), want = P * l * l * l / (3 * EI);
    printf("    cantilever: %ld steps, tip deflection %.6e m, Euler-Bernoulli %.6e m (error %.2e)\n", steps, w, want, w / want - 1);
    CHECK(!ps1.diverged, "diverged");
    NEAR_REL(w, want, 0.01);
    CHECK(ps1.x[0][root] == AM_R(0) && ps1.x[2][root] == AM_R(0) && ps1.q[0][root] == AM_R(1), "the clamp moved");
    /* without its regions the beam just sits (no gravity, no floor) */
    lay = info_a.layers;
    lay.has_bc = 0;
    CHECK(am_model_build_layers(&pm2, &lat_a, &info_a.env, &lay, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&pm2, &ps2);
    am_steps(&pm2, &ps2, 2000);
    CHECK(ps2.x[2][tip] == AM_R(0) && !pm2.fixed[root], "the beam moved without regions");
#if !defined(AM_COMPACT)
    /* round trip: each voxel with a condition is a region of its own cell */
    long len = 0;
    CHECK(am_vxa_format_layers(&lat_a, ly, &info_a.env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(strstr(text, "<NumBCs>2</NumBCs>") && strstr(text, "<DofFixed>63</DofFixed>") && strstr(text, "<ForceZ>-0.1</ForceZ>"),
          "written regions");
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text, "r.vxa", err, sizeof err) == AM_OK && info_b.warnings == 0, "%s %s", err,
          info_b.warning);
    int same = info_b.layers.has_bc;
    for (int c = 0; c < 6; c++)
        for (int k = 0; k < 3; k++) same &= info_b.layers.force[k][c] == ly->force[k][c] && info_b.layers.fixed[c] == ly->fixed[c];
    CHECK(same, "regions differ after a round trip");
#endif
    /* what is not supported: a warning each, in line order; a bad DofFixed: an error */
#define REG(body) "<Environment><Boundary_Conditions><NumBCs>1</NumBCs><FRegion>" body "</FRegion></Boundary_Conditions></Environment>"
    expect_vxa(vxa(REG("<PrimType>2</PrimType>"), 0, 0, 0), AM_OK, "");
    CHECK(!strcmp(info_a.warning, "t.vxa:2: warning: <FRegion> of PrimType 2 not supported (amorph reads box regions, PrimType 0): "
                                  "ignored\n"), "%s", info_a.warning);
    expect_vxa(vxa(REG("<dX>1</dX><dY>1</dY><dZ>1</dZ><DofFixed>7</DofFixed><TorqueZ>2</TorqueZ>"), 0, 0, 0), AM_OK, "");
    CHECK(!strcmp(info_a.warning, "t.vxa:2: warning: <DofFixed> 7 fixes some degrees of freedom only: amorph clamps all six of the "
                                  "region's voxels\nt.vxa:2: warning: <TorqueZ> 2 not supported (amorph's boundary conditions are "
                                  "clamps, forces and displacements): ignored\n"), "%s", info_a.warning);
    CHECK(info_a.layers.fixed[0] && info_a.layers.fixed[1], "clamped");
    expect_vxa(vxa(REG("<X>0.6</X><dX>0.1</dX><dY>1</dY><dZ>1</dZ><ForceX>1</ForceX>"), 0, 0, 0), AM_OK, "");
    CHECK(!info_a.warning[0] && info_a.layers.force[0][1] == AM_P(1) && info_a.layers.force[0][0] == AM_P(0),
          "a box inside the second cell, off its centre: %s", info_a.warning);
    expect_vxa(vxa(REG("<X>0.6</X><dX>0.1</dX><dY>1</dY><dZ>1</dZ><ForceX>1</ForceX>"), 0, 0, "<Layer><![CDATA[10]]></Layer>"), AM_OK, "");
    CHECK(!strcmp(info_a.warning, "t.vxa:2: warning: <FRegion> holds no voxel (no filled cell touches its box): no effect\n"),
          "%s", info_a.warning);
    expect_vxa(vxa(REG("<dX>1</dX><dY>1</dY><dZ>1</dZ><ForceZ>-3</ForceZ>"), 0, 0, 0), AM_OK, "");
    CHECK(info_a.layers.force[2][0] == AM_P(-1.5) && info_a.layers.force[2][1] == AM_P(-1.5), "the force shared by two voxels");
    expect_vxa(vxa(REG("<DofFixed>99</DofFixed>"), 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:2: <DofFixed> 99 is not a set of the six degrees of freedom (0..63)");
    expect_vxa(vxa(REG("<ForceX>abc</ForceX>"), 0, 0, 0), AM_ERR_PARSE, "t.vxa:2: <ForceX>: 'abc' is not a finite number");
    expect_vxa(vxa("<Environment><Fixed_Regions><NumFixed>1</NumFixed><FRegion><dX>0.5</dX><dY>1</dY><dZ>1</dZ></FRegion>"
                   "</Fixed_Regions></Environment>", 0, 0, 0), AM_OK, "");
    CHECK(info_a.layers.fixed[0] && !info_a.layers.fixed[1], "a region of <Fixed_Regions> is fixed");
}

/* VoxCAD's and Voxelyze's rule for a region: a voxel belongs to it when its cell touches the box
 * (not only when its centre lies inside); faces that only meet do not count. Each box below
 * selects other voxels by the centre rule (noted), so the rule is what is tested. */
#define REG1(body) "<Environment><Boundary_Conditions><NumBCs>1</NumBCs><FRegion>" body "</FRegion></Boundary_Conditions></Environment>"
static void test_vxa_regions_touch(void)
{
    const char* row = SH("4", "1", "1"); /* cells [0, 0.25], [0.25, 0.5], [0.5, 0.75], [0.75, 1] along x */
    /* VoxCAD's thin face region (its SampleSimulation): the first column (no centre inside) */
    expect_vxa(vxa(REG1("<X>0</X><dX>0.01</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed>"), 0, row, "<Layer>1111</Layer>"), AM_OK, "");
    CHECK(!info_a.warning[0] && info_a.layers.fixed[0] && !info_a.layers.fixed[1] && !info_a.layers.fixed[3], "thin face: %d %d\n%s",
          info_a.layers.fixed[0], info_a.layers.fixed[1], info_a.warning);
    /* and the last, its box given from its far corner (a negative extent) */
    expect_vxa(vxa(REG1("<X>1</X><dX>-0.01</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed>"), 0, row, "<Layer>1111</Layer>"), AM_OK, "");
    CHECK(info_a.layers.fixed[3] && !info_a.layers.fixed[2] && !info_a.layers.fixed[0], "far face");
    /* [0.3, 0.6] touches cells 1 and 2 (centre rule: cell 1 alone), which share its force */
    expect_vxa(vxa(REG1("<X>0.3</X><dX>0.3</dX><dY>1</dY><dZ>1</dZ><ForceX>2</ForceX>"), 0, row, "<Layer>1111</Layer>"), AM_OK, "");
    CHECK(info_a.layers.force[0][0] == AM_P(0) && info_a.layers.force[0][1] == AM_P(1) && info_a.layers.force[0][2] == AM_P(1) &&
              info_a.layers.force[0][3] == AM_P(0) && !info_a.layers.fixed[1],
          "forces %g %g %g %g", (double)info_a.layers.force[0][0], (double)info_a.layers.force[0][1], (double)info_a.layers.force[0][2],
          (double)info_a.layers.force[0][3]);
    /* exactly cell 1: its neighbours only meet the box at a face */
    expect_vxa(vxa(REG1("<X>0.25</X><dX>0.25</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed>"), 0, row, "<Layer>1111</Layer>"), AM_OK, "");
    CHECK(!info_a.layers.fixed[0] && info_a.layers.fixed[1] && !info_a.layers.fixed[2], "a cell's own box");
    /* evosoro's sticky floor: a thin slab at z = 0 clamps the bottom layer of a column */
    expect_vxa(vxa(REG1("<X>0</X><Y>0</Y><Z>0</Z><dX>1</dX><dY>1</dY><dZ>0.01</dZ><DofFixed>63</DofFixed>"), 0, SH("1", "1", "2"),
                   "<Layer>1</Layer><Layer>1</Layer>"),
               AM_OK, "");
    CHECK(!info_a.warning[0] && info_a.layers.fixed[0] && !info_a.layers.fixed[1], "sticky floor: %d %d", info_a.layers.fixed[0],
          info_a.layers.fixed[1]);
    /* a box in an empty cell holds no voxel */
    expect_vxa(vxa(REG1("<X>0.3</X><dX>0.1</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed>"), 0, row, "<Layer>1011</Layer>"), AM_OK, "");
    CHECK(!strcmp(info_a.warning, "t.vxa:2: warning: <FRegion> holds no voxel (no filled cell touches its box): no effect\n"), "%s",
          info_a.warning);
}

/* Poisson's ratio 0.5 (volvox's files, written for voxcraft-sim, which clamps it): the largest ratio
 * below 0.5, one warning; voxcraft-sim's material <Fixed>: its voxels are clamped */
static void test_vxa_poisson_and_fixed(void)
{
    char err[AM_ERR_MAX] = "";
    long len = 0;
    expect_vxa(vxa(0, MAT("<Elastic_Mod>1e6</Elastic_Mod><Density>1000</Density><Poissons_Ratio>0.5</Poissons_Ratio><Fixed>1</Fixed>"), 0,
                   0),
               AM_OK, "");
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
    const am_param below = nextafter(0.5, 0.0);
#else
    const am_param below = nextafterf(0.5f, 0.0f);
#endif
    const am_material* m = &lat_a.palette.mat[0];
    CHECK(m->poisson == below && m->fixed == 1, "poisson %.17g (want %.17g), fixed %d", (double)m->poisson, (double)below, m->fixed);
    CHECK(!strcmp(info_a.warning, "t.vxa:5: warning: <Poissons_Ratio> 0.5 (incompressible) is beyond amorph's model: the largest ratio "
                                  "below 0.5 used for material 1\n") &&
              info_a.warnings == 1 && !info_a.differ[0],
          "%s", info_a.warning);
    /* the model takes it, and the material's voxels hold under gravity */
    am_env env = info_a.env;
    env.gravity = AM_P(9.81);
    CHECK(am_model_build(&pm1, &lat_a, &env, err, sizeof err) == AM_OK, "%s", err);
    CHECK(pm1.fixed[0] && pm1.fixed[1], "fixed voxels %d %d", pm1.fixed[0], pm1.fixed[1]);
    am_state_reset(&pm1, &ps1);
    am_steps(&pm1, &ps1, 100);
    CHECK(ps1.x[2][0] == AM_R(0) && ps1.x[2][1] == AM_R(0) && !ps1.diverged, "a fixed voxel moved");
    /* written where voxcraft-sim reads it, and read back */
    CHECK(am_vxa_format(&lat_a, &info_a.env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(strstr(text, "<Fixed>1</Fixed>\n        </Mechanical>") != NULL, "no <Fixed> in <Mechanical>");
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text, "f.vxa", err, sizeof err) == AM_OK && am_lattice_equal(&lat_a, &lat_b) &&
              info_b.warnings == 0,
          "%s %s", err, info_b.warning);
    /* a free material writes no <Fixed> there (VoxCAD's files stay as they were) */
    expect_vxa(vxa(0, MAT("<Fixed>0</Fixed>"), 0, 0), AM_OK, "");
    CHECK(lat_a.palette.mat[0].fixed == 0, "<Fixed>0</Fixed>");
    CHECK(am_vxa_format(&lat_a, &info_a.env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_OK &&
              !strstr(text, "<Fixed>1</Fixed>\n        </Mechanical>") && !strstr(text, "<Fixed>0</Fixed>\n        </Mechanical>"),
          "%s", err);
}

/* evosoro's per-voxel stiffness: each voxel's modulus replaces its material's E; a link joins two
 * voxels' moduli as it joins two materials'; the time step follows the stiffest voxel */
#define STIFF(values)                                                                                                          \
    "<VXA Version=\"1.1\">\n<Environment><Gravity><GravEnabled>1</GravEnabled><FloorEnabled>1</FloorEnabled></Gravity>"       \
    "<Thermal><TempEnabled>1</TempEnabled><TempAmplitude>20</TempAmplitude><VaryTempEnabled>1</VaryTempEnabled></Thermal>"      \
    "</Environment>\n<VXC Version=\"0.94\"><Palette><Material><Name>m</Name><Mechanical><Elastic_Mod>1e6</Elastic_Mod>"        \
    "<Density>1000</Density><CTE>0.01</CTE></Mechanical></Material></Palette>\n"                                               \
    "<Structure Compression=\"ASCII_READABLE\"><X_Voxels>4</X_Voxels><Y_Voxels>1</Y_Voxels><Z_Voxels>1</Z_Voxels>"           \
    "<Data><Layer><![CDATA[1110]]></Layer></Data>\n<Stiffness><MinElasticMod>1000.0</MinElasticMod>"                          \
    "<MaxElasticMod>10000000.0</MaxElasticMod>\n<Layer><![CDATA[" values "]]></Layer></Stiffness></Structure></VXC></VXA>\n"
static void test_vxa_stiffness(void)
{
    char err[AM_ERR_MAX] = "";
    expect_vxa(STIFF("1000000, 4000000, 1000000, 0, "), AM_OK, "");
    CHECK(info_a.layers.has_stiffness && info_a.layers.stiffness[1] == AM_P(4e6) && info_a.layers.stiffness[3] == AM_P(0) &&
              info_a.warnings == 0,
          "layer %d %g\n%s", info_a.layers.has_stiffness, (double)info_a.layers.stiffness[1], info_a.warning);
    /* malformed: a voxel's value outside (0, 1e30] (an empty cell's 0 above is fine), a count, a word */
    expect_vxa(STIFF("1000000, 0, 1000000, 0"), AM_ERR_RANGE,
               "t.vxa:6: <Stiffness> layer 0: value 1 (x = 1, y = 0, a voxel) is 0 Pa: it must be greater than 0 and at most 1e+30");
    expect_vxa(STIFF("1000000, 1000000, 1000000"), AM_ERR_PARSE, "t.vxa:6: <Stiffness> layer 0 has 3 values, expected 4 (X_Voxels x Y_Voxels)");
    expect_vxa(STIFF("1000000, stiff, 1000000, 0"), AM_ERR_PARSE, "t.vxa:6: <Stiffness> layer 0: value 1 'stiff' is not a finite number");
#if defined(AM_COMPACT)
    expect_vxa(STIFF("1000000, 4000000, 1000000, 0"), AM_OK, "");
    CHECK(am_model_build_layers(&pm1, &lat_a, &info_a.env, &info_a.layers, err, sizeof err) == AM_ERR_CAPACITY &&
              !strcmp(err, "a stiffness per voxel: the board profile has no room for them (desktop profile only)"),
          "%s", err);
#else
    const double L = 0.001; /* VoxCAD's default Lattice_Dim */
    expect_vxa(STIFF("1000000, 4000000, 1000000, 0"), AM_OK, "");
    lay = info_a.layers;
    am_env env = info_a.env;
    env.period_steps = 50;
    CHECK(am_model_build_layers(&pm1, &lat_a, &env, &lay, err, sizeof err) == AM_OK, "%s", err);
    lay.has_stiffness = 0;
    CHECK(am_model_build_layers(&pm2, &lat_a, &env, &lay, err, sizeof err) == AM_OK, "%s", err);
    /* the stiff voxel's own constants (floor spring 2 E L), and its links: 2 E1 E2 / (E1 + E2) = 1.6e6 Pa */
    NEAR_REL(am_to_si(&pm1, pm1.k_floor[1], AM_DIM_STIFFNESS), 2 * 4e6 * L, 1e-5);
    NEAR_REL(am_to_si(&pm1, pm1.k_floor[0], AM_DIM_STIFFNESS), 2 * 1e6 * L, 1e-5);
    const int l01 = pm1.slot[0][0], l12 = pm1.slot[0][1];
    CHECK(l01 != pm1.nl && l12 != pm1.nl && pm1.lpos[l01] == 1 && pm1.lpos[l12] == 2, "links");
    NEAR_REL(am_to_si(&pm1, pm1.k_ax[l01], AM_DIM_FORCE), 1.6e6 * L * L, 1e-5);
    NEAR_REL(am_to_si(&pm1, pm1.k_ax[l12], AM_DIM_FORCE), 1.6e6 * L * L, 1e-5);
    NEAR_REL(am_to_si(&pm2, pm2.k_ax[l01], AM_DIM_FORCE), 1e6 * L * L, 1e-5);
    /* the stable step follows the stiffest voxel: its floor spring is 4 times as stiff, so dt_rec
     * halves (the material's 1e6 Pa would keep the step twice as long, and unstable) */
    NEAR_REL(am_to_si(&pm1, pm1.dt_rec, AM_DIM_TIME) / am_to_si(&pm2, pm2.dt_rec, AM_DIM_TIME), 0.5, 1e-5);
    CHECK(am_to_si(&pm1, pm1.max_speed, AM_DIM_VELOCITY) > am_to_si(&pm2, pm2.max_speed, AM_DIM_VELOCITY), "the speed bound");
    /* it moves otherwise than without the layer */
    am_state_reset(&pm1, &ps1);
    am_state_reset(&pm2, &ps2);
    ps1.actuate = ps2.actuate = 1;
    am_steps(&pm1, &ps1, 300);
    am_steps(&pm2, &ps2, 300);
    CHECK(!ps1.diverged && !ps2.diverged && am_state_hash(&pm1, &ps1) != am_state_hash(&pm2, &ps2), "the stiffness changed nothing");
    /* a layer equal to the material's modulus simulates bit for bit as no layer */
    for (int c = 0; c < 4; c++) lay.stiffness[c] = AM_P(1e6);
    lay.has_stiffness = 1;
    CHECK(am_model_build_layers(&pm1, &lat_a, &env, &lay, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&pm1, &ps1);
    ps1.actuate = 1;
    am_steps(&pm1, &ps1, 300);
    CHECK(am_state_hash(&pm1, &ps1) == am_state_hash(&pm2, &ps2), "a layer of the material's modulus differs from none");
    /* the model checks the layer too */
    lay.stiffness[2] = AM_P(-1);
    CHECK(am_model_build_layers(&pm1, &lat_a, &env, &lay, err, sizeof err) == AM_ERR_RANGE &&
              !strcmp(err, "cell 2: its stiffness must be a positive number of Pa"),
          "%s", err);
    /* round trip: evosoro's <Stiffness> layers, bit for bit */
    long len = 0;
    CHECK(am_vxa_format_layers(&lat_a, &info_a.layers, &info_a.env, 1e-5, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(strstr(text, "<Stiffness>\n        <Layer><![CDATA[1000000, 4000000, 1000000, 0]]></Layer>") != NULL, "written stiffness");
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, text, "s.vxa", err, sizeof err) == AM_OK && info_b.warnings == 0, "%s %s", err,
          info_b.warning);
    int same = info_b.layers.has_stiffness;
    for (int c = 0; c < 4; c++) same &= info_b.layers.stiffness[c] == info_a.layers.stiffness[c];
    CHECK(same, "stiffnesses differ after a round trip");
#endif
}

/* the ignored items that change the motion, named once for the one-line summary */
static void test_vxa_differ(void)
{
    expect_vxa(vxa("<Simulator><Features><MaxVelLimitEnabled>0</MaxVelLimitEnabled><VolumeEffectsEnabled>1</VolumeEffectsEnabled>"
                   "</Features><EquilibriumMode><EquilibriumModeEnabled>0</EquilibriumModeEnabled></EquilibriumMode></Simulator>\n"
                   "<Environment><FluidEnvironment>1</FluidEnvironment><AggregateDragCoefficient>750</AggregateDragCoefficient>"
                   "</Environment>",
                   0, 0, 0),
               AM_OK, "");
    CHECK(!strcmp(info_a.differ, "VolumeEffectsEnabled, FluidEnvironment") && info_a.warnings == 4, "differ '%s'\n%s", info_a.differ,
          info_a.warning);
    /* the same tags switched off: warnings, and nothing that changes the motion */
    expect_vxa(vxa("<Simulator><Features><VolumeEffectsEnabled>0</VolumeEffectsEnabled></Features></Simulator>\n"
                   "<Environment><FluidEnvironment>0</FluidEnvironment></Environment>",
                   0, 0, 0),
               AM_OK, "");
    CHECK(!info_a.differ[0] && info_a.warnings == 2, "differ '%s'", info_a.differ);
    /* a region's torque, twice: named once */
    expect_vxa(vxa("<Environment><Boundary_Conditions><NumBCs>2</NumBCs><FRegion><dX>1</dX><dY>1</dY><dZ>1</dZ><TorqueX>1</TorqueX>"
                   "</FRegion><FRegion><dX>1</dX><dY>1</dY><dZ>1</dZ><TorqueX>2</TorqueX></FRegion></Boundary_Conditions></Environment>",
                   0, 0, 0),
               AM_OK, "");
    CHECK(!strcmp(info_a.differ, "TorqueX") && info_a.warnings == 2, "differ '%s'", info_a.differ);
}

/* VoxCAD's prescribed displacements: a region that fixes a degree of freedom moves its voxels by
 * <DisplaceX..Z> (m) there (the clamped cell's slot of am_layers.force), at once: am_state_reset puts
 * it in the state and the clamp holds it; a force on a clamped cell is dropped, a displacement of a
 * free degree of freedom is a warning (VoxCAD ignores it), one past AM_MAX_DISPLACE voxel edges an
 * error */
static void test_vxa_displace(void)
{
    static am_model dm;
    static am_state ds;
    char err[AM_ERR_MAX] = "";
    expect_vxa(vxa(REG("<X>0.5</X><dX>0.5</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed><ForceX>3</ForceX><DisplaceX>1e-4</DisplaceX>"
                       "<DisplaceZ>-2e-5</DisplaceZ>"), 0, 0, 0), AM_OK, "");
    const am_layers* ly = &info_a.layers;
    CHECK(!info_a.warning[0] && !info_a.differ[0] && !ly->fixed[0] && ly->fixed[1] && ly->force[0][1] == AM_P(1e-4) &&
          ly->force[1][1] == AM_P(0) && ly->force[2][1] == AM_P(-2e-5) && ly->force[0][0] == AM_P(0),
          "displaced: fixed %d %d, slot %g %g %g\n%s", ly->fixed[0], ly->fixed[1], (double)ly->force[0][1], (double)ly->force[1][1],
          (double)ly->force[2][1], info_a.warning);
#if !defined(AM_COMPACT)
    CHECK(am_model_build_layers(&dm, &lat_a, &info_a.env, ly, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&dm, &ds);
    const double x1 = am_to_si(&dm, ds.x[0][1], AM_DIM_LENGTH), z1 = am_to_si(&dm, ds.x[2][1], AM_DIM_LENGTH);
    CHECK(fabs(x1 - 1e-4) < 1e-9 && fabs(z1 + 2e-5) < 1e-9 && ds.x[0][0] == AM_R(0) && ds.fext[0][1] == AM_R(0), "reset: x %g %g, fext %g", x1,
          z1, am_to_si(&dm, ds.fext[0][1], AM_DIM_FORCE));
    for (int k = 0; k < 50; k++) am_step(&dm, &ds);
    CHECK(am_to_si(&dm, ds.x[0][1], AM_DIM_LENGTH) == x1 && am_to_si(&dm, ds.x[0][0], AM_DIM_LENGTH) > 1e-7,
          "after 50 steps: the clamp %g, the free voxel pulled %g", am_to_si(&dm, ds.x[0][1], AM_DIM_LENGTH), am_to_si(&dm, ds.x[0][0], AM_DIM_LENGTH));
#endif
    /* only the fixed degrees of freedom move (DofFixed 1: x); y is free: VoxCAD ignores its displacement */
    expect_vxa(vxa(REG("<dX>1</dX><dY>1</dY><dZ>1</dZ><DofFixed>1</DofFixed><DisplaceX>1e-4</DisplaceX><DisplaceY>5e-5</DisplaceY>"), 0, 0, 0),
               AM_OK, "");
    CHECK(ly->force[0][0] == AM_P(1e-4) && ly->force[1][0] == AM_P(0) &&
          strstr(info_a.warning, "t.vxa:2: warning: <DisplaceY> 5e-05 of a free degree of freedom (DofFixed 1): ignored, as VoxCAD ignores it"),
          "free y: %g\n%s", (double)ly->force[1][0], info_a.warning);
    /* a force, then a clamp over it: the clamp's displacement (0) */
    expect_vxa(vxa("<Environment><Boundary_Conditions><NumBCs>2</NumBCs><FRegion><dX>1</dX><dY>1</dY><dZ>1</dZ><ForceX>2</ForceX></FRegion>"
                   "<FRegion><dX>0.5</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed></FRegion></Boundary_Conditions></Environment>", 0, 0, 0),
               AM_OK, "");
    CHECK(ly->fixed[0] && ly->force[0][0] == AM_P(0) && !ly->fixed[1] && ly->force[0][1] == AM_P(1), "force then clamp: %g %g",
          (double)ly->force[0][0], (double)ly->force[0][1]);
    /* more than AM_MAX_DISPLACE voxel edges (Lattice_Dim 0.001 m by default) */
    expect_vxa(vxa(REG("<dX>1</dX><dY>1</dY><dZ>1</dZ><DofFixed>63</DofFixed>\n<DisplaceZ>0.06</DisplaceZ>"), 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:3: <DisplaceZ> 0.06 m is more than 50 voxel edges (Lattice_Dim 0.001 m)");
}

/* VoxCAD's <StopCondition> and evosoro's <InitCmTime> as the evaluation's cycles and least
 * relaxation (am_vxa_stop_settings), each kind of stop; a flag's value kept; a stop without a
 * counterpart warned and named; a body above empty layers starts there (env.lift) */
static void test_vxa_stop_and_place(void)
{
    char note[640], err[AM_ERR_MAX] = "";
    am_eval_def ev = am_default_eval();
    const double dt = 5e-5; /* 500 steps a 0.025 s period */
    /* seconds: 1 s less InitCmTime 0.25 s = 30 periods; InitCmTime 0.25 s = 5556 steps of 4.5e-5 s */
    expect_vxa(vxa("<Simulator><StopCondition><StopConditionType>2</StopConditionType><StopConditionValue>1</StopConditionValue>"
                   "<InitCmTime>0.25</InitCmTime></StopCondition></Simulator>\n"
                   "<Environment><Thermal><TempEnabled>1</TempEnabled><VaryTempEnabled>1</VaryTempEnabled><TempPeriod>0.025</TempPeriod>"
                   "</Thermal></Environment>", 0, 0, 0), AM_OK, "");
    CHECK(info_a.stop_type == 2 && info_a.stop_value == 1 && info_a.init_cm_time == 0.25 && info_a.stop_line == 2 && !info_a.warnings,
          "stop %d %g %g line %d, %s", info_a.stop_type, info_a.stop_value, info_a.init_cm_time, info_a.stop_line, info_a.warning);
    CHECK(am_vxa_stop_settings(&info_a, dt, 4.5e-5, 500, 0, &ev, note, sizeof note, err, sizeof err) == AM_OK, "%s", err);
    CHECK(ev.cycles == 30 && ev.relax_min_steps == 5556 && ev.relax_max_steps == 40000 + 5556, "cycles %d, relax %ld..%ld", ev.cycles,
          ev.relax_min_steps, ev.relax_max_steps);
    CHECK(!strncmp(note, "cycles = 30 (<StopCondition> 1 s less <InitCmTime> 0.25 s: 30 periods of 0.025 s), relax_min_steps = 5556", 102),
          "note '%s'", note);
    /* flags keep theirs */
    ev = am_default_eval();
    ev.cycles = 3;
    CHECK(am_vxa_stop_settings(&info_a, dt, 4.5e-5, 500, AM_VXA_KEEP_CYCLES | AM_VXA_KEEP_RELAX, &ev, note, sizeof note, err, sizeof err) == AM_OK &&
          ev.cycles == 3 && ev.relax_min_steps == 200 && !note[0], "kept: cycles %d, note '%s'", ev.cycles, note);
    /* time steps (of amorph's step): 12345 steps are 24.69 periods of 500 steps: 25 */
    expect_vxa(vxa("<Simulator><StopCondition><StopConditionType>1</StopConditionType><StopConditionValue>12345</StopConditionValue>"
                   "</StopCondition></Simulator>", 0, 0, 0), AM_OK, "");
    ev = am_default_eval();
    CHECK(am_vxa_stop_settings(&info_a, dt, 4.5e-5, 500, 0, &ev, note, sizeof note, err, sizeof err) == AM_OK && ev.cycles == 25 &&
          ev.relax_min_steps == 200 && strstr(note, "24.69 periods of 0.025 s, amorph runs whole ones)"), "steps: %d, '%s'", ev.cycles, note);
    /* periods of TempPeriod 0.05 s at a period of 0.025 s: 7 periods are 14 cycles; no period (a constant temperature): nothing */
    expect_vxa(vxa("<Simulator><StopCondition><StopConditionType>3</StopConditionType><StopConditionValue>7</StopConditionValue>"
                   "</StopCondition></Simulator>\n<Environment><Thermal><TempEnabled>1</TempEnabled><VaryTempEnabled>1</VaryTempEnabled>"
                   "<TempPeriod>0.05</TempPeriod></Thermal></Environment>", 0, 0, 0), AM_OK, "");
    ev = am_default_eval();
    CHECK(am_vxa_stop_settings(&info_a, dt, 4.5e-5, 500, 0, &ev, note, sizeof note, err, sizeof err) == AM_OK && ev.cycles == 14, "periods: %d",
          ev.cycles);
    expect_vxa(vxa("<Simulator><StopCondition><StopConditionType>3</StopConditionType><StopConditionValue>7</StopConditionValue>"
                   "</StopCondition></Simulator>", 0, 0, 0), AM_OK, "");
    ev = am_default_eval();
    CHECK(am_vxa_stop_settings(&info_a, dt, 4.5e-5, 500, 0, &ev, note, sizeof note, err, sizeof err) == AM_OK && ev.cycles == 10 && !note[0],
          "periods of no period: %d '%s'", ev.cycles, note);
    /* a stop without a counterpart: a warning, named in the summary with the setting; nothing mapped */
    expect_vxa(vxa("<Simulator><StopCondition><StopConditionType>5</StopConditionType><StopConditionValue>1</StopConditionValue>"
                   "</StopCondition></Simulator>", 0, 0, 0), AM_OK, "");
    CHECK(info_a.stop_type == -1 && !strcmp(info_a.differ, "StopConditionType 5 (cycles = 10 run: --cycles N)") && info_a.warnings == 1 &&
          strstr(info_a.warning, "t.vxa:2: warning: <StopConditionType> 5 (until the kinetic energy is below a threshold) is not simulated"),
          "type 5: '%s' %s", info_a.differ, info_a.warning);
    /* a negative time: an error with its line */
    expect_vxa(vxa("<Simulator><StopCondition>\n<InitCmTime>-1</InitCmTime></StopCondition></Simulator>", 0, 0, 0), AM_ERR_RANGE,
               "t.vxa:3: <InitCmTime> -1 must be 0 or more");
    /* placement: a body over two empty layers starts two layers up; on the floor, at 0 */
    expect_vxa(vxa(0, 0, SH("2", "1", "3"), "<Layer>00</Layer><Layer>00</Layer><Layer>11</Layer>"), AM_OK, "");
    CHECK(info_a.env.lift == AM_P(0.002), "lift %g", (double)info_a.env.lift);
    expect_vxa(vxa(0, 0, SH("2", "1", "2"), "<Layer>11</Layer><Layer>00</Layer>"), AM_OK, "");
    CHECK(info_a.env.lift == AM_P(0), "lift %g on the floor", (double)info_a.env.lift);
}

/* voxcraft's VXD over a base VXA: replaced and added elements, warnings in order (base, then VXD),
 * messages naming the VXD file, and a VXD alone refused with what to pass instead */
static void test_vxa_vxd(void)
{
    static am_xml_doc vdoc;
    static char btext[1 << 14];
    char err[AM_ERR_MAX] = "";
    long len = 0;
    CHECK(am_port_read_file("tests/data/voxcraft/base.vxa", btext, sizeof btext, &len, err, sizeof err) == AM_OK, "%s", err);
    if (!read_data("tests/data/voxcraft/robot.vxd")) return;
    CHECK(am_vxa_parse_vxd(&lat_a, &info_a, &doc, btext, "base.vxa", &vdoc, ftext, "robot.vxd", err, sizeof err) == AM_OK, "%s", err);
    CHECK(lat_a.nx == 4 && lat_a.ny == 3 && lat_a.nz == 2 && lat_a.cell[1] == 2 && lat_a.cell[12] == 0 && lat_a.cell[13] == 1,
          "the VXD's structure: %d x %d x %d", lat_a.nx, lat_a.ny, lat_a.nz);
    CHECK(info_a.layers.has_phase && info_a.layers.phase[3] == AM_P(0.75), "the VXD's phases");
    CHECK(info_a.env.temp_amplitude == AM_P(30) && lat_a.palette.count == 2 && !strcmp(lat_a.palette.mat[1].name, "Active"),
          "the VXD's thermal, the base's palette");
    const char* want = "base.vxa:5: warning: unsupported tag <GPU> ignored\n"
                       "base.vxa:9: warning: unsupported tag <EnableExpansion> ignored\n"
                       "robot.vxd:25: warning: unsupported tag <RecordHistory> ignored\n"
                       "robot.vxd:28: warning: <Material replace=\"VXA.VXC.Palette.Material\">: amorph reads no element at that path: "
                       "ignored\n"
                       "robot.vxd:31: warning: unsupported tag <RawPrint> ignored (amorph reads the elements of a VXD that "
                       "replace=\"VXA...\" a part of the base)\n";
    CHECK(!strcmp(info_a.warning, want), "warnings:\n%s", info_a.warning);
    /* the base alone: its own 1-voxel structure */
    CHECK(am_vxa_parse(&lat_b, &info_b, &doc, btext, "base.vxa", err, sizeof err) == AM_OK && am_lattice_count(&lat_b) == 1, "%s", err);
    /* an element the base lacks is added; an error in the VXD names the VXD's line */
    const char* v2 = "<VXD>\n<Collisions replace=\"VXA.Simulator.Collisions\"><SelfColEnabled>0</SelfColEnabled></Collisions>\n"
                     "<Amorph replace=\"VXA.Amorph\" Version=\"1\"><PeriodSteps>123</PeriodSteps></Amorph>\n</VXD>\n";
    CHECK(am_vxa_parse_vxd(&lat_b, &info_b, &doc, btext, "base.vxa", &vdoc, v2, "v2.vxd", err, sizeof err) == AM_OK, "%s", err);
    CHECK(info_b.env.collisions == 0 && info_b.env.period_steps == 123 && info_b.period_steps_given, "replaced and added elements");
    const char* v3 = "<VXD>\n\n<Structure replace=\"VXA.VXC.Structure\"><X_Voxels>0</X_Voxels></Structure></VXD>";
    CHECK(am_vxa_parse_vxd(&lat_b, &info_b, &doc, btext, "base.vxa", &vdoc, v3, "v3.vxd", err, sizeof err) == AM_ERR_RANGE &&
              !strcmp(err, "v3.vxd:3: <X_Voxels> 0 is outside 1..1000000000"),
          "%s", err);
    CHECK(am_vxa_parse_vxd(&lat_b, &info_b, &doc, btext, "base.vxa", &vdoc, "<VXA/>", "v4.vxd", err, sizeof err) == AM_ERR_PARSE &&
              !strcmp(err, "v4.vxd:1: not a VXD file: the root element is <VXA>, expected <VXD>"),
          "%s", err);
    /* a replace path too long to read is shown by its start (issue 31: it was shown as "") */
    static char v6[400];
    snprintf(v6, sizeof v6, "<VXD>\n<A replace=\"VXA.%0150d\"/></VXD>", 7);
    CHECK(am_vxa_parse_vxd(&lat_b, &info_b, &doc, btext, "base.vxa", &vdoc, v6, "v6.vxd", err, sizeof err) == AM_OK &&
              strstr(info_b.warning, "v6.vxd:2: warning: <A replace=\"VXA.000000000000000000000000000000000000...\">: not a path"),
          "%s", info_b.warning);
    const char* v5 = "<VXD><A replace=\"VXA.B\"/>\n<C replace=\"VXA.B\"/></VXD>";
    CHECK(am_vxa_parse_vxd(&lat_b, &info_b, &doc, btext, "base.vxa", &vdoc, v5, "v5.vxd", err, sizeof err) == AM_ERR_PARSE &&
              !strcmp(err, "v5.vxd:2: replace=\"VXA.B\" given twice (first on line 1)"),
          "%s", err);
    expect_vxa("<VXD>\n<Structure replace=\"VXA.VXC.Structure\"/></VXD>", AM_ERR_PARSE,
               "t.vxa:1: a VXD file (voxcraft-sim's robot: elements that replace parts of a base VXA file) is not read alone: give its "
               "base VXA file first, then the VXD (amorph sim BASE.vxa ROBOT.vxd, or a folder holding base.vxa and one .vxd)");
}

/* the reader on damaged files: every prefix of a file with every kind of layer (ZLIB cells,
 * PhaseOffset reals, regions), and random byte changes, each read cleanly (AM_OK, or one line
 * "t.vxa:LINE: problem"; never a crash: asan and valgrind run it) */
static void test_vxa_noise(void)
{
    static char src[1 << 14], buf[1 << 14];
    char err[AM_ERR_MAX];
    long n = 0;
    int bad = 0, ok = 0, refused = 0;
    static const char* const files[] = {"tests/data/voxcad_cantilever.vxa", "tests/data/evosoro_phase.vxa"};
    uint64_t r = 0x2545F4914F6CDD1Dull;
    for (int f = 0; f < 2; f++) {
        CHECK(am_port_read_file(files[f], src, sizeof src, &n, err, sizeof err) == AM_OK, "%s", err);
        const long step = test_quick() ? 97 : 7;
        for (long cut = 0; cut < n; cut += step) {
            memcpy(buf, src, (size_t)cut);
            buf[cut] = 0;
            am_status st = am_vxa_parse(&lat_b, &info_b, &doc, buf, "t.vxa", err, sizeof err);
            if (st == AM_OK) ok++;
            else refused++;
            if (st != AM_OK && (strncmp(err, "t.vxa:", 6) || strchr(err, '\n'))) bad++;
        }
        const int rounds = test_quick() ? 100 : 2000;
        for (int i = 0; i < rounds; i++) {
            memcpy(buf, src, (size_t)n + 1);
            for (int k = 0; k < 1 + i % 3; k++) {
                r ^= r << 13, r ^= r >> 7, r ^= r << 17;
                const char set[] = "0123456789<>/=\", .-eE]![xAZ";
                buf[r % (uint64_t)n] = set[(r >> 32) % (sizeof set - 1)];
            }
            am_status st = am_vxa_parse(&lat_b, &info_b, &doc, buf, "t.vxa", err, sizeof err);
            if (st == AM_OK) ok++;
            else refused++;
            if (st != AM_OK && (strncmp(err, "t.vxa:", 6) || strchr(err, '\n'))) bad++;
            if (st == AM_OK && info_b.layers.has_phase) {
                /* what was read builds or is refused with a message */
                am_status mb = am_model_build_layers(&pm2, &lat_b, &info_b.env, &info_b.layers, err, sizeof err);
                if (mb != AM_OK && mb != AM_ERR_EMPTY && !err[0]) bad++;
            }
        }
    }
    CHECK(bad == 0 && ok > 0 && refused > 0, "%d unclean outcomes (%d read, %d refused)", bad, ok, refused);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_xml_basics);
    RUN(test_vxa_period_for_commands);
    RUN(test_robot_settings);
    RUN(test_xml_errors);
    RUN(test_xml_limits);
    RUN(test_vxa_round_trip_scenes);
    RUN(test_vxa_round_trip_everything);
    RUN(test_vxa_round_trip_simulates_the_same);
    RUN(test_vxa_voxcad_conventions);
    RUN(test_vxa_warnings);
    RUN(test_vxa_errors);
    RUN(test_vxa_bad_tokens_quoted);
    RUN(test_vxa_format_errors);
    RUN(test_vxa_evaluation);
    RUN(test_vxa_phase_offset);
    RUN(test_robot_carries_its_layers);
    RUN(test_vxa_cantilever);
    RUN(test_vxa_regions_touch);
    RUN(test_vxa_poisson_and_fixed);
    RUN(test_vxa_stiffness);
    RUN(test_vxa_differ);
    RUN(test_vxa_stop_and_place);
    RUN(test_vxa_displace);
    RUN(test_vxa_vxd);
    RUN(test_vxa_noise);
    return SUMMARY();
}
