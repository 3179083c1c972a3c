/*
 * registry.h — private to src/scad: the builtin library as the language sees
 * it.  Each builtin module and function is one entry, declared once: its
 * name, its parameters, how it reads its arguments, how it prints itself in
 * OpenSCAD's .csg and what it builds.  The evaluator binds a call's
 * arguments to the entry's parameters (the same rule as for user modules,
 * with its warnings), then asks the entry to read them once, and prints or
 * builds from what was read; it reaches the library through nothing else.
 */
#ifndef RAYSCAD_SCAD_REGISTRY_H
#define RAYSCAD_SCAD_REGISTRY_H

#include "eval.h"

enum { SCAD_MAX_PARAMS = 16 };

typedef struct scad_call scad_call;

typedef struct scad_module_def {
    const char *name;
    /* Its parameters (at most SCAD_MAX_PARAMS), NULL-terminated, in
     * OpenSCAD 2021.01's order; NULL when it has none.  The first
     * npositional take the call's unnamed arguments in turn, the rest are
     * given by name only.  A named argument that is none of them warns
     * "variable x not specified as parameter" ($-names excepted). */
    const char *const *params;
    int npositional;
    /* read fills args (size bytes, zeroed first; at most SCAD_MAX_ARGS)
     * from the bound arguments, with OpenSCAD's conversions, defaults and
     * warnings.  NULL when the module takes no arguments. */
    size_t size;
    void (*read)(scad_call *c, void *args);
    /* Its .csg header ("cube(size = [1, 1, 1], center = false)") into out;
     * returns 1 when the node lists its children.  NULL: "name()" with its
     * children. */
    int (*print)(scad_call *c, const void *args, scad_buf *out);
    /* Its geometry, evaluating its children as it needs; NULL: none. */
    scad_geom *(*build)(scad_call *c, const void *args);
} scad_module_def;

enum { SCAD_MAX_ARGS = 512 };

/* One instantiation of a builtin module. */
struct scad_call {
    scad_eval *ev;
    scad_env *env;           /* the caller's scope, with the call's $-arguments */
    const scad_stmt *st;     /* name, location, children */
    const scad_state *state; /* the inherited transform and colour */
    const scad_module_def *def;
    const scad_argv *argv; /* every argument, by resolved name */
    /* arg[i] is the value bound to params[i] (borrowed), undef when none */
    scad_value arg[SCAD_MAX_PARAMS];
};

/* A builtin function: an owned result from borrowed arguments, taken in
 * order (OpenSCAD's builtin functions ignore argument names). */
typedef struct scad_function_def {
    const char *name;
    const char *params; /* what each position means: "x", "a, b" … */
    scad_value (*fn)(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *name);
} scad_function_def;

/* The module (function) called name, or NULL; *id (may be NULL) gets its
 * index below scad_registry_module_count(), the same in every run. */
const scad_module_def *scad_registry_module(const char *name, int *id);
const scad_function_def *scad_registry_function(const char *name);
int scad_registry_module_count(void);

#endif
