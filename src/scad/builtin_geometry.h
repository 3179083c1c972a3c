/*
 * builtin_geometry.h — private to src/scad: the geometry modules of
 * builtin_geometry.c (2D shapes, polyhedron, extrusions, hull, and the
 * faceted forms of sphere and cylinder) and the end-of-evaluation release of
 * the shape data they made.
 */
#ifndef RAYSCAD_BUILTIN_GEOMETRY_H
#define RAYSCAD_BUILTIN_GEOMETRY_H

#include "eval.h"
#include "geom2d.h" /* offset, projection, minkowski, text */

/* import() and surface() (builtin_import.c). */
scad_geom *scad_module_import(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_argv *a, const scad_state *state);
scad_geom *scad_module_surface(scad_eval *ev, scad_env *env, const scad_stmt *st,
                               const scad_argv *a, const scad_state *state);

/* The module called name, or NULL.  Consulted before the table of
 * builtin_modules.c, so its sphere and cylinder win. */
scad_builtin_mod scad_geometry_module(const char *name);

/* Drop the evaluation's own references to the shape data made while it ran
 * (the csg nodes made from the geometry hold theirs).  Call once, after the
 * trees are converted. */
void scad_geometry_release(scad_eval *ev);

/* A leaf of shape s placed by state: the evaluation takes s's reference
 * (dropped by scad_geometry_release).  NULL when out of memory, s's data
 * then released. */
scad_geom *scad_geometry_leaf(scad_eval *ev, iv_shape *s, const scad_state *state);

#endif
