/*
 * rayscad_internal.h — private to the library's face (src/rayscad): what
 * the public handles of include/rayscad.h hold.
 */
#ifndef RAYSCAD_LIB_INTERNAL_H
#define RAYSCAD_LIB_INTERNAL_H

#include "../../include/rayscad.h"
#include "../csg/csg.h"
#include "../mesh/mesh.h"
#include "../scad/scad.h"

struct rayscad_model {
    scad_result r; /* its trees go to the scene */
};

struct rayscad_scene {
    csg_scene *s;
    double facet_sag; /* the model's scad_result.facet_sag */
};

struct rayscad_sampling {
    mesh_dexels *d;
};

struct rayscad_mesh {
    mesh *m;
    double tolerance; /* simplified to; 0: the contour as it is */
};

/* err (errlen bytes, may be NULL) gets the message. */
void rayscad_say(char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
