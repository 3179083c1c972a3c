/*
 * builtin_geometry.h — private to src/scad: the geometry modules of
 * builtin_geometry.c (2D shapes, polyhedron, extrusions, hull, and the
 * faceted forms of sphere and cylinder) and the end-of-evaluation release of
 * the shape data they made.
 */
#ifndef RAYSCAD_BUILTIN_GEOMETRY_H
#define RAYSCAD_BUILTIN_GEOMETRY_H

#include "eval.h"

/* The module called name, or NULL.  Consulted before the table of
 * builtin_modules.c, so its sphere and cylinder win. */
scad_builtin_mod scad_geometry_module(const char *name);

/* Drop the evaluation's own references to the shape data made while it ran
 * (the csg nodes made from the geometry hold theirs).  Call once, after the
 * trees are converted. */
void scad_geometry_release(scad_eval *ev);

#endif
