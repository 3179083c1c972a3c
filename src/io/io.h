/*
 * io.h — the C face of the C++ adapters: images through OpenImageIO,
 * meshes through OpenMesh (with the mesh exporter), AMF through libxml2 and
 * 3MF through lib3mf (for import(), and both written for export).  Nothing
 * here prints or throws: every C++ exception is caught at this boundary and
 * becomes a status with a message.
 */
#ifndef RAYSCAD_IO_H
#define RAYSCAD_IO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Write a width × height image with `channels` (3 or 4) floats per pixel,
 * row-major from the top, values sRGB-encoded in [0, 1] (alpha straight, not
 * premultiplied).  The format follows the extension of path (png, jpg/jpeg,
 * tif/tiff, exr, …): 8-bit sRGB for LDR formats; linear half floats for
 * EXR/HDR.  The file is written to a temporary name beside path and renamed,
 * so a failure never leaves a partial file nor touches an existing one.
 * Returns 0, or -1 with a message in err. */
int io_image_write(const char *path, int width, int height, int channels, const float *pixels,
                   char *err, size_t errlen);

/* Read an image as sRGB-encoded floats (channels as stored, 1–4).  *pixels
 * is malloc'ed; the caller frees it.  Returns 0, or -1 with a message. */
int io_image_read(const char *path, int *width, int *height, int *channels, float **pixels,
                  char *err, size_t errlen);

/* 1 when the extension of path names an image format OpenImageIO can
 * write, else 0.  OpenImageIO is loaded on the first image read or write
 * (image_loader.c); png, jpg, jpeg, tif, tiff and exr are answered without
 * loading it. */
int io_image_format_supported(const char *path);

/* Load OpenImageIO now rather than at the first image call (a caller that
 * must control the conditions of the load, such as a memory limit).
 * Returns 0, or -1 with the reason in err. */
int io_image_load(char *err, size_t errlen);

/* ---- meshes (OpenMesh; src/io/mesh.cpp) --------------------------------- */

/* Meshes cross this boundary as flat arrays: v holds 3 floats (x, y, z) per
 * vertex, t holds 3 int32 vertex indices per triangle (counter-clockwise
 * seen from outside), as mesh_vertices / mesh_triangles give them. */

/* 1 when path ends in "." and ext (given in lower case), in any case. */
int io_path_has_extension(const char *path, const char *ext);

/* 1 when the extension of path (case-insensitive) is a mesh format
 * io_mesh_write and io_mesh_read handle: stl, off, obj, ply. */
int io_mesh_format_supported(const char *path);

/* The colours of a mesh's triangles (NULL where a mesh has none): triangle
 * i has colour rgba[of_tri[i] - 1] (sRGB and alpha in [0, 1]), or
 * io_default_rgba when of_tri[i] is 0. */
typedef struct io_colors {
    const float (*rgba)[4];
    int n;
    const uint16_t *of_tri;
} io_colors;

/* openscad's colour for a rendered object of no color(): the Cornfield
 * scheme's #f9d72c. */
extern const float io_default_rgba[4];

/* The colour of triangle i as 8-bit sRGB and alpha. */
void io_color_bytes(const io_colors *c, int i, unsigned char out[4]);

/* Write nv vertices and nt triangles (borrowed) to path in the format of its
 * extension: STL binary (ascii != 0: ASCII STL), PLY binary (ascii != 0:
 * ASCII PLY), OFF and OBJ always ASCII; ASCII numbers carry 9 significant
 * digits, so floats survive the round trip.  STL gets face normals.  With
 * colours c (may be NULL): PLY gets a red, green, blue, alpha per face, and
 * OBJ a material per colour in a material file beside it (path's name with
 * .mtl, written first; io_obj_write).  The file is written to a temporary
 * name beside path and renamed, so a failure never leaves a partial file
 * nor touches an existing one.  Returns 0, or -1 with a message in err
 * (unknown extension, an index out of range, a triangle that would make the
 * mesh non-manifold, an I/O error). */
int io_mesh_write(const char *path, const float *v, int nv, const int32_t *t, int nt, int ascii,
                  const io_colors *c, char *err, size_t errlen);

/* OBJ with colours (src/io/obj.c): the material file (newmtl per colour,
 * Kd and d), then the OBJ naming it with mtllib, its faces grouped by
 * colour under usemtl; both through temporary files.  0, or -1 with a
 * message in err. */
int io_obj_write(const char *path, const float *v, int nv, const int32_t *t, int nt,
                 const io_colors *c, char *err, size_t errlen);

/* Read a mesh file (stl, off, obj, ply) into malloc'ed arrays *v (3 floats
 * per vertex) and *t (3 indices per triangle) that the caller frees.  STL
 * vertices that coincide exactly are merged into one, so a closed mesh
 * written as STL comes back indexed.  Do not feed it OFF files with the
 * counts on the OFF line (as OpenSCAD writes them): OpenMesh 9.0 runs out of
 * memory on those.  Returns 0, or -1 with a message (then *v = *t = NULL). */
int io_mesh_read(const char *path, float **v, int *nv, int32_t **t, int *nt, char *err,
                 size_t errlen);

/* ---- AMF and 3MF import (src/io/amf.cpp, src/io/3mf.cpp) ---------------- */

/* Read the meshes of an AMF file (libxml2; a ZIP-compressed AMF through
 * libzip) or of a 3MF file (lib3mf 1.8) as OpenSCAD 2021.01's import()
 * reads them: every object's triangles, objects concatenated into one
 * mesh (their union under the nonzero winding rule), in the arrays' usual
 * conventions: *v and *t malloc'ed for the caller, *nv = *nt = 0 when
 * the file holds no triangle.  msg (msglen bytes) receives lines separated
 * by '\n', each a warning worded as OpenSCAD words it ("Failed to parse
 * file '…'", "Could not read file '…'", "Can't open import file '…'"),
 * with rayscad's reason appended after a colon, or, starting with "note: ",
 * a remark of rayscad's own; "" when there are none.  Returns 0 (msg may
 * still hold warnings: an AMF that fails to parse after complete objects
 * keeps them, as in 2021.01), or -1 when nothing could be read (then the
 * last line of msg says why and *v = *t = NULL). */
int io_amf_read(const char *path, float **v, int *nv, int32_t **t, int *nt, char *msg,
                size_t msglen);
int io_3mf_read(const char *path, float **v, int *nv, int32_t **t, int *nt, char *msg,
                size_t msglen);

/* ---- AMF and 3MF export (src/io/amf.cpp, src/io/3mf.cpp) ---------------- */

/* Write nv vertices and nt triangles (borrowed; the conventions above) to
 * path as one object in millimetres, as OpenSCAD 2021.01 exports them:
 * io_amf_write an uncompressed AMF (2021.01's layout, CRLF line ends,
 * coordinates with 9 significant digits so floats read back exactly);
 * io_3mf_write a 3MF package through lib3mf (one mesh object, one build
 * item; lib3mf keeps six decimals of each coordinate, cut toward zero).
 * The extension of path is not looked at.  Any triangle soup is accepted,
 * closed or not; refused: a coordinate that is NaN or infinite, an index
 * out of range, a triangle with a repeated vertex.  With colours c (may be
 * NULL), io_3mf_write gives every triangle its colour (the materials
 * extension's colour group, the object's default being io_default_rgba).
 * The file is written to a temporary
 * name beside path and renamed, so a failure never leaves a partial file
 * nor touches an existing one.  Returns 0, or -1 with a message in err. */
int io_amf_write(const char *path, const float *v, int nv, const int32_t *t, int nt, char *err,
                 size_t errlen);
int io_3mf_write(const char *path, const float *v, int nv, const int32_t *t, int nt,
                 const io_colors *c, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
