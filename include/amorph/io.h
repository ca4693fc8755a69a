/* amorph/io.h: the file layer (src/io/): every codec (XML, inflate, PNG, pictures, surface meshes
 * and printable files, the lattice text format, VoxCAD/voxcraft VXA) and the run folder's
 * checkpoint (its file names and tables: amorph/evo.h). It includes the four layers below it.
 */
#ifndef AMORPH_IO_H
#define AMORPH_IO_H

#include <stdint.h>
#include "amorph/base.h"
#include "amorph/sim.h"
#include "amorph/geno.h"
#include "amorph/evo.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ==== a small, strict XML reader in fixed memory (used by the VXA format).
 *
 * am_xml_parse checks a whole text and builds a tree of elements in the caller's am_xml_doc: no
 * allocation, no recursion. Elements, attributes, character data, CDATA sections, comments,
 * processing instructions (skipped), the <?xml ...?> declaration at the start and the five
 * predefined entities plus numeric character references (&#65; &#x41;) are understood. A DOCTYPE
 * is refused (no entity definitions, so no entity expansion). The tree keeps offsets into the
 * text, which must stay alive and unchanged while the document is used; decoded text is produced
 * on demand by am_xml_text and am_xml_attr_text.
 *
 * Limits (include/amorph/base.h): AM_XML_MAX_BYTES of text, AM_XML_MAX_NODES elements,
 * AM_XML_MAX_ATTRS attributes, AM_XML_MAX_DEPTH levels of nesting, names of at most 255 bytes and
 * 255 attributes per element. Passing one is an AM_ERR_CAPACITY with a message, never a write
 * past an array. Every error is one line "fname:line: problem".
 */

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
AM_API am_status am_xml_parse(am_xml_doc* doc, const char* text, long len, const char* fname, char* err, int errsz);

/* 1 when element n is named name */
AM_API int am_xml_is(const am_xml_doc* doc, int n, const char* name);
/* index of the attribute of element n named name, or -1 */
AM_API int am_xml_attr_find(const am_xml_doc* doc, int n, const char* name);
/* the character data of element n (text and CDATA, entities decoded, comments and child elements
 * left out) into out (capacity cap, NUL-terminated); *len gets its length (may be NULL).
 * AM_ERR_CAPACITY (out holds "") when it does not fit. */
AM_API am_status am_xml_text(const am_xml_doc* doc, int n, char* out, long cap, long* len);
/* the decoded value of attribute a (tabs and newlines read as spaces), as am_xml_text */
AM_API am_status am_xml_attr_text(const am_xml_doc* doc, int a, char* out, long cap, long* len);

/* ==== a zlib inflater (RFC 1950 streams of RFC 1951 deflate data), hand-written,
 * in fixed memory.
 *
 * The one decompressor of amorph: the VXA reader decodes Compression="ZLIB" layers with it and
 * the tests read PNG files with it. It works on caller buffers with a small caller workspace
 * (am_inflate_work, under 2 KB, no allocation), decodes the three block kinds (stored, fixed and
 * dynamic Huffman) and is strict: a bad header, a preset dictionary, a bad block type, a stored
 * length that does not match its complement, an over-subscribed or incomplete Huffman code (but
 * the one-code distance tree RFC 1951 allows), an invalid symbol, a distance reaching before the
 * start of the output, an output longer than the caller's buffer, input that ends early, a wrong
 * Adler-32 and bytes after the stream are each an error with its own one-line message.
 */

/* a canonical Huffman code: count[len] codes of each length, the symbols in code order */
typedef struct am_huffman {
    int16_t count[16];
    int16_t symbol[288];
} am_huffman;

/* the inflater's workspace: the literal/length and distance codes of the block being decoded */
typedef struct am_inflate_work {
    am_huffman lit, dist;
    int kinds[3];            /* blocks met: stored, fixed Huffman, dynamic Huffman */
} am_inflate_work;

/* inflates raw deflate data in[0..n) into out (capacity cap); *len gets the bytes written and
 * *used the input bytes consumed (through the last block's last byte). AM_ERR_PARSE for malformed
 * or truncated data, AM_ERR_CAPACITY when the output needs more than cap bytes. The message names
 * the input byte where decoding stopped. */
AM_API am_status am_inflate_raw(const uint8_t* in, long n, uint8_t* out, long cap, long* len, long* used, am_inflate_work* w,
                         char* err, int errsz);

/* inflates one zlib stream (2-byte header, deflate data, big-endian Adler-32 of the output) that
 * fills in[0..n) exactly into out (capacity cap); *len gets the bytes written. AM_ERR_PARSE for a
 * bad header or checksum, malformed or truncated data, or bytes after the checksum;
 * AM_ERR_CAPACITY as am_inflate_raw. */
AM_API am_status am_zlib_inflate(const uint8_t* in, long n, uint8_t* out, long cap, long* len, am_inflate_work* w, char* err,
                          int errsz);
/* inflates one gzip member (RFC 1952: a header with its optional fields, deflate data, the CRC-32
 * and the size of the output, little-endian) that fills in[0..n) exactly, as `gzip -9n` writes a
 * run's evals.csv.gz; the same statuses as am_zlib_inflate (a bad magic, method, CRC-32 or size,
 * or bytes after the member: AM_ERR_PARSE) */
AM_API am_status am_gzip_inflate(const uint8_t* in, long n, uint8_t* out, long cap, long* len, am_inflate_work* w, char* err,
                          int errsz);

/* ==== pictures without a library: checksums, a PNG encoder and a small software
 * rasteriser (docs/pictures.md).
 *
 * Everything works on caller buffers and allocates nothing. The PNG encoder writes 8-bit RGB or
 * RGBA images with one zlib stream in either stored blocks or one fixed-Huffman deflate block
 * (greedy matches at the pixel and row distances, which is what flat synthetic pictures need).
 * The rasteriser draws z-buffered, flat-shaded triangles, lines and a 5 x 7 pixel font into an
 * RGB canvas through an orthographic camera whose viewport is a rectangle of the canvas, so one
 * canvas can hold several panels.
 */

/* ---- checksums ---- */

/* CRC-32 (ISO 3309, as PNG and zlib): crc is the running value, 0 to start;
 * am_crc32(0, "123456789", 9) == 0xCBF43926 */
AM_API uint32_t am_crc32(uint32_t crc, const void* data, long n);
/* Adler-32 (RFC 1950): adler is the running value, 1 to start;
 * am_adler32(1, "Wikipedia", 9) == 0x11E60398 */
AM_API uint32_t am_adler32(uint32_t adler, const void* data, long n);

/* ---- PNG ---- */

/* how am_png_encode deflates: stored (no compression); one fixed-Huffman block of matches one pixel
 * and one row back (2 KiB of stack); or the smallest of a block with codes made for the picture
 * (matches also through a 16 KiB hash table of recent strings; 34 KiB of stack in all), a fixed
 * block of the same matches, and stored blocks (two passes) */
enum { AM_PNG_STORED = 0, AM_PNG_FIXED = 1, AM_PNG_DYNAMIC = 2 };
#define AM_PNG_MAX_SIDE 8192                   /* pixels along either side of an image */

/* the largest PNG file am_png_encode can write for this image, bytes (0 for a bad size) */
AM_API long am_png_max_size(int w, int h, int channels);
/* encodes w x h pixels (channels 3: RGB, 4: RGBA; rows top to bottom, 8 bits per sample) as a
 * PNG file in out (capacity cap); *len gets its length. AM_ERR_ARG for a bad size or mode,
 * AM_ERR_CAPACITY when cap is too small (am_png_max_size always suffices). */
AM_API am_status am_png_encode(const uint8_t* pixels, int w, int h, int channels, int mode, uint8_t* out, long cap,
                        long* len, char* err, int errsz);

/* ---- rasteriser ---- */

/* an RGB picture with a depth buffer, both the caller's */
typedef struct am_canvas {
    int w, h;        /* pixels */
    uint8_t* rgb;    /* (h x w x 3) bytes, rows top to bottom */
    float* depth;    /* (h x w) distance along the view direction of what was drawn (smaller is nearer) */
} am_canvas;

/* fills the picture with one colour and resets the depth buffer to far */
AM_API void am_canvas_clear(am_canvas* c, const uint8_t rgb[3]);

/* an orthographic camera looking at `target` from azimuth/elevation, shown in a rectangle of the
 * canvas; set with am_camera_look */
typedef struct am_camera {
    double target[3];     /* world point at the centre of the viewport, m */
    double right[3], up[3], fwd[3]; /* unit view axes in world coordinates (fwd points into the picture) */
    double scale;         /* pixels per metre */
    int vx, vy, vw, vh;   /* viewport rectangle in canvas pixels (left, top, width, height) */
} am_camera;

/* camera at azimuth az (radians, 0 looks along +y, pi/2 along -x) and elevation el (radians above
 * the horizon, looking down), showing view_h metres over the viewport's height; z is up */
AM_API void am_camera_look(am_camera* cam, const double target[3], double az, double el, double view_h, int vx, int vy,
                    int vw, int vh);
/* world point -> canvas pixel (out[0], out[1]) and depth out[2] */
AM_API void am_camera_project(const am_camera* cam, const double p[3], double out[3]);
/* v rotated by the unit quaternion q = (w, x, y, z) (the pictures' and the mesh's placement) */
AM_API void am_quat_rotate(const double q[4], const double v[3], double out[3]);

/* a triangle given in canvas pixels with depths (v = x0, y0, depth0, x1, y1, depth1, x2, y2,
 * depth2), clipped to the viewport, depth-tested and written in one colour; depth_test 0 draws
 * over everything and leaves the depth buffer alone (overlays) */
AM_API void am_raster_triangle(am_canvas* c, const am_camera* cam, const double v[9], const uint8_t rgb[3], int depth_test);
/* a world-space line of the given width in pixels, depth-tested against what is drawn
 * (bias metres towards the viewer so lines on a surface stay visible) */
AM_API void am_raster_line3(am_canvas* c, const am_camera* cam, const double a[3], const double b[3], double width,
                     double bias, const uint8_t rgb[3]);
/* a canvas-space line (x0, y0)-(x1, y1) of the given width, over everything, clipped to the viewport */
AM_API void am_raster_line2(am_canvas* c, const am_camera* cam, double x0, double y0, double x1, double y1, double width,
                     const uint8_t rgb[3]);
/* a box centred at centre with half-extents half[3] along its own axes, turned by the unit
 * quaternion q = (w, x, y, z), flat-shaded: each visible face gets
 * rgb * (ambient + (1 - ambient) * max(0, n . light)), light a unit vector towards the light */
AM_API void am_raster_box(am_canvas* c, const am_camera* cam, const double centre[3], const double q[4],
                   const double half[3], const uint8_t rgb[3], const double light[3], double ambient);
/* text in a 5 x 7 pixel font (ASCII 32..126), each font pixel drawn as scale x scale canvas
 * pixels, top-left corner at (x, y), over everything and clipped to the viewport; returns the
 * width drawn in pixels */
AM_API int am_raster_text(am_canvas* c, const am_camera* cam, int x, int y, int scale, const char* text,
                   const uint8_t rgb[3]);

/* ==== the surface of a voxel body as a triangle mesh whose vertices follow the voxels
 * around them, and the STL and AMF writers of printable robots (docs/pictures.md, Surface;
 * docs/formats.md, STL and AMF).
 *
 * The mesh is built once per lattice (its topology) and placed once per pose (its positions):
 *   - am_mesh_build makes the faces of the lattice's cells that lie on a surface, each a quad cut
 *     into four triangles around its centre, counter-clockwise seen from outside. A vertex sits on
 *     a lattice corner and follows the voxels that share the corner: placed, it is the mean of
 *     their corner points p + R (+-hx, +-hy, +-hz). Faces that meet at a corner share its vertex,
 *     so the surface has no gap or overlap however the voxels bend and turn.
 *   - AM_MESH_BODY: the outer surface of the whole body (faces between a voxel and empty space),
 *     each triangle in the colour of its voxel's material: what render and view draw.
 *     AM_MESH_MATERIALS: one closed surface per material (faces between a voxel of the material
 *     and anything else), what a multi-material printer needs: a face between two materials is in
 *     both surfaces, once each way round.
 *   - Every surface is closed and every edge is shared by exactly two of its triangles: where two
 *     voxels of one surface touch only along an edge or at a corner, the corner's vertex is split
 *     (one per fan of faces around it) and such an edge gets a midpoint per side, so no edge is
 *     ever shared by four triangles. Diagonal neighbours are not linked in the simulator either.
 *     The split vertices still sit at one point; am_mesh_open_pinches moves each a little towards
 *     its own voxels, so that a file that names vertices by their position (STL) is manifold too.
 *
 * Nothing allocates: the caller owns the am_mesh (a large struct, declare it static) and the
 * arrays of positions. Capacities follow AM_MAX_DIM (amorph/base.h, from the profile's
 * configuration header); the build never runs out of room
 * for a lattice of this profile, and says so with AM_ERR_CAPACITY if it ever would. */

/* faces of one build: every cell face position of the workspace, once per side */
#define AM_MESH_MAX_FACES (2L * 3L * AM_MAX_DIM * AM_MAX_DIM * (AM_MAX_DIM + 1))
/* vertices: at most 4 corners, 2 midpoints and a centre per face */
#define AM_MESH_MAX_VERTS (7L * AM_MESH_MAX_FACES)
/* triangles: 4 per face and 2 per pair of midpoints */
#define AM_MESH_MAX_TRIS (8L * AM_MESH_MAX_FACES)
/* am_mesh_open_pinches: the share of the way from a pinch to the centre of its voxels a split
 * vertex moves (0.025: two voxels touching at a corner end 0.043 voxel sizes apart there) */
#define AM_MESH_PINCH_PULL 0.025

enum { AM_MESH_BODY = 0, AM_MESH_MATERIALS = 1 };

typedef struct am_mesh {
    int mode;                 /* AM_MESH_BODY or AM_MESH_MATERIALS */
    int nx, ny, nz;           /* the lattice's size; corner (x, y, z) has index x + (nx+1) (y + (ny+1) z) */
    int nv;                   /* voxels (filled cells; voxel k is the k-th in cell order, as am_model numbers them) */
    long nface, nvert, ntri;  /* faces, vertices, triangles */
    long ncorner;             /* vertices 0 .. ncorner-1 sit on corners, the rest are means of others */
    double voxel_size;        /* the lattice's cell edge, m */
    int32_t cell_voxel[AM_MAX_CELLS];      /* voxel of each cell, -1 if empty */
    int32_t voxel_cell[AM_MAX_VOXELS];     /* cell of each voxel */
    /* per vertex (nvert) */
    int32_t vcorner[AM_MESH_MAX_VERTS];    /* the lattice corner of a corner vertex, -1 for the others */
    uint8_t vmask[AM_MESH_MAX_VERTS];      /* the cells around its corner it follows: bit bx + 2 by + 4 bz
                                            * is the cell (x - 1 + bx, y - 1 + by, z - 1 + bz) */
    int32_t vfrom[AM_MESH_MAX_VERTS][4];   /* a vertex that is no corner: the mean of these four earlier
                                            * vertices (a midpoint lists its two ends twice) */
    uint8_t vpull[AM_MESH_MAX_VERTS];      /* a vertex where its surface pinches (one of two or more
                                            * vertices of one surface at a corner, a midpoint): the
                                            * cells around its corner (a midpoint: around the corner of
                                            * vfrom[0]; bits as vmask) whose voxels own its faces there,
                                            * which am_mesh_open_pinches moves it towards; else 0 */
    /* per triangle (ntri) */
    int32_t tri[AM_MESH_MAX_TRIS][3];      /* vertices, counter-clockwise seen from outside */
    uint8_t tmat[AM_MESH_MAX_TRIS];        /* palette index (0-based) of the material inside it */
    /* the build's scratch */
    int32_t face_cell[AM_MESH_MAX_FACES];  /* the cell inside the face */
    uint8_t face_dir[AM_MESH_MAX_FACES];   /* its outward direction 0..5: +x, -x, +y, -y, +z, -z */
    int32_t face_of[6 * AM_MAX_CELLS];     /* face of (cell, direction), -1 if none */
    int32_t slot[4 * AM_MESH_MAX_FACES];   /* per face corner: union-find parent, then its vertex */
    int32_t mid[4 * AM_MESH_MAX_FACES];    /* per face edge (corner k to k+1): its midpoint vertex or -1 */
    int32_t corner_head[(AM_MAX_DIM + 1) * (AM_MAX_DIM + 1) * (AM_MAX_DIM + 1)]; /* a corner's first vertex */
} am_mesh;

/* the surface of lat (mode AM_MESH_BODY or AM_MESH_MATERIALS) into *mesh. AM_ERR_EMPTY for a
 * lattice without voxels, AM_ERR_ARG for a bad mode, AM_ERR_CAPACITY if a capacity would be passed. */
AM_API am_status am_mesh_build(am_mesh* mesh, const am_lattice* lat, int mode, char* err, int errsz);

/* the rest shape: vertex positions (nvert x 3, m) with the corner (x, y, z) at (x L, y L, z L),
 * L the lattice's voxel size, so the body sits in the box [0, nx L] x [0, ny L] x [0, nz L] */
AM_API void am_mesh_rest(const am_mesh* mesh, double* pos);

/* half-extents of voxel i along its own axes in a pose (pose: nv x 7 floats, x, y, z in m then the
 * unit quaternion qw, qx, qy, qz, as am_record writes them): half the mean distance to its lattice
 * neighbours on each axis, so thermal expansion shows; an axis without neighbours takes the mean of
 * the others, a lone voxel half the voxel size; never more than the voxel size */
AM_API void am_mesh_half(const am_mesh* mesh, const float* pose, int i, double half[3]);

/* vertex positions (nvert x 3, m) for a pose of the body (as am_mesh_half): each corner vertex is
 * the mean of p + R (+-hx, +-hy, +-hz) over the voxels it follows, the others the means they are */
AM_API void am_mesh_place(const am_mesh* mesh, const float* pose, double* pos);

/* moves the vertices where a surface pinches (vpull) AM_MESH_PINCH_PULL of the way towards the
 * centre of the voxels they pull to (pose as am_mesh_half, or NULL for the rest shape), and places
 * the vertices that are means of others again. After am_mesh_rest or am_mesh_place: the two sides
 * of a pinch no longer meet, so the surface is manifold by position as well as by vertex number
 * (each surface stays closed; its volume shrinks by a sliver at each pinch). */
AM_API void am_mesh_open_pinches(const am_mesh* mesh, const float* pose, double* pos);

/* signed volume enclosed by the triangles of material mat (-1: all), m^3 (positive when every
 * triangle turns counter-clockwise seen from outside) */
AM_API double am_mesh_volume(const am_mesh* mesh, const double* pos, int mat);

/* 1 when the mesh holds a triangle of material mat (palette index) */
AM_API int am_mesh_holds(const am_mesh* mesh, int mat);

/* Self-intersection: pairs of triangles (of material mat, -1: all) that share no vertex and cross,
 * each pair once. A crossing is an overlap of positive length (coplanar triangles: of positive
 * area) beyond a tolerance of 1e-6 voxel sizes, so triangles that only touch are not counted.
 * Broad phase: a uniform grid of cells no smaller than the largest triangle, at most
 * AM_MESH_GRID_DIM a side, each triangle filed under the cell of its box's low corner; a triangle
 * is compared with those filed in the 3 x 3 x 3 cells that can hold an overlapping box. */
#define AM_MESH_GRID_DIM (3 * AM_MAX_DIM + 4)
typedef struct am_mesh_grid {
    int32_t start[AM_MESH_GRID_DIM * AM_MESH_GRID_DIM * AM_MESH_GRID_DIM + 1]; /* first entry of each cell in order */
    int32_t order[AM_MESH_MAX_TRIS];                                         /* triangles, cell by cell */
} am_mesh_grid;
typedef struct am_mesh_crossing {
    long pairs;     /* crossing pairs found */
    long visits;    /* candidate pairs looked at (the work done) */
    int complete;   /* 1 when every candidate pair was looked at; 0 when max_visits stopped the search
                     * or a position was not finite */
    double at[3];   /* the first crossing found: the mean of the two triangles' centres, m */
} am_mesh_crossing;
/* the crossings of the surface in pos, with grid (the caller's scratch, a large struct) and at
 * most max_visits candidate pairs looked at */
AM_API void am_mesh_crossings(const am_mesh* mesh, const double* pos, int mat, am_mesh_grid* grid, long max_visits,
                       am_mesh_crossing* out);

/* The printable files (docs/formats.md), in millimetres (positions in m times 1000):
 * ASCII STL: one `solid NAME ... endsolid NAME`: the triangles of material mat (NAME the
 * material's), or with mat -1 every triangle of the mesh (NAME `body`: the AM_MESH_BODY surface).
 * One solid a file, as slicers and ADMesh read them.
 * AMF (ISO/ASTM 52915): <amf unit="millimeter">, a <material id="K"> with its name and <color>
 * per material held (K = palette index + 1; 0 means no material in AMF), one <object> whose
 * <mesh> holds every vertex and one <volume materialid="K"> per material held, materials in
 * palette order.
 * title (may be NULL): the AMF's <metadata type="name">. AM_ERR_CAPACITY or AM_ERR_IO when out
 * dropped text. */
AM_API am_status am_mesh_write_stl(const am_mesh* mesh, const double* pos, const am_palette* pal, int mat, am_text* out,
                            char* err, int errsz);
AM_API am_status am_mesh_write_amf(const am_mesh* mesh, const double* pos, const am_palette* pal, const char* title,
                            am_text* out, char* err, int errsz);

/* the lattice text format (docs/formats.md). Parse from a NUL-terminated buffer; fname is used
 * only in messages ("fname:line: problem"). */
AM_API am_status am_lattice_parse(am_lattice* lat, const char* text, const char* fname, char* err, int errsz);
/* a lattice read line by line, for text that is not held whole (a file streamed through a small
 * buffer): begin, one call per line, end. am_lattice_parse is these calls over a whole text and
 * gives the same lattice and messages. */
typedef struct am_lattice_reader {
    am_lattice* lat;            /* the lattice being filled (partial after an error) */
    const char* fname;          /* for messages; must stay valid while reading */
    int line, last;             /* lines read; the last one */
    int have_header, have_size, have_voxel;
    int z, y;                   /* the layer being read (-1 before the first) and its rows so far */
    am_status st;               /* the first failure: every later call returns it */
} am_lattice_reader;
AM_API void am_lattice_read_begin(am_lattice_reader* r, am_lattice* lat, const char* fname);
/* one line of n characters without its newline (text[n] is '\n' or NUL) */
AM_API am_status am_lattice_read_line(am_lattice_reader* r, const char* text, long n, char* err, int errsz);
/* after the last line: AM_OK when the lattice is complete */
AM_API am_status am_lattice_read_end(am_lattice_reader* r, char* err, int errsz);
/* write lat in the lattice text format into buf (capacity cap, NUL-terminated); *len gets the
 * length. AM_ERR_CAPACITY if it does not fit. */
AM_API am_status am_lattice_format(const am_lattice* lat, char* buf, long cap, long* len, char* err, int errsz);
/* the same text written to out, a whole-text buffer or a stream (amorph/base.h); AM_ERR_CAPACITY
 * or AM_ERR_IO when out dropped text */
AM_API am_status am_lattice_write(const am_lattice* lat, am_text* out, char* err, int errsz);
/* the largest text am_lattice_format can produce for any lattice of this profile */
#define AM_LATTICE_TEXT_MAX (AM_MAX_MATERIALS * 400L + AM_MAX_CELLS * 3L + 8192L)

/* ==== VoxCAD / Voxelyze files (VXA 1.1 holding a VXC 0.94 object), read and written.
 *
 * docs/vxa.md is the manual: which tags map to which amorph fields, the CTE convention (VXA's CTE
 * is linear per degree: a file read here sets env.cte_mode = AM_CTE_LINEAR), and what is not
 * supported. The reader parses the text with the fixed-memory XML reader (amorph/io.h) into a
 * caller's workspace, fills a lattice and an environment, and lists every tag it does not
 * support as a warning line "fname:line: warning: unsupported tag <X> ignored" (never silence).
 * Malformed files are errors "fname:line: problem". ZLIB layers are inflated (amorph/io.h);
 * evosoro's per-voxel phases and stiffnesses and VoxCAD's boundary conditions come out as per-cell layers
 * (am_layers, for am_model_build_layers); a voxcraft VXD is read over its base (am_vxa_parse_vxd).
 *
 * The writer produces what VoxCAD writes (ASCII_READABLE structure) plus one <Amorph> element that
 * VoxCAD ignores and this reader uses, holding what VXA cannot say (per-material damping, fixed
 * materials, the volumetric CTE convention, the period in steps), so writing then reading gives
 * back the same lattice and materials bit for bit.
 */

/* what a VXA file says beside the lattice */
typedef struct am_vxa_info {
    am_env env;              /* the file's environment mapped to amorph (docs/vxa.md) */
    double temp_period;      /* s: the actuation period (<TempPeriod>); 0 when there is none */
    int period_steps_given;  /* 1 when the <Amorph> element fixed env.period_steps; else am_vxa_robot
                                gives temp_period as env.period_s, which am_period_steps turns into
                                steps of the robot's step */
    am_eval_def eval;        /* how the robot is evaluated: <Amorph>'s <Evaluation>, else am_default_eval() */
    int key_line[AM_EVO_KEY_MAX]; /* the line of the element that set each configuration key's value (by
                                     the key's index, am_evo_key_name: <DtFrac> dt_frac, <TempPeriod>
                                     period_s, <PeriodSteps> period_steps, <Evaluation>'s elements theirs);
                                     0 where the file set none */
    unsigned char key_vxd[AM_EVO_KEY_MAX]; /* 1 where that line is the VXD file's, not the base's */
    am_layers layers;        /* per-cell layers beyond materials: evosoro's <PhaseOffset>, the boundary
                                conditions' fixed cells and forces (docs/vxa.md); build the model with
                                am_model_build_layers */
    /* VoxCAD's <StopCondition> and evosoro's <InitCmTime> (docs/vxa.md, Run length), for
     * am_vxa_stop_settings once the robot's time step is known */
    int stop_type;           /* <StopConditionType> (VoxCAD's StopCondition: 1 time steps, 2 seconds,
                                3 actuation periods, ...); -1 when the file gives none, or when its
                                <Amorph> element's <Evaluation> says how the robot is evaluated */
    double stop_value;       /* <StopConditionValue> (seconds: with evosoro's <AfterlifeTime> added) */
    double init_cm_time;     /* s: <InitCmTime>, the time before the centre of mass is recorded (0: none) */
    const char* stop_file;   /* the file and line of <StopCondition>, for messages */
    int stop_line;
    char differ[256];        /* the ignored items (of those warned about) that change how the robot moves
                                in VoxCAD, Voxelyze or voxcraft-sim (FluidEnvironment, MatModel, ...),
                                comma separated, each once; empty when none (docs/vxa.md) */
    int warnings;            /* warnings found (all counted, the first ones kept in warning) */
    char warning[AM_VXA_WARN_TEXT]; /* warning lines, each ended by '\n'; NUL-terminated */
} am_vxa_info;

/* 1 when text looks like XML (after an optional byte order mark and blanks it starts with '<') */
AM_API int am_vxa_sniff(const char* text);

/* reads the NUL-terminated VXA text into lat and info, using work as the XML workspace (large:
 * declare it static). fname is used only in messages. AM_ERR_PARSE for malformed XML or VXA,
 * AM_ERR_RANGE for a value outside its range, AM_ERR_CAPACITY past a capacity of the build. */
AM_API am_status am_vxa_parse(am_lattice* lat, am_vxa_info* info, am_xml_doc* work, const char* text, const char* fname, char* err,
                       int errsz);

/* reads a base VXA file with a VXD file over it (voxcraft-sim's convention): every element of the
 * VXD (root <VXD>) with replace="VXA.A.B" stands for the element at that path of the base text,
 * or is added there when the base lacks it; the result is read as one VXA file. vxd_work is a
 * second XML workspace; messages name the file of the element at fault. A VXD text given alone to
 * am_vxa_parse is an error that says so. vxd_text NULL: am_vxa_parse. */
AM_API am_status am_vxa_parse_vxd(am_lattice* lat, am_vxa_info* info, am_xml_doc* work, const char* text, const char* fname,
                           am_xml_doc* vxd_work, const char* vxd_text, const char* vxd_fname, char* err, int errsz);

/* the robot a VXA file read into r->lattice (am_vxa_parse or am_vxa_parse_vxd with lat = r->lattice)
 * and info is: the file's environment, its period in seconds as env.period_s unless the file fixed
 * period_steps, the file's evaluation (the default one unless <Amorph> holds an <Evaluation>), and
 * the file's per-cell layers copied into r->layers.
 * AM_ERR_CAPACITY when the file has layers and r->layers is NULL. */
AM_API am_status am_vxa_robot(am_robot* r, const am_vxa_info* info, char* err, int errsz);

/* The file's run length (info->stop_type, stop_value, init_cm_time) as the evaluation's settings, for
 * a robot whose time step is dt and actuation period period_steps steps of it (dt_ref: the step
 * the relaxation's counts refer to, AM_REF_DT_FRAC dt_rec; all in s): a stop in seconds, time
 * steps or actuation periods, less InitCmTime, becomes cycles (whole periods, rounded), and
 * InitCmTime becomes relax_min_steps (the relaxation, before the centre of mass is recorded,
 * lasts at least that long; relax_max_steps grows by as much), each set through the configuration
 * (am_evo_set_over: its ranges and bounds) unless keep holds its AM_VXA_KEEP_* bit (a flag gave it).
 * note gets "cycles = 40 (<StopCondition> 1 s: 40 periods of 0.025 s), ..." (empty when nothing was
 * set). A value out of its range: AM_ERR_RANGE, "FILE:LINE: <StopCondition> ...: cycles = ...". */
#define AM_VXA_KEEP_CYCLES 1u
#define AM_VXA_KEEP_RELAX 2u
AM_API am_status am_vxa_stop_settings(const am_vxa_info* info, double dt, double dt_ref, int period_steps, unsigned keep, am_eval_def* eval,
                               char* note, int notesz, char* err, int errsz);

/* writes lat and env as a VXA file into buf (capacity cap, NUL-terminated); *len gets its length.
 * dt (s, > 0) is the time step the simulator uses for this robot (env.dt_frac times the model's
 * dt_rec): <TempPeriod> is env.period_steps * dt seconds. AM_ERR_ARG for a lattice or environment
 * that cannot be written, AM_ERR_CAPACITY when buf is short (AM_VXA_TEXT_MAX always suffices). */
AM_API am_status am_vxa_format(const am_lattice* lat, const am_env* env, double dt, char* buf, long cap, long* len, char* err,
                        int errsz);
/* the same with per-cell layers (NULL: none): phases as evosoro's <PhaseOffset> layers (in
 * periods, each value in the shortest form that reads back to the same bits), stiffnesses as its
 * <Stiffness> layers (Pa, likewise), and each voxel with a boundary condition (clamped, or a force)
 * as one box <FRegion> inside its own cell in <Boundary_Conditions>, at most AM_VXA_MAX_BC_VOXELS
 * of them (AM_ERR_CAPACITY past that) */
AM_API am_status am_vxa_format_layers(const am_lattice* lat, const am_layers* layers, const am_env* env, double dt, char* buf, long cap,
                               long* len, char* err, int errsz);
/* the whole robot: its lattice and layers as am_vxa_format_layers writes them, its environment, and
 * its evaluation (cycles, the relaxation's settings, fitness and score) as an <Evaluation> element in
 * <Amorph>, one element per evaluation key of the configuration, so that am_vxa_robot gives back
 * the robot whole and amorph sim evaluates it as the run did (amorph export --vxa) */
AM_API am_status am_vxa_format_robot(const am_robot* r, double dt, char* buf, long cap, long* len, char* err, int errsz);
#define AM_VXA_MAX_BC_VOXELS 256
#define AM_VXA_TEXT_MAX (AM_MAX_MATERIALS * 2048L + AM_MAX_CELLS * 36L + AM_MAX_DIM * 128L + AM_VXA_MAX_BC_VOXELS * 640L + 8192L)

/* the actuation period in steps for a period in seconds and a time step: the nearest whole
 * number, at least 2, at most 10^7 (the range of the configuration's period_steps) */
AM_API int am_vxa_period_steps(double period_s, double dt);

/* ==== a run's checkpoint (docs/evolve.md): the text of checkpoint.txt in the run folder, whose
 * file names and tables are amorph/evo.h's (AM_RUN_*, log.csv, evals.csv) ==== */

/* ---- checkpoints ---- */

/* the run as text (config, stream, counters, population, best), ending with a checksum line */
AM_API am_status am_evo_checkpoint_format(const am_evo* e, char* buf, long cap, long* len, char* err, int errsz);
/* the same text written to out, a whole-text buffer or a stream (amorph/base.h): the checksum is
 * computed on the way, so a stream needs no copy of the whole text */
AM_API am_status am_evo_checkpoint_write(const am_evo* e, am_text* out, char* err, int errsz);
/* reads a checkpoint (checksum first: a damaged file is refused); messages "fname:line: problem".
 * text is used as scratch (its spaces and newlines may be overwritten). It is the two passes
 * below over a whole text. */
AM_API am_status am_evo_checkpoint_parse(am_evo* e, char* text, const char* fname, char* err, int errsz);

/* A checkpoint that is not held whole (a file streamed through a small buffer) is read in two
 * passes: the scan takes its bytes in pieces of any size and checks the checksum; the reader then
 * takes its lines one at a time. Same results and messages as am_evo_checkpoint_parse. */
typedef struct am_evo_ckpt_scan {
    long bytes;                 /* bytes seen */
    int lines;                  /* newlines seen */
    uint64_t hash;              /* hash of every byte seen */
    uint64_t line_hash;         /* hash of the bytes before the current line */
    uint64_t prev_hash;         /* hash of the bytes before the last whole line */
    char cur[32], prev[32];     /* the first bytes of the current and of the last whole line */
    long cur_len, prev_len;     /* their lengths */
    int config_end;             /* line of the first "config-end" after the first configuration line, 0 if none */
    int last_end;               /* line of the last "end" line, 0 if none */
    int checksum_line;          /* set by am_evo_checkpoint_scan_end: the last line, the checksum */
    int cr;                     /* 1: the last byte seen was a CR (left out when a LF follows) */
} am_evo_ckpt_scan;
AM_API void am_evo_checkpoint_scan_begin(am_evo_ckpt_scan* sc);
AM_API void am_evo_checkpoint_scan(am_evo_ckpt_scan* sc, const char* data, long n);
/* after the last byte: AM_OK when the last line is a checksum that matches the text before it */
AM_API am_status am_evo_checkpoint_scan_end(am_evo_ckpt_scan* sc, const char* fname, char* err, int errsz);

/* a remembered body's result in a checkpoint: 28 numbers of 8 bytes, and one more per material
 * past the third (at most) */
#define AM_EVO_MEMO_RESULT_BYTES (8 * (25 + AM_MAX_GENO_MATERIALS))

/* pass 2, after a successful scan: begin (clears e), every line in order, end */
typedef struct am_evo_ckpt_reader {
    am_evo* e;
    const char* fname;          /* for messages; must stay valid while reading */
    int line;                   /* lines read */
    int until, config_end, last_end; /* from the scan */
    am_status st;               /* the first failure: every later call returns it */
    int version;                /* the checkpoint's format version (1 to 3) */
    int seen_rng, seen_gen, seen_evals, seen_hist, seen_last, pop_seen, best_seen;
    uint8_t pop_have[AM_MAX_POPULATION]; /* 1 for each member index read */
    int in_genome;              /* 1 while the lines of an individual's genome are read */
    am_evo_ind* ind;            /* that individual */
    int ind_pop;                /* 1 for a member of the population, 0 for the best */
    long idx;                   /* its index */
    int first;                  /* the first line of its genome */
    char where[96];             /* "fname (genome from line N)", the genome's file name in messages */
    int key_line[AM_EVO_KEY_MAX]; /* the line that set each key of the configuration, 0 if none */
    am_genome_reader gr;
    int memo_slot;              /* the remembered body being read, -1 none */
    int memo_line;              /* its 'memo' line */
    long memo_have, memo_need;  /* its bytes read, and all of them */
    uint8_t memo_res[AM_EVO_MEMO_RESULT_BYTES]; /* its result's numbers as read */
} am_evo_ckpt_reader;
AM_API void am_evo_checkpoint_read_begin(am_evo_ckpt_reader* r, am_evo* e, const am_evo_ckpt_scan* sc, const char* fname);
/* one line of n characters, NUL-terminated at n (used as scratch: its spaces may be overwritten);
 * lines from the checksum line on are ignored */
AM_API am_status am_evo_checkpoint_read_line(am_evo_ckpt_reader* r, char* text, long n, char* err, int errsz);
AM_API am_status am_evo_checkpoint_read_end(am_evo_ckpt_reader* r, char* err, int errsz);
/* the largest checkpoint text of a population of n */
#define AM_EVO_CHECKPOINT_MAX(n) (16384L + ((long)(n) + 1) * (AM_GENOME_TEXT_MAX + 256L) + AM_EVO_MEMO * AM_EVO_MEMO_TEXT_MAX)
/* the text of one remembered body: its memo line, then base64 lines of 48 bytes (64 characters) */
#define AM_EVO_MEMO_TEXT_MAX (80L + (AM_EVO_MEMO_RESULT_BYTES + AM_EVO_MEMO_BYTES + 47L) / 48L * 68L)

#ifdef __cplusplus
}
#endif
#endif
