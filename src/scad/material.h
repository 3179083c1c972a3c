/*
 * material.h — private to src/scad: the renderer's optics, read from
 * rayscad's own $rs_ variables (which OpenSCAD ignores).
 */
#ifndef RAYSCAD_SCAD_MATERIAL_H
#define RAYSCAD_SCAD_MATERIAL_H

#include "eval.h"

/* Fill the optical fields of *m (reflect, absorb, ior, emit, light) for a
 * leaf of shape s placed by world_from_object xf, from the $rs_ variables
 * visible where the leaf is instantiated: its own arguments a first (may be
 * NULL), then env's dynamic scope, as $fn is found.  Values out of range are
 * clamped; values of the wrong type are ignored.  Never fails. */
void scad_material_apply(scad_eval *ev, scad_env *env, const scad_argv *a, const iv_shape *s,
                         const csg_affine xf, csg_material *m);

#endif
