/* A strict XML reader in fixed memory (include/amorph/io.h).
 *
 * One forward pass over the text, no recursion: open elements live on a fixed stack of
 * AM_XML_MAX_DEPTH indices, elements and attributes in the caller's am_xml_doc arrays. Before the
 * pass, one sweep refuses NUL and control bytes, so later code can treat the text as characters.
 * The pass checks everything a later decode relies on (entity references, closed comments and
 * CDATA sections, matching end tags), so am_xml_text and am_xml_attr_text cannot fail on a parsed
 * document except for the size of their output buffer. Line numbers are counted lazily: a cursor
 * moves forward over the text as positions are asked for.
 *
 * Not supported, each refused with a message rather than misread: DOCTYPE (and so entity
 * definitions), encodings other than ASCII-compatible ones (bytes >= 0x80 pass through
 * unchecked, as UTF-8 or Latin-1 text), namespaces (a ':' is just a name character).
 */
#include "amorph/io.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* element and attribute indices are int16_t, offsets int32_t */
_Static_assert(AM_XML_MAX_NODES <= 32767 && AM_XML_MAX_ATTRS <= 32767, "xml: indices must fit int16_t");
_Static_assert(AM_XML_MAX_BYTES < 2147483647L, "xml: offsets must fit int32_t");

#define XML_NAME_MAX 255
#define XML_REF_MAX 32 /* longest entity or character reference read between '&' and ';' */

typedef struct xctx {
    am_xml_doc* d;
    const char* t;
    long len;
    long line_pos; /* line counting has reached this offset ... */
    int line;      /* ... which is on this line */
    char* err;
    int errsz;
} xctx;

/* the line of offset pos (counting moves forward; a step back restarts from the top) */
static int line_at(xctx* c, long pos)
{
    if (pos < c->line_pos) {
        c->line_pos = 0;
        c->line = 1;
    }
    for (; c->line_pos < pos && c->line_pos < c->len; c->line_pos++)
        if (c->t[c->line_pos] == '\n') c->line++;
    return c->line;
}

static am_status xerr(xctx* c, long pos, am_status code, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* "fname:line: message" for the line of offset pos */
static am_status xerr(xctx* c, long pos, am_status code, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    am_vfail_at(c->err, c->errsz, code, c->d->fname, line_at(c, pos), fmt, ap);
    va_end(ap);
    return code;
}

static int is_ws(char ch) { return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; }

static int name_start(char ch)
{
    unsigned char u = (unsigned char)ch;
    return (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || u == '_' || u == ':' || u >= 0x80;
}

static int name_char(char ch) { return name_start(ch) || (ch >= '0' && ch <= '9') || ch == '-' || ch == '.'; }

/* 1 when t[pos..] starts with s inside [0, len) */
static int starts(const char* t, long len, long pos, const char* s)
{
    long n = (long)strlen(s);
    return pos >= 0 && pos + n <= len && memcmp(t + pos, s, (size_t)n) == 0;
}

/* first offset >= pos (below end) where s starts, or -1 */
static long find(const char* t, long end, long pos, const char* s)
{
    long n = (long)strlen(s);
    for (long q = pos; q + n <= end; q++)
        if (t[q] == s[0] && memcmp(t + q, s, (size_t)n) == 0) return q;
    return -1;
}

/* end of the name starting at pos (pos itself when there is none) */
static long scan_name(const char* t, long len, long pos)
{
    if (pos >= len || !name_start(t[pos])) return pos;
    long q = pos + 1;
    while (q < len && name_char(t[q])) q++;
    return q;
}

/* an XML 1.0 Char: #x9 | #xA | #xD | [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF] */
static int xml_char_ok(unsigned long v)
{
    return v == 0x9 || v == 0xA || v == 0xD || (v >= 0x20 && v <= 0xD7FF) || (v >= 0xE000 && v <= 0xFFFD) ||
           (v >= 0x10000 && v <= 0x10FFFF);
}

/* the reference at t[pos] == '&' up to end: its UTF-8 bytes into out (*n of them), *next past the
 * ';'. Returns NULL, or what is wrong with it. */
static const char* ref(const char* t, long end, long pos, long* next, char out[4], int* n)
{
    long semi = -1;
    for (long q = pos + 1; q < end && q <= pos + XML_REF_MAX; q++) {
        if (t[q] == ';') {
            semi = q;
            break;
        }
        if (is_ws(t[q]) || t[q] == '&' || t[q] == '<') break;
    }
    if (semi < 0) return "'&' must start a reference such as &amp; (write &amp; for a literal '&')";
    const char* s = t + pos + 1;
    long k = semi - pos - 1;
    *next = semi + 1;
    *n = 1;
    if (k == 2 && !memcmp(s, "lt", 2)) out[0] = '<';
    else if (k == 2 && !memcmp(s, "gt", 2)) out[0] = '>';
    else if (k == 3 && !memcmp(s, "amp", 3)) out[0] = '&';
    else if (k == 4 && !memcmp(s, "quot", 4)) out[0] = '"';
    else if (k == 4 && !memcmp(s, "apos", 4)) out[0] = '\'';
    else if (k >= 2 && s[0] == '#') {
        unsigned long v = 0;
        int hex = s[1] == 'x';
        long i = hex ? 2 : 1;
        if (i >= k) return "empty character reference";
        for (; i < k; i++) {
            char ch = s[i];
            int dgt = ch >= '0' && ch <= '9' ? ch - '0'
                      : hex && ch >= 'a' && ch <= 'f' ? ch - 'a' + 10
                      : hex && ch >= 'A' && ch <= 'F' ? ch - 'A' + 10
                                                       : -1;
            if (dgt < 0) return "bad digit in a character reference";
            v = v * (hex ? 16u : 10u) + (unsigned long)dgt;
            if (v > 0x10FFFFul) return "character reference beyond U+10FFFF";
        }
        if (!xml_char_ok(v)) return "character reference to a character XML does not allow";
        if (v < 0x80) out[0] = (char)v;
        else if (v < 0x800) {
            out[0] = (char)(0xC0 | (v >> 6));
            out[1] = (char)(0x80 | (v & 0x3F));
            *n = 2;
        } else if (v < 0x10000) {
            out[0] = (char)(0xE0 | (v >> 12));
            out[1] = (char)(0x80 | ((v >> 6) & 0x3F));
            out[2] = (char)(0x80 | (v & 0x3F));
            *n = 3;
        } else {
            out[0] = (char)(0xF0 | (v >> 18));
            out[1] = (char)(0x80 | ((v >> 12) & 0x3F));
            out[2] = (char)(0x80 | ((v >> 6) & 0x3F));
            out[3] = (char)(0x80 | (v & 0x3F));
            *n = 4;
        }
    } else
        return "unknown entity (XML predefines only &lt; &gt; &amp; &quot; &apos;)";
    return NULL;
}

/* checks every reference and "]]>" in character data [p, e) */
static am_status check_text(xctx* c, long p, long e, int attr)
{
    while (p < e) {
        if (c->t[p] == '&') {
            char b[4];
            int n;
            long nx;
            const char* why = ref(c->t, e, p, &nx, b, &n);
            if (why) return xerr(c, p, AM_ERR_PARSE, "%s", why);
            p = nx;
        } else if (!attr && c->t[p] == ']' && starts(c->t, e, p, "]]>")) {
            return xerr(c, p, AM_ERR_PARSE, "']]>' is not allowed in text (write ]]&gt;)");
        } else
            p++;
    }
    return AM_OK;
}

/* the name at t[s..e) quoted for a message (am_quote) */
static const char* qname(char q[AM_QUOTE_BUF], const char* t, long s, long e)
{
    return am_quote(q, AM_QUOTE_BUF, t + s, e - s);
}

/* a byte for a message: printable ASCII as itself, the rest as a hex code */
static const char* show_byte(char ch, char buf[8])
{
    unsigned char u = (unsigned char)ch;
    if (u >= 0x21 && u < 0x7f) snprintf(buf, 8, "'%c'", ch);
    else snprintf(buf, 8, "0x%02x", u);
    return buf;
}

am_status am_xml_parse(am_xml_doc* doc, const char* text, long len, const char* fname, char* err, int errsz)
{
    if (!doc || !text || len < 0) return am_fail(err, errsz, AM_ERR_ARG, "xml: no document or no text");
    xctx c = {doc, text, len, 0, 1, err, errsz};
    doc->text = text;
    doc->len = len;
    doc->fname = fname ? fname : "(text)";
    doc->nnodes = 0;
    doc->nattrs = 0;
    if (len > AM_XML_MAX_BYTES)
        return xerr(&c, 0, AM_ERR_CAPACITY, "%ld bytes of XML: more than the %ld the reader takes (%s profile)", len,
                    (long)AM_XML_MAX_BYTES, AM_PROFILE_NAME);
    /* bytes XML never allows */
    for (long i = 0; i < len; i++) {
        unsigned char u = (unsigned char)text[i];
        if (u == 0) return xerr(&c, i, AM_ERR_PARSE, "a NUL byte (binary data) in an XML file");
        if (u < 0x20 && u != '\t' && u != '\n' && u != '\r')
            return xerr(&c, i, AM_ERR_PARSE, "control character 0x%02x is not allowed in XML", u);
    }

    const char* t = text;
    char b8[8], qn[AM_QUOTE_BUF], qa[AM_QUOTE_BUF]; /* a byte, an element and an attribute name for messages */
    long p = 0;
    if (starts(t, len, 0, "\xEF\xBB\xBF")) p = 3; /* UTF-8 byte order mark */
    if (starts(t, len, p, "<?xml") && p + 5 < len && (is_ws(t[p + 5]) || t[p + 5] == '?')) {
        long q = find(t, len, p, "?>");
        if (q < 0) return xerr(&c, p, AM_ERR_PARSE, "the XML declaration is not closed with '?>'");
        p = q + 2;
    }

    int16_t stack[AM_XML_MAX_DEPTH];    /* open elements */
    int16_t last[AM_XML_MAX_DEPTH + 1]; /* last child so far of the open element at each depth */
    int depth = 0, root_seen = 0;
    last[0] = -1;
    while (p < len) {
        if (t[p] != '<') {
            /* character data */
            long q = p;
            while (q < len && t[q] != '<') q++;
            if (depth == 0) {
                for (long i = p; i < q; i++)
                    if (!is_ws(t[i]))
                        return xerr(&c, i, AM_ERR_PARSE, "text %s the root element",
                                    root_seen ? "after" : "before");
            } else {
                am_status st = check_text(&c, p, q, 0);
                if (st != AM_OK) return st;
            }
            p = q;
            continue;
        }
        if (starts(t, len, p, "<!--")) {
            long q = p + 4;
            for (;;) {
                if (q + 1 >= len) return xerr(&c, p, AM_ERR_PARSE, "comment not closed (no '-->')");
                if (t[q] == '-' && t[q + 1] == '-') {
                    if (q + 2 < len && t[q + 2] == '>') break;
                    return xerr(&c, q, AM_ERR_PARSE, "'--' inside a comment");
                }
                q++;
            }
            p = q + 3;
            continue;
        }
        if (starts(t, len, p, "<![CDATA[")) {
            if (depth == 0) return xerr(&c, p, AM_ERR_PARSE, "CDATA section outside the root element");
            long q = find(t, len, p + 9, "]]>");
            if (q < 0) return xerr(&c, p, AM_ERR_PARSE, "CDATA section not closed (no ']]>')");
            p = q + 3;
            continue;
        }
        if (starts(t, len, p, "<!DOCTYPE")) return xerr(&c, p, AM_ERR_PARSE, "DOCTYPE declarations are not supported");
        if (starts(t, len, p, "<!"))
            return xerr(&c, p, AM_ERR_PARSE, "unexpected '<!' (expected a comment <!-- --> or a CDATA section)");
        if (starts(t, len, p, "<?")) {
            long ne = scan_name(t, len, p + 2);
            if (ne == p + 2) return xerr(&c, p, AM_ERR_PARSE, "a processing instruction '<?' needs a target name");
            if (ne - p - 2 == 3 && (t[p + 2] | 0x20) == 'x' && (t[p + 3] | 0x20) == 'm' && (t[p + 4] | 0x20) == 'l')
                return xerr(&c, p, AM_ERR_PARSE, "the XML declaration <?xml ...?> must come first in the file");
            long q = find(t, len, ne, "?>");
            if (q < 0) return xerr(&c, p, AM_ERR_PARSE, "processing instruction not closed (no '?>')");
            p = q + 2;
            continue;
        }
        if (p + 1 < len && t[p + 1] == '/') {
            /* end tag */
            long ns = p + 2, ne = scan_name(t, len, ns);
            if (ne == ns) return xerr(&c, p, AM_ERR_PARSE, "'</' must be followed by an element name");
            long q = ne;
            while (q < len && is_ws(t[q])) q++;
            if (q >= len || t[q] != '>')
                return xerr(&c, q < len ? q : p, AM_ERR_PARSE, "end tag </%s> not closed with '>'", qname(qn, t, ns, ne));
            if (depth == 0) return xerr(&c, p, AM_ERR_PARSE, "end tag </%s> without a start tag", qname(qn, t, ns, ne));
            am_xml_node* open = &doc->node[stack[depth - 1]];
            if (open->name_len != ne - ns || memcmp(t + open->start + 1, t + ns, (size_t)(ne - ns)) != 0)
                return xerr(&c, p, AM_ERR_PARSE, "</%s> does not close <%s> (opened on line %d)", qname(qn, t, ns, ne),
                            qname(qa, t, open->start + 1, open->start + 1 + open->name_len), (int)open->line);
            open->content_end = (int32_t)p;
            open->end = (int32_t)(q + 1);
            depth--;
            p = q + 1;
            continue;
        }

        /* start tag */
        long ns = p + 1, ne = scan_name(t, len, ns);
        if (ne == ns) {
            if (ns >= len) return xerr(&c, p, AM_ERR_PARSE, "the file ends after '<'");
            return xerr(&c, p, AM_ERR_PARSE, "'<' followed by %s does not start a tag (write &lt; for a literal '<')",
                        show_byte(t[ns], b8));
        }
        if (ne - ns > XML_NAME_MAX)
            return xerr(&c, p, AM_ERR_CAPACITY, "element name '%s' longer than %d bytes", qname(qn, t, ns, ne), XML_NAME_MAX);
        if (depth == 0 && root_seen)
            return xerr(&c, p, AM_ERR_PARSE, "a second root element <%s> (an XML document has exactly one)",
                        qname(qn, t, ns, ne));
        if (doc->nnodes >= AM_XML_MAX_NODES)
            return xerr(&c, p, AM_ERR_CAPACITY, "more than %d elements (the XML reader's capacity, %s profile)",
                        AM_XML_MAX_NODES, AM_PROFILE_NAME);
        if (depth >= AM_XML_MAX_DEPTH)
            return xerr(&c, p, AM_ERR_CAPACITY, "elements nested deeper than %d levels (the XML reader's limit, %s profile)",
                        AM_XML_MAX_DEPTH, AM_PROFILE_NAME);
        int n = doc->nnodes++;
        am_xml_node* nd = &doc->node[n];
        nd->start = (int32_t)p;
        nd->line = line_at(&c, p);
        nd->parent = (int16_t)(depth > 0 ? stack[depth - 1] : -1);
        nd->child = nd->next = -1;
        nd->attr = (int16_t)doc->nattrs;
        nd->nattr = 0;
        nd->name_len = (uint8_t)(ne - ns);
        if (depth > 0) {
            if (last[depth] < 0) doc->node[nd->parent].child = (int16_t)n;
            else doc->node[last[depth]].next = (int16_t)n;
            last[depth] = (int16_t)n;
        }
        root_seen = 1;

        /* attributes, then '>' or '/>' */
        long q = ne;
        int empty = 0;
        for (;;) {
            long ws = q;
            while (q < len && is_ws(t[q])) q++;
            if (q >= len) return xerr(&c, p, AM_ERR_PARSE, "start tag <%s> not closed (the file ends)", qname(qn, t, ns, ne));
            if (t[q] == '>') {
                q++;
                break;
            }
            if (t[q] == '/') {
                if (q + 1 < len && t[q + 1] == '>') {
                    q += 2;
                    empty = 1;
                    break;
                }
                return xerr(&c, q, AM_ERR_PARSE, "expected '/>' after '/' in <%s>", qname(qn, t, ns, ne));
            }
            long as = q, ae = scan_name(t, len, as);
            if (ae == as)
                return xerr(&c, q, AM_ERR_PARSE, "unexpected %s in the start tag <%s>", show_byte(t[q], b8),
                            qname(qn, t, ns, ne));
            if (q == ws)
                return xerr(&c, q, AM_ERR_PARSE, "expected a blank before attribute '%s' in <%s>", qname(qa, t, as, ae),
                            qname(qn, t, ns, ne));
            if (ae - as > XML_NAME_MAX)
                return xerr(&c, q, AM_ERR_CAPACITY, "attribute name '%s' longer than %d bytes", qname(qa, t, as, ae),
                            XML_NAME_MAX);
            q = ae;
            while (q < len && is_ws(t[q])) q++;
            if (q >= len || t[q] != '=')
                return xerr(&c, q < len ? q : as, AM_ERR_PARSE, "attribute '%s' of <%s> has no '=' and value",
                            qname(qa, t, as, ae), qname(qn, t, ns, ne));
            q++;
            while (q < len && is_ws(t[q])) q++;
            if (q >= len || (t[q] != '"' && t[q] != '\''))
                return xerr(&c, q < len ? q : as, AM_ERR_PARSE, "the value of attribute '%s' must be quoted (\" or ')",
                            qname(qa, t, as, ae));
            char quote = t[q];
            long vs = ++q;
            while (q < len && t[q] != quote) {
                if (t[q] == '<')
                    return xerr(&c, q, AM_ERR_PARSE, "'<' in the value of attribute '%s' (write &lt;)", qname(qa, t, as, ae));
                q++;
            }
            if (q >= len) return xerr(&c, vs, AM_ERR_PARSE, "the value of attribute '%s' is not closed", qname(qa, t, as, ae));
            am_status st = check_text(&c, vs, q, 1);
            if (st != AM_OK) return st;
            for (int a = nd->attr; a < nd->attr + nd->nattr; a++) {
                const am_xml_attr* o = &doc->attr[a];
                if (o->name_len == ae - as && memcmp(t + o->name, t + as, (size_t)(ae - as)) == 0)
                    return xerr(&c, as, AM_ERR_PARSE, "attribute '%s' given twice in <%s>", qname(qa, t, as, ae),
                                qname(qn, t, ns, ne));
            }
            if (doc->nattrs >= AM_XML_MAX_ATTRS || nd->nattr >= 255)
                return xerr(&c, as, AM_ERR_CAPACITY, "more than %d attributes (the XML reader's capacity, %s profile)",
                            doc->nattrs >= AM_XML_MAX_ATTRS ? AM_XML_MAX_ATTRS : 255, AM_PROFILE_NAME);
            am_xml_attr* at = &doc->attr[doc->nattrs++];
            at->name = (int32_t)as;
            at->name_len = (uint8_t)(ae - as);
            at->value = (int32_t)vs;
            at->value_end = (int32_t)q;
            nd->nattr++;
            q++; /* the closing quote */
        }
        nd->content = (int32_t)q;
        if (empty) {
            nd->content_end = nd->end = (int32_t)q;
        } else {
            nd->content_end = nd->end = -1;
            stack[depth++] = (int16_t)n;
            last[depth] = -1;
        }
        p = q;
    }
    if (depth > 0) {
        const am_xml_node* o = &doc->node[stack[depth - 1]];
        return xerr(&c, len > 0 && t[len - 1] == '\n' ? len - 1 : len, AM_ERR_PARSE,
                    "the file ends inside <%s> (opened on line %d)", qname(qn, t, o->start + 1, o->start + 1 + o->name_len),
                    (int)o->line);
    }
    if (!root_seen)
        return xerr(&c, len > 0 && t[len - 1] == '\n' ? len - 1 : len, AM_ERR_PARSE,
                    "no root element (the file is empty or holds only comments)");
    return AM_OK;
}

int am_xml_is(const am_xml_doc* doc, int n, const char* name)
{
    size_t k = strlen(name);
    const am_xml_node* nd = &doc->node[n];
    return nd->name_len == k && memcmp(doc->text + nd->start + 1, name, k) == 0;
}

int am_xml_attr_find(const am_xml_doc* doc, int n, const char* name)
{
    size_t k = strlen(name);
    const am_xml_node* nd = &doc->node[n];
    for (int a = nd->attr; a < nd->attr + nd->nattr; a++)
        if (doc->attr[a].name_len == k && memcmp(doc->text + doc->attr[a].name, name, k) == 0) return a;
    return -1;
}

/* decoded character data of [p, e) into out: in element content (attr 0) comments and processing
 * instructions are skipped, CDATA copied raw, child elements (the chain from child) jumped over,
 * and line ends read as '\n'; in attribute values (attr 1) blanks read as ' ' */
static am_status decode(const am_xml_doc* d, long p, long e, int child, int attr, char* out, long cap, long* olen)
{
    const char* t = d->text;
    long o = 0;
    if (olen) *olen = 0;
    if (!out || cap < 1) return AM_ERR_CAPACITY;
    out[0] = 0;
    while (p < e) {
        char b[4];
        int n = 1;
        if (!attr && t[p] == '<') {
            long q;
            if (starts(t, e, p, "<!--")) {
                q = find(t, e, p + 4, "-->");
                p = q < 0 ? e : q + 3;
                continue;
            }
            if (starts(t, e, p, "<?")) {
                q = find(t, e, p + 2, "?>");
                p = q < 0 ? e : q + 2;
                continue;
            }
            if (starts(t, e, p, "<![CDATA[")) {
                q = find(t, e, p + 9, "]]>");
                if (q < 0) q = e;
                if (q - (p + 9) >= cap - o) {
                    out[0] = 0;
                    return AM_ERR_CAPACITY;
                }
                memcpy(out + o, t + p + 9, (size_t)(q - (p + 9)));
                o += q - (p + 9);
                p = q + 3;
                continue;
            }
            while (child >= 0 && d->node[child].start < p) child = d->node[child].next;
            if (child >= 0 && d->node[child].start == p) {
                p = d->node[child].end;
                child = d->node[child].next;
            } else
                p = e; /* not reached for a parsed document */
            continue;
        }
        if (t[p] == '&') {
            long nx;
            if (ref(t, e, p, &nx, b, &n)) return AM_ERR_PARSE; /* not reached for a parsed document */
            p = nx;
        } else if (t[p] == '\r' || (attr && (t[p] == '\n' || t[p] == '\t'))) {
            b[0] = attr ? ' ' : '\n';
            p += !attr && p + 1 < e && t[p + 1] == '\n' ? 2 : 1;
        } else
            b[0] = t[p++];
        if (n >= cap - o) {
            out[0] = 0;
            return AM_ERR_CAPACITY;
        }
        memcpy(out + o, b, (size_t)n);
        o += n;
    }
    out[o] = 0;
    if (olen) *olen = o;
    return AM_OK;
}

am_status am_xml_text(const am_xml_doc* doc, int n, char* out, long cap, long* len)
{
    const am_xml_node* nd = &doc->node[n];
    return decode(doc, nd->content, nd->content_end, nd->child, 0, out, cap, len);
}

am_status am_xml_attr_text(const am_xml_doc* doc, int a, char* out, long cap, long* len)
{
    return decode(doc, doc->attr[a].value, doc->attr[a].value_end, -1, 1, out, cap, len);
}
