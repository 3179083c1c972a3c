/*
 * csg_text.c — OpenSCAD's .csg output (`openscad -o x.csg`): in dump mode
 * (scad_eval.dump) the evaluation builds OpenSCAD's node tree instead of
 * geometry — every node a header ("cube(size = [1, 1, 1], center =
 * false)", printed by the builtin's registry entry, or "group()" for a
 * module call, if, for …) and all its children, empty groups included —
 * and this file writes it out, one node per line, tab-indented, as
 * OpenSCAD's Node::toString and its tree dumper do.
 */
#include <string.h>

#include "eval.h"

scad_geom *scad_dump_node(scad_eval *ev, const char *text, scad_geom *list)
{
    scad_geom *g = scad_geom_op(ev, CSG_OP_UNION);
    if (!g) return NULL;
    size_t n = strlen(text);
    char *t = scad_arena_alloc(ev->arena, n + 1);
    if (!t) {
        scad_eval_error(ev, scad_eval_here(ev), "out of memory");
        return NULL;
    }
    memcpy(t, text, n + 1);
    g->text = t;
    scad_geom_add(ev, g, list);
    return g;
}

/* Returns NULL, or the node being written when b ran out of memory. */
static const scad_geom *write_node(scad_buf *b, const scad_geom *g, int indent)
{
    for (int i = 0; i < indent; i++)
        scad_buf_put(b, "\t", 1);
    scad_buf_puts(b, g->text);
    if (g->n == 0) {
        scad_buf_puts(b, ";\n");
        return b->oom ? g : NULL;
    }
    scad_buf_puts(b, " {\n");
    if (b->oom) return g;
    for (int i = 0; i < g->n; i++) {
        const scad_geom *failed = write_node(b, g->kids[i], indent + 1);
        if (failed) return failed;
    }
    for (int i = 0; i < indent; i++)
        scad_buf_put(b, "\t", 1);
    scad_buf_puts(b, "}\n");
    return b->oom ? g : NULL;
}

const scad_geom *scad_dump_write(scad_buf *b, const scad_geom *list)
{
    const scad_geom *failed = NULL;
    if (list && list->text) {
        failed = write_node(b, list, 0);
    } else if (list) {
        for (int i = 0; i < list->n && !failed; i++)
            failed = write_node(b, list->kids[i], 0);
    }
    scad_buf_puts(b, "\n");
    return failed ? failed : b->oom ? list : NULL;
}
