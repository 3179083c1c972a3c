/*
 * geometry_services.h — the 2D geometry members of the command's
 * scad_services (offset, projection, minkowski, text): polygon booleans,
 * offsets and Minkowski sums through src/io/polygon.h (Clipper), text
 * outlines through src/io/text.h (FreeType, HarfBuzz, fontconfig), and the
 * meshing of a csg tree through src/mesh.  Each has the signature and the
 * contract of its scad_services member (src/scad/scad.h); ud is unused.
 */
#ifndef RAYSCAD_CLI_GEOMETRY_SERVICES_H
#define RAYSCAD_CLI_GEOMETRY_SERVICES_H

#include "../scad/scad.h"

int cli_paths_clip(void *ud, int op, const scad_paths *a, int a_evenodd, const scad_paths *b,
                   int b_evenodd, scad_paths *out, char *err, size_t errlen);
int cli_paths_offset(void *ud, const scad_paths *a, double delta, int join, double miter_limit,
                     double arc_tolerance, scad_paths *out, char *err, size_t errlen);
int cli_paths_minkowski(void *ud, const scad_paths *a, const scad_paths *b, scad_paths *out,
                        char *err, size_t errlen);
/* Meshes at h, or at 1/256 of the longest side when h <= 0. */
int cli_mesh_tree(void *ud, csg_node *root, double h, float **v, int *nv, int32_t **t, int *nt,
                  char *err, size_t errlen);
int cli_text(void *ud, const scad_text_params *p, scad_paths *out, char *err, size_t errlen);

#endif
