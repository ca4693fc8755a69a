/* amorph/xml.h: a small, strict XML reader in fixed memory (used by the VXA format).
 *
 * am_xml_parse checks a whole text and builds a tree of elements in the caller's am_xml_doc: no
 * allocation, no recursion. Elements, attributes, character data, CDATA sections, comments,
 * processing instructions (skipped), the <?xml ...?> declaration at the start and the five
 * predefined entities plus numeric character references (&#65; &#x41;) are understood. A DOCTYPE
 * is refused (no entity definitions, so no entity expansion). The tree keeps offsets into the
 * text, which must stay alive and unchanged while the document is used; decoded text is produced
 * on demand by am_xml_text and am_xml_attr_text.
 *
 * Limits (include/amorph/config.h): AM_XML_MAX_BYTES of text, AM_XML_MAX_NODES elements,
 * AM_XML_MAX_ATTRS attributes, AM_XML_MAX_DEPTH levels of nesting, names of at most 255 bytes and
 * 255 attributes per element. Passing one is an AM_ERR_CAPACITY with a message, never a write
 * past an array. Every error is one line "fname:line: problem".
 */
#ifndef AMORPH_XML_H
#define AMORPH_XML_H

#include <stdint.h>
#include "amorph/config.h"
#include "amorph/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* one element; offsets are byte offsets into the text */
typedef struct am_xml_node {
    int32_t start;          /* offset of the '<' of the start tag */
    int32_t content;        /* offset just past the start tag's '>' */
    int32_t content_end;    /* offset of the end tag's '<' (== content for <x/>) */
    int32_t end;            /* offset just past the element */
    int32_t line;           /* line of the start tag, from 1 */
    int16_t parent, child, next; /* element indices, -1 when none */
    int16_t attr;           /* index of the first attribute (nattr of them follow) */
    uint8_t name_len, nattr;
} am_xml_node;

typedef struct am_xml_attr {
    int32_t name;           /* offset of the name */
    int32_t value, value_end; /* the raw value between the quotes */
    uint8_t name_len;
} am_xml_attr;

/* a parsed document; large: declare it static. Element 0 is the root. */
typedef struct am_xml_doc {
    const char* text;       /* the caller's text */
    long len;               /* its length, bytes */
    const char* fname;      /* for messages */
    int nnodes, nattrs;
    am_xml_node node[AM_XML_MAX_NODES];
    am_xml_attr attr[AM_XML_MAX_ATTRS];
} am_xml_doc;

/* parses text[0, len) (text[len] need not be NUL; a NUL byte inside is an error). fname is used
 * only in messages. AM_ERR_PARSE for malformed XML, AM_ERR_CAPACITY past a limit. */
am_status am_xml_parse(am_xml_doc* doc, const char* text, long len, const char* fname, char* err, int errsz);

/* 1 when element n is named name */
int am_xml_is(const am_xml_doc* doc, int n, const char* name);
/* index of the attribute of element n named name, or -1 */
int am_xml_attr_find(const am_xml_doc* doc, int n, const char* name);
/* the character data of element n (text and CDATA, entities decoded, comments and child elements
 * left out) into out (capacity cap, NUL-terminated); *len gets its length (may be NULL).
 * AM_ERR_CAPACITY (out holds "") when it does not fit. */
am_status am_xml_text(const am_xml_doc* doc, int n, char* out, long cap, long* len);
/* the decoded value of attribute a (tabs and newlines read as spaces), as am_xml_text */
am_status am_xml_attr_text(const am_xml_doc* doc, int a, char* out, long cap, long* len);

#ifdef __cplusplus
}
#endif
#endif
