/*
 * geom2d.h — private to src/scad: what offset(), projection(), minkowski()
 * and text() share — OpenSCAD's fragment count, 2D subtrees flattened to
 * polygon sets through the scad_services polygon booleans, and polygon sets
 * turned back into region leaves.
 */
#ifndef RAYSCAD_SCAD_GEOM2D_H
#define RAYSCAD_SCAD_GEOM2D_H

#include "eval.h"

/* $fn, $fa, $fs as a call sees them (its own arguments first). */
typedef struct scad_facet_params {
    double fn, fa, fs;
} scad_facet_params;

scad_facet_params scad_facets_lookup(scad_eval *ev, scad_env *env, const scad_argv *a,
                                     scad_loc loc);
/* OpenSCAD 2021.01's get_fragments_from_r (capped at 100000). */
int scad_fragments(double r, scad_facet_params f);
/* 1 when a round shape of radius r at these settings is built with
 * OpenSCAD's facets (the --facets rule). */
int scad_facets_shown(const scad_eval *ev, scad_facet_params f, double r);

/* Keep one reference to s's data until the end of the evaluation (in
 * ev->owned, released by scad_geometry_release).  Returns 0, or -1 when out
 * of memory (then s's data is released). */
int scad_geom_keep(scad_eval *ev, iv_shape *s);

/* A 2D leaf over the polygon set p (borrowed; copied), placed by state;
 * NULL when p is empty or out of memory. */
scad_geom *scad_region_geom(scad_eval *ev, const scad_paths *p, const scad_state *state);

void scad_paths_free(scad_paths *p);

/* 1 when g is a 2D leaf: a prism over the preview slab z in [-½, ½] (an
 * extruded prism has its own z range; a linear_extrude(1, center = true)
 * is the one extrusion that reads as 2D). */
int scad_geom_is_flat(const scad_geom *g);
/* Which kinds of leaves a subtree holds: bit 1 a 2D leaf, bit 2 a 3D one. */
int scad_geom_dims(const scad_geom *g);

/* The 2D subtree g as one normalised polygon set in the frame
 * local_from_world (leaves' transforms applied, their z dropped), its
 * unions, intersections and differences done by the paths_clip service;
 * 3D leaves count as empty.  Smooth discs get OpenSCAD's fragments where
 * facets are shown at f, else 256.  Returns 0 and *out (empty when g is),
 * or -1 after reporting an error at loc (no paths_clip service, or it
 * failed). */
int scad_flatten_2d(scad_eval *ev, const scad_geom *g, const csg_affine local_from_world,
                    scad_facet_params f, scad_loc loc, const char *who, scad_paths *out);

/* The modules (the table of builtin_geometry.c points at them). */
scad_geom *scad_module_offset(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_argv *a, const scad_state *state);
scad_geom *scad_module_projection(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                  const scad_argv *a, const scad_state *state);
scad_geom *scad_module_minkowski(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                 const scad_argv *a, const scad_state *state);
scad_geom *scad_module_text(scad_eval *ev, scad_env *env, const scad_stmt *st,
                            const scad_argv *a, const scad_state *state);

#endif
