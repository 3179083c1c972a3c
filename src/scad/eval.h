/*
 * eval.h — private to src/scad: the evaluator's state, environments, the
 * geometry it builds, and the interface of the builtin functions and
 * modules.
 */
#ifndef RAYSCAD_SCAD_EVAL_H
#define RAYSCAD_SCAD_EVAL_H

#include "value.h"

/* ---- geometry ---------------------------------------------------------------
 * The evaluator builds a light tree of scad_geom in its arena; at the end it
 * is turned into csg nodes (a '#' subtree twice: in the model and in the
 * highlight tree).
 *
 * In dump mode (scad_eval.dump) the same tree holds OpenSCAD's node tree
 * instead, for the .csg text: every node has its header in `text`
 * ("cube(size = [1, 1, 1], center = false)", with any '#'/'%' prefix), no
 * geometry, and keeps all its children, empty groups included.  A node with
 * text NULL is a bare list (the children one scope produced): adding it to
 * a parent adds its children in its place.
 *
 * An operation node is allocated without the leaf's members (from shape
 * on: 48 bytes instead of 256), so they may be read only where is_leaf is
 * set; a leaf may become an empty operation (is_leaf cleared), never the
 * other way round.  A model such as children() doubling 20 times holds
 * about as many operations as leaves. */
typedef struct scad_geom scad_geom;
struct scad_geom {
    int is_leaf;
    csg_op op;
    scad_geom **kids;
    int n, cap;
    const char *text; /* dump mode only */
    int whole;        /* op: one piece of geometry in the preview (csg_node_frame_whole) */
    int extruded;     /* leaf: made by linear_extrude(), 3D even over the 2D slab */
    int raw2d;        /* leaf: square() or circle(), exported unclipped when alone */
    scad_loc loc;     /* the statement that made it (scad_eval_here) */
    /* leaves only */
    iv_shape shape;
    csg_affine xf;
    csg_material mat;
};

/* What a subtree inherits: the accumulated world_from_object transform and
 * the colour of the outermost color() (OpenSCAD 2021.01: the first color()
 * met going down wins). */
typedef struct scad_state {
    csg_affine xf;
    csg_material mat;
} scad_state;

/* ---- environments ----------------------------------------------------------- */

typedef struct scad_var {
    const char *name;
    scad_value v;
} scad_var;

/* The special variables that every primitive reads (facets, animation,
 * rayscad's materials), which each environment finds in O(1): see
 * scad_env.special. */
enum { SCAD_ENV_NSPECIAL = 9 };

/* A context: variables, the definitions of a scope, lexical parent (for
 * plain names, functions and modules) and dynamic parent (the caller, for
 * $-variables).  A module call's context also knows its children.
 *
 * special[k] is the nearest environment on the dynamic chain, this one
 * included, that defines the k-th well-known special variable (env.c:
 * special_names), or NULL: inherited from dyn when the environment is
 * made, and pointed at itself when the name is first set here.  It stays
 * exact because an environment's variables are only set while no
 * environment below it on the dynamic chain is alive, except for those a
 * closure captured, which never start a $-lookup again. */
struct scad_env {
    scad_env *parent, *dyn;
    const scad_scope *defs;
    scad_var *vars;
    int nvars, cap;
    scad_var inline_vars[4];
    /* Past ENV_INDEXED variables, vars by name: open addressing on the
     * interned name's hash, slot = 1 + index into vars, 0 empty. */
    int *index;
    uint32_t index_mask;
    scad_env *special[SCAD_ENV_NSPECIAL];
    int is_module;
    const scad_scope *children;
    scad_env *children_env;
    int captured; /* a function literal refers to it: freed at the end */
    scad_env *next_captured;
};

typedef struct scad_eval {
    scad_diag *d;
    const scad_scope *top; /* the main file's scope: the fonts the files `use` */
    scad_names *names;     /* the parse's; names set from C are interned here */
    /* interned names the evaluator compares with: "$children",
     * "$parent_modules", and the control modules that are no keywords */
    const char *sym_children, *sym_parent_modules, *sym_children_module, *sym_intersection_for;
    /* the interned parameters of each builtin module (registry.h), made
     * on first use: scad_registry_module_count() of them */
    scad_args *builtin_params;
    scad_arena *arena; /* geometry */
    int depth, max_depth;
    int max_list, max_string; /* value size limits (scad_options) */
    long steps, max_steps;    /* work done and its limit (scad_options.max_steps) */
    /* scad_options.progress, the main file's top-level scope and the share
     * of its statements done (scad_eval_file_scope) */
    void (*progress)(void *ud, double done);
    void *progress_ud;
    const scad_scope *progress_scope;
    double progress_done;
    int module_depth;          /* user modules being instantiated: $parent_modules */
    const char **module_names; /* their names, outermost first (parent_module) */
    int module_names_cap;
    int aborted; /* an error stopped the evaluation */
    char *stack_base;
    size_t stack_budget;
    scad_env *captured;
    unsigned long rand_seed;  /* the clock's, for rands() without a seed */
    struct scad_mt19937 *rng; /* rands()'s engine (math.c), made on first use */
    scad_geom *root;          /* the first '!' subtree */
    int has_root;
    const scad_stmt *root_stmt; /* the statement of the first '!' */
    scad_loc second_root;       /* where another '!' was, file NULL if none */
    int in_root;                /* '!' statements being evaluated */
    scad_geom **highlights;
    int nhighlights, caphighlights;
    scad_geom **backgrounds;
    int nbackgrounds, capbackgrounds;
    int dump;           /* build OpenSCAD's node tree for .csg output, no geometry */
    scad_env *builtins; /* the root environment (PI, $fn …) */
    /* The module instantiations and function calls being evaluated,
     * outermost first: OpenSCAD's "TRACE: called by" lines after an error. */
    struct scad_frame {
        const char *name;
        scad_loc loc;
    } * frames;
    int nframes, capframes;
    /* Where a top-level error with no place of its own is reported: the
     * top-level assignment or statement being evaluated (deeper, the
     * innermost frame says it; see scad_eval_here). */
    scad_loc at;
    int facets;                    /* scad_facets, from the options */
    int for_mesh;                  /* evaluated for a mesh (scad_options.for_mesh) */
    int no_builtins;               /* openscad's empty context: no builtin functions */
    const scad_services *services; /* from the options; never NULL (an empty set) */
    /* shape data made by builtin_geometry.c, one reference each, dropped by
     * scad_geometry_release */
    iv_shape *owned;
    int nowned, capowned;
} scad_eval;

/* Evaluated call arguments: names[i] is NULL for positional ones. */
typedef struct scad_argv {
    scad_value *v;
    const char **names;
    scad_loc *locs;
    int n;
    /* A builtin function's arguments are evaluated when first read
     * (scad_arg_at), as OpenSCAD 2021.01 evaluates them: an argument a
     * function never reads is never evaluated (nor warned about).
     * pending[i] != 0 until v[i] is; NULL when all are. */
    unsigned char *pending;
    const scad_args *src;
    scad_env *env;
    scad_eval *ev;
} scad_argv;

/* Argument i of a (evaluated now if it is pending), borrowed. */
scad_value scad_arg_at(const scad_argv *a, int i);
/* Argument i of a lazy argv evaluated once more (OpenSCAD reads some
 * twice, warnings and all), owned. */
scad_value scad_arg_again(const scad_argv *a, int i);

scad_value scad_eval_expr(scad_eval *ev, scad_env *env, const scad_expr *e);
/* A call expression (eval_call.c): a user function, a function literal or
 * a builtin function. */
scad_value scad_eval_call(scad_eval *ev, scad_env *env, const scad_expr *e);

/* ---- limits and the error trace (eval_call.c) ------------------------------- */

/* One step of work (a call, a module instantiation, or a value of a loop or
 * list being built): 0 to go on; past ev->max_steps, an error and -1. */
int scad_eval_step(scad_eval *ev, scad_loc loc);
/* Enter a module instantiation or function call for the error trace: 0,
 * or -1 when out of memory (not recorded: a shorter trace, nothing worse);
 * scad_frame_pop takes what scad_frame_push returned. */
int scad_frame_push(scad_eval *ev, const char *name, scad_loc loc);
void scad_frame_pop(scad_eval *ev, int pushed);
/* On entry to every user function or module (what: "function" or
 * "module"): 0 to go on, or -1 after the recursion error (at loc; openscad's
 * echo line at echo_loc, a module's definition); each 0 is paired with a
 * scad_call_leave. */
int scad_call_enter(scad_eval *ev, scad_loc loc, scad_loc echo_loc, const char *what,
                    const char *name);
void scad_call_leave(scad_eval *ev);

/* ---- environments and binding (env.c) --------------------------------------- */

/* A new environment below parent (lexical) and dyn (dynamic) for the
 * definitions of defs (may be NULL); NULL after an out-of-memory error. */
scad_env *scad_env_new(scad_eval *ev, scad_env *parent, scad_env *dyn, const scad_scope *defs);
/* A function literal closes over e: keep it and its lexical ancestors
 * until scad_eval_free_captured. */
void scad_env_capture(scad_eval *ev, scad_env *e);
/* The function (module) that name refers to from env: the innermost scope
 * that defines it, then the files that scope `use`s.  With def_env NULL
 * only the definition is looked up; else *def_env is where it was defined,
 * and *fresh says whether that is a new environment of a used file, which
 * the caller frees after the call. */
const scad_funcdef *scad_find_function(scad_eval *ev, scad_env *env, const char *name,
                                       scad_env **def_env, int *fresh);
const scad_moddef *scad_find_module(scad_eval *ev, scad_env *env, const char *name,
                                    scad_env **def_env, int *fresh);
/* Evaluate a call's arguments (env.c says in which order).  resolve 0:
 * first to last, names as written.  resolve 1: bound to params by
 * OpenSCAD's rule, the first npositional of them taking the unnamed
 * arguments; params NULL: unnamed ones stay unnamed.  user 1: params are a
 * user module's or function's (--check-parameters=false silences their
 * "not specified as parameter").  0, or -1 after an out-of-memory error;
 * free out with scad_argv_free. */
int scad_args_bind(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out, int resolve,
                   const scad_args *params, int npositional, int user, scad_loc loc);
int scad_args_eval(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out);
/* The same, each argument evaluated only when first read (scad_arg_at). */
int scad_args_lazy(scad_eval *ev, scad_env *env, const scad_args *args, scad_argv *out);
void scad_argv_free(scad_argv *a);
/* The assignments of scope s, in order, into env (eval_stmt.c). */
void scad_run_assignments(scad_eval *ev, scad_env *env, const scad_scope *s);

/* ---- value lists and iteration (eval_expr.c) ---------------------------------- */

typedef struct scad_vlist {
    scad_value *v;
    int n, cap;
} scad_vlist;

/* Append v (taken) as one step of work, within the list limit. */
/* OpenSCAD's Expression::isLiteral: constants, and vectors and ranges of
 * constants. */
int scad_expr_is_literal(const scad_expr *e);
void scad_vlist_push(scad_eval *ev, scad_vlist *l, scad_value v, scad_loc loc);
/* The list as a vector value; l is emptied. */
scad_value scad_vlist_take(scad_vlist *l);
void scad_vlist_free(scad_vlist *l);
/* The values a for loop visits over v, appended to out: their count, or -1
 * when refused (warned). */
int scad_iter_values(scad_eval *ev, scad_value v, scad_loc loc, scad_vlist *out);
/* echo()'s line, assert()'s check (0 when it holds, else the error and
 * -1), and let()'s assignments in sequence. */
void scad_echo_line(scad_eval *ev, const scad_argv *a);
int scad_check_assert(scad_eval *ev, scad_env *env, const scad_args *args, scad_loc loc);
void scad_assign_seq(scad_eval *ev, scad_env *env, const scad_args *args);
/* Borrowed value of the variable of the interned name; undef (with
 * OpenSCAD's warning unless silent) when unknown.  *found tells which. */
scad_value scad_env_lookup(scad_eval *ev, scad_env *env, const char *name, scad_loc loc, int silent,
                           int *found);
/* The same for a name from C code, which need not be interned. */
scad_value scad_env_lookup_cstr(scad_eval *ev, scad_env *env, const char *name, scad_loc loc,
                                int silent, int *found);
/* Set (or replace) the variable of the interned name in env; takes
 * ownership of v. */
void scad_env_set(scad_env *env, const char *name, scad_value v);

/* The $-variables set in from and its lexical parents up to stop copied
 * into to where it does not set them (a tail call keeps its caller's). */
void scad_env_copy_specials(scad_env *to, scad_env *from, const scad_env *stop);

/* Bind a call to parameters in two steps, in OpenSCAD 2021.01's order:
 * scad_bind_defaults evaluates every default in def_env (given or not);
 * then the caller evaluates the call's arguments, resolved to parameter
 * names (scad_args_bind), and scad_bind_given sets each of them
 * by name.  The values in argv are borrowed. */
void scad_bind_defaults(scad_eval *ev, scad_env *target, scad_env *def_env,
                        const scad_args *params);
void scad_bind_given(scad_env *target, const scad_argv *argv);

/* n steps of work done at once by a builtin (the elements concat copies,
 * the points minkowski sums …), counted against the step limit as the
 * evaluator counts calls and loop values: 0 to go on; past the limit, the
 * error "evaluation took more than N steps (what)" at loc and -1. */
int scad_eval_steps(scad_eval *ev, long n, scad_loc loc, const char *what);

/* scad_diag.hard_stop for an evaluation (ud: its scad_eval): the call
 * trace, an error naming --hardwarnings, and the evaluation stops. */
void scad_eval_hard_stop(void *ud);

/* Error: reports "file:line:col: error: …" and stops the evaluation. */
void scad_eval_error(scad_eval *ev, scad_loc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The same, OpenSCAD's echo stream reading echo_msg (its own wording). */
void scad_eval_error_worded(scad_eval *ev, scad_loc loc, const char *echo_msg, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* "DEPRECATED: msg" without a place, once per evaluation (openscad's
 * printDeprecation). */
void scad_deprecated_once(scad_eval *ev, const char *msg);
/* Where the evaluation is: the module instantiation or function call
 * being evaluated (the innermost frame), else the top-level assignment or
 * statement (ev->at).  For errors such as running out of memory that
 * arise in no particular expression. */
scad_loc scad_eval_here(const scad_eval *ev);

/* The file's scope evaluated in env; top-level objects as one union. */
scad_geom *scad_eval_file_scope(scad_eval *ev, scad_env *env, const scad_scope *s);
/* Free e (a no-op for environments a closure captured). */
void scad_env_free(scad_env *e);
/* Frees the environments closures kept alive; call once at the end. */
void scad_eval_free_captured(scad_eval *ev);
/* sin/cos in degrees, exact at multiples of 30 and 45 degrees. */

/* ---- builtins --------------------------------------------------------------- */

/* Instantiate st's children in a fresh scope below env with the given state;
 * returns them as one node (union of several, NULL if none). op selects how
 * several children combine. */
scad_geom *scad_eval_children(scad_eval *ev, scad_env *env, const scad_stmt *st,
                              const scad_state *state, csg_op op);
/* The same children one by one, each child statement's result (empty sets
 * included, statements that make no node left out): a malloc'd array of *n
 * (the caller frees it; the geometry is the arena's), or NULL when there
 * are none. */
scad_geom **scad_eval_children_list(scad_eval *ev, scad_env *env, const scad_stmt *st,
                                    const scad_state *state, int *n);

/* Keep one reference to s's data until the end of the evaluation (in
 * ev->owned).  Returns 0, or -1 when out of memory (then s's data is
 * released). */
int scad_geom_keep(scad_eval *ev, iv_shape *s);
/* Drop the evaluation's own references to the shape data made while it ran
 * (the csg nodes made from the geometry hold theirs).  Call once, after the
 * trees are converted. */
void scad_geometry_release(scad_eval *ev);

/* Geometry in the eval arena. */
scad_geom *scad_geom_leaf(scad_eval *ev, const iv_shape *s, const scad_state *state);
scad_geom *scad_geom_op(scad_eval *ev, csg_op op);
/* The empty set as an operand (eval_stmt.c): an op node without children. */
scad_geom *scad_geom_empty(scad_eval *ev);
int scad_geom_is_empty(const scad_geom *g);
void scad_geom_add(scad_eval *ev, scad_geom *parent, scad_geom *child);

/* Looks up a named or positional argument: index pos (or -1 for named
 * only).  Returns a borrowed value, undef when absent. */
scad_value scad_argv_get(const scad_argv *a, const char *name, int pos);
/* 1 when the argument is present (positional or named). */
int scad_argv_given(const scad_argv *a, const char *name, int pos);

/* ---- dump mode ----------------------------------------------------------------- */

/* A dump node with a copy of text as its header and the children of list
 * (a bare list, a node, or NULL) spliced in. */
scad_geom *scad_dump_node(scad_eval *ev, const char *text, scad_geom *list);
/* The tree as OpenSCAD's .csg text into b (each top-level node unindented).
 * Returns NULL, or when b ran out of memory (b->oom) the node whose text
 * it could not take, borrowed from the tree. */
const scad_geom *scad_dump_write(scad_buf *b, const scad_geom *list);

/* A number from a value: 1 when v is a finite-or-not number. */
static inline int scad_to_num(scad_value v, double *out)
{
    if (v.kind != SV_NUM) return 0;
    *out = v.u.num;
    return 1;
}

#endif
