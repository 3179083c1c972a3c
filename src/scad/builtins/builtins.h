/*
 * builtins.h — private to src/scad/builtins: what the files of OpenSCAD's
 * builtin library share.  Each family file (primitives.c, operations.c …)
 * declares its modules and functions as registry entries (../registry.h)
 * and lists them for registry.c; everything else here is a helper for
 * reading arguments, printing .csg headers and making geometry.
 */
#ifndef RAYSCAD_SCAD_BUILTINS_H
#define RAYSCAD_SCAD_BUILTINS_H

#include "../registry.h"
#include "../../geom/bsp.h"

/* ---- the families (NULL-terminated lists for registry.c) ------------------ */

extern const scad_module_def *const scad_primitive_modules[]; /* primitives.c */
extern const scad_module_def *const scad_operation_modules[]; /* operations.c */
extern const scad_module_def *const scad_extrude_modules[];   /* extrude.c */
extern const scad_module_def *const scad_hull_modules[];      /* hull.c */
extern const scad_module_def *const scad_ops2d_modules[];     /* ops2d.c */
extern const scad_module_def *const scad_minkowski_modules[]; /* minkowski.c */
extern const scad_module_def *const scad_import_modules[];    /* import.c */
extern const scad_module_def *const scad_text_modules[];      /* text.c */
extern const scad_function_def scad_math_functions[];         /* math.c, ends with name NULL */
extern const scad_function_def scad_dxf_functions[];          /* dxf.c, ends with name NULL */

/* ---- reading arguments (args.c): OpenSCAD 2021.01's conversions ------------ */

/* $fn, $fa, $fs as a call sees them: its own $-arguments, else the dynamic
 * scope; a value that is not a number counts as 0 (Value::toDouble).  Kept
 * as they are, as OpenSCAD's nodes keep them (the fragment rule clamps). */
typedef struct scad_facet_params {
    double fn, fa, fs;
} scad_facet_params;

scad_facet_params scad_facets_read(scad_call *c);
/* The same with OpenSCAD's primitives' clamping: $fs and $fa below 0.01
 * become 0.01, each with its warning (circle, sphere, cylinder). */
scad_facet_params scad_facets_read_clamped(scad_call *c);
/* OpenSCAD 2021.01's get_fragments_from_r: 3 below the finest radius or
 * for an infinite or NaN $fn, $fn itself (at least 3) when positive, else
 * from $fa and $fs; capped at 100000 (OpenSCAD has no cap; more would not
 * fit a polytope). */
int scad_fragments(double r, scad_facet_params f);
/* 1 when a round shape of radius r at these settings is built with
 * OpenSCAD's facets (the --facets rule). */
int scad_facets_shown(const scad_eval *ev, scad_facet_params f, double r);

/* x from a number (Value::getDouble): 1 when v is one, else x untouched. */
int scad_arg_num(scad_value v, double *x);
/* A vector of exactly n numbers (Value::getVec2/getVec3): the elements
 * are taken in turn until one is not a number, which ends it (the rest
 * keep their values); 1 when all n were numbers. */
int scad_arg_vec(scad_value v, int n, double *out);
/* 1 when v is the boolean true; dflt when v is no boolean. */
int scad_arg_bool(scad_value v, int dflt);
/* A number as an int the way OpenSCAD's nodes take convexity and the
 * like: dflt when not a finite number, else clamped to int. */
int scad_arg_int(scad_value v, int dflt);
/* OpenSCAD's lookup_radius: a numeric diameter d (halved) wins over the
 * radius r, with OpenSCAD's warning when both are numbers; 1 when either
 * gave *out. */
int scad_arg_radius(scad_call *c, int d, int r, const char *dname, const char *rname, double *out);

/* ---- printing .csg headers (print.c) ---------------------------------------- */

/* An ostream's default form of a double (6 significant digits: "1e+06"). */
void scad_print_g(scad_buf *b, double x);
void scad_print_bool(scad_buf *b, int x);
/* before, "$fn = …, $fa = …, $fs = …", after. */
void scad_print_facets(scad_buf *b, scad_facet_params f, const char *before, const char *after);
/* OpenSCAD 2021.01's lookup_file: name relative to the folder of the file
 * `from` unless absolute or empty; where it is not there but in the main
 * file's folder, that one, with its DEPRECATED line.  Appended to out. */
void scad_lookup_file(scad_eval *ev, const char *from, const char *name, scad_buf *out);
/* The path of `name` (as written in the file `from`) as OpenSCAD prints it:
 * relative to the main file's folder; *mtime gets its modification time
 * (0 when it does not exist). */
void scad_print_path(scad_eval *ev, const char *from, const char *name, scad_buf *out,
                     long long *mtime);

/* The file = …, layer = …, origin = … of import() and the extrusions. */
typedef struct scad_file_arg {
    const char *name; /* the file as written (borrowed), NULL when none */
    scad_value layer; /* borrowed; undef when none */
    double origin[2]; /* [0, 0] unless two numbers were given */
} scad_file_arg;

/* Read them from parameters file, layer and origin (alt_file, alt_layer:
 * the alternative names import() takes, or -1).  An origin that is given
 * but not two finite numbers warns as OpenSCAD's `who` does (NULL: no
 * warning). */
void scad_file_arg_read(scad_call *c, int file, int layer, int origin, int alt_file, int alt_layer,
                        const char *who, scad_file_arg *out);
/* "file = "…", layer = "…", origin = [x, y]" as OpenSCAD prints them (the
 * path relative to the main file's folder); *mtime gets the file's
 * modification time, 0 when it does not exist. */
void scad_file_arg_print(scad_call *c, const scad_file_arg *f, scad_buf *b, long long *mtime);
/* The path OpenSCAD opens for name (scad_lookup_file from the call's file). */
void scad_file_path(scad_call *c, const char *name, scad_buf *out);

/* ---- geometry (shape.c, material.c) ---------------------------------------- */

/* A leaf of shape s placed by state: the evaluation takes s's reference.
 * NULL when out of memory, s's data then released. */
scad_geom *scad_geometry_leaf(scad_eval *ev, iv_shape *s, const scad_state *state);
/* A leaf of shape s at state's transform, then local (may be NULL); the
 * caller keeps s's reference (already kept). */
scad_geom *scad_leaf_at(scad_eval *ev, const iv_shape *s, const scad_state *state,
                        const csg_affine local);
/* The same with the $rs_ optics of the call (its arguments, then its
 * scope) in the leaf's material. */
scad_geom *scad_optics_leaf(scad_call *c, const iv_shape *s, const csg_affine local);
/* Half the thickness of the slab OpenSCAD 2021.01 previews a 2D object as
 * (measured: a side view of square(10) shows z from -0.5 to 0.5). */
#define SCAD_SLAB 0.5

/* A 2D leaf: region g (its reference passes to the evaluation) in the
 * preview slab; NULL when g is NULL or out of memory. */
scad_geom *scad_region_leaf(scad_eval *ev, iv_region *g, const scad_state *state);
/* The n-gon OpenSCAD makes of a circle of radius r (a new reference); NULL
 * when out of memory. */
iv_region *scad_circle_region(double r, int n);
/* The call's children evaluated as one union under state (NULL: the
 * call's own). */
scad_geom *scad_call_children(scad_call *c, const scad_state *state);
/* g (a leaf, or NULL) with the call's $rs_ optics in its material. */
scad_geom *scad_with_optics(scad_call *c, scad_geom *g);
/* Circle point i of n at radius r, OpenSCAD's generate_circle. */
void scad_circle_point(double r, int i, int n, double out[2]);
/* Ring i of the `rings` of OpenSCAD's sphere of radius r: its radius *rr
 * at height *z (primitives.cc's ring at phi = 180°·(i + ½)/rings). */
void scad_sphere_ring(double r, int i, int rings, double *rr, double *z);
/* OpenSCAD's fragment count of a round leaf (a sphere, a cone or a disc):
 * the one recorded when it was made (g->cap), else what f gives its
 * radius. */
int scad_leaf_fragments(const scad_geom *g, scad_facet_params f);

/* Fill the optical fields of *m (reflect, absorb, ior, emit, light) for a
 * leaf of shape s placed by world_from_object xf, from the $rs_ variables
 * visible to the call: its own arguments first, then its dynamic scope.
 * Values out of range are clamped; values of the wrong type are ignored. */
void scad_material_apply(scad_call *c, const iv_shape *s, const csg_affine xf, csg_material *m);

/* A 2D leaf over the polygon set p (borrowed; copied), placed by state;
 * NULL when p is empty or out of memory. */
scad_geom *scad_region_geom(scad_eval *ev, const scad_paths *p, const scad_state *state);
void scad_paths_free(scad_paths *p);

/* 1 when g is a 2D leaf: a prism over the preview slab z in [-½, ½] that
 * no linear_extrude() made (g->extruded: linear_extrude(1, center = true)
 * makes that same prism, in 3D). */
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

/* The boundary of the 3D subtree g as OpenSCAD tessellates it, in the
 * frame local_from_world: convex polygons facing out, its booleans
 * resolved (solid.c); 2D leaves count as empty.  Returns 0, or -1 after
 * reporting an error at loc (out of memory, the work bound hit). */
int scad_solid_polys(scad_eval *ev, scad_loc loc, const char *who, const scad_geom *g,
                     const double local_from_world[12], scad_facet_params f, geom_polys *out);
/* The faces of leaf g alone (nothing for a 2D leaf).  0, or -1 out of
 * memory. */
int scad_leaf_polys(const scad_geom *g, const double local_from_world[12], scad_facet_params f,
                    geom_polys *out);

/* The distinct vertices of the polygons, sorted, into *V (malloc'ed, *nv of
 * them); map (may be NULL; p->nv entries) gets each polygon vertex's index
 * in *V.  0, or -1 out of memory. */
int scad_polys_vertices(const geom_polys *p, double (**V)[3], int *nv, int *map);
/* The polygons as a mesh leaf's shape (repeated points merged), in *out.
 * 0, or -1 when out of memory or empty. */
int scad_polys_mesh(const geom_polys *p, iv_shape *out);

/* import() of a DXF file (dxf.c): the drawing as one 2D leaf, read with the
 * call's layer, origin, scale and $fn/$fa/$fs. */
scad_geom *scad_dxf_import(scad_call *c, const char *path, const char *layer,
                           const double origin[2], double scale, scad_facet_params f);

/* import() of an SVG file (svg.c): the drawing as one 2D leaf at dpi
 * (user units per inch), centred on its bounding box when center. */
scad_geom *scad_svg_import(scad_call *c, const char *path, double dpi, int center);

/* Web colour by lower-case name (colors.c); returns 1 and fills rgba
 * (0..1) or 0. */
int scad_color_by_name(const char *name, float rgba[4]);
/* "#rgb", "#rgba", "#rrggbb" or "#rrggbbaa" (operations.c); returns 1 and
 * fills rgba, or 0. */
int scad_color_by_hex(const char *s, float rgba[4]);

#endif
