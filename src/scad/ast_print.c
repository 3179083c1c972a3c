/*
 * ast_print.c — the parsed main file as `openscad -o x.ast` (2021.01)
 * writes it: FileModule::print, LocalScope::print, UserFunction::print,
 * UserModule::print, Assignment::print and ModuleInstantiation::print,
 * expressions as Expression::print (scad_expr_format).
 *
 * What 2021.01's parser keeps is what is printed: included files inline
 * (an include is lexical), used files not at all, an assignment to a name
 * already assigned in its scope in the first one's place, a `*`-disabled
 * instantiation not at all (the parser deletes it), and no modifiers
 * (! # % are flags the printer does not show).  Each scope prints its
 * functions, then its modules, assignments and instantiations, every line
 * indented with tabs.  An instantiation's children follow on the same line
 * when they are one instantiation, in braces when they hold an assignment
 * or more than one element, and an empty child list is ";".  An empty else
 * branch prints "else;" with no line break, so the next statement follows
 * on the same line — as openscad writes it.
 */
#include "ast_print.h"

typedef struct printer {
    scad_buf *b;
} printer;

static void tabs(printer *p, int indent)
{
    for (int i = 0; i < indent; i++)
        scad_buf_put(p->b, "\t", 1);
}

/* `name = value, …` of a call, or the parameters of a definition (a name
 * with no default alone). */
static void print_args(printer *p, const scad_args *a)
{
    for (int i = 0; i < a->n; i++) {
        if (i) scad_buf_puts(p->b, ", ");
        if (a->v[i].name) scad_buf_puts(p->b, a->v[i].name);
        if (a->v[i].name && a->v[i].value) scad_buf_puts(p->b, " = ");
        if (a->v[i].value) scad_expr_format(p->b, a->v[i].value);
    }
}

/* LocalScope::numElements: its assignments and instantiations (functions
 * and modules do not count; disabled instantiations were never added). */
static int elements(const scad_scope *s)
{
    if (!s) return 0;
    int n = s->nassigns;
    for (int i = 0; i < s->nstmts; i++)
        n += !s->stmts[i]->disable;
    return n;
}

static void print_scope(printer *p, const scad_scope *s, int indent, int inlined,
                        const scad_annotation *notes);

/* A child list after "name(args": ");", " child" on the line, or a block.
 * openscad's rule is one element inline; a lone assignment is braced all
 * the same in what 2021.01 writes. */
static void print_children(printer *p, const scad_scope *s, int indent)
{
    int n = elements(s);
    if (n == 0) {
        scad_buf_puts(p->b, ");\n");
    } else if (n == 1 && s->nassigns == 0) {
        scad_buf_puts(p->b, ") ");
        print_scope(p, s, indent, 1, NULL);
    } else {
        scad_buf_puts(p->b, ") {\n");
        print_scope(p, s, indent + 1, 0, NULL);
        tabs(p, indent);
        scad_buf_puts(p->b, "}\n");
    }
}

static void print_stmt(printer *p, const scad_stmt *st, int indent, int inlined)
{
    if (!inlined) tabs(p, indent);
    scad_buf_puts(p->b, st->name);
    scad_buf_puts(p->b, "(");
    if (st->cond)
        scad_expr_format(p->b, st->cond);
    else
        print_args(p, &st->args);
    print_children(p, st->children, indent);
    if (!st->cond || !st->else_children) return;
    int n = elements(st->else_children);
    tabs(p, indent);
    if (n == 0) {
        scad_buf_puts(p->b, "else;");
    } else if (n == 1 && st->else_children->nassigns == 0) {
        scad_buf_puts(p->b, "else ");
        print_scope(p, st->else_children, indent, 1, NULL);
    } else {
        scad_buf_puts(p->b, "else {\n");
        print_scope(p, st->else_children, indent + 1, 0, NULL);
        tabs(p, indent);
        scad_buf_puts(p->b, "}\n");
    }
}

static void print_annotation(printer *p, const char *name, const char *text)
{
    if (text) scad_buf_printf(p->b, "//%s(%s)\n", name, text);
}

static void print_scope(printer *p, const scad_scope *s, int indent, int inlined,
                        const scad_annotation *notes)
{
    for (int i = 0; i < s->nfuncs && !p->b->oom; i++) {
        const scad_funcdef *f = s->funcs[i];
        tabs(p, indent);
        scad_buf_printf(p->b, "function %s(", f->name);
        print_args(p, &f->params);
        scad_buf_puts(p->b, ") = ");
        scad_expr_format(p->b, f->body);
        scad_buf_puts(p->b, ";\n");
    }
    for (int i = 0; i < s->nmods && !p->b->oom; i++) {
        const scad_moddef *m = s->mods[i];
        tabs(p, indent);
        scad_buf_printf(p->b, "module %s(", m->name);
        print_args(p, &m->params);
        scad_buf_puts(p->b, ") {\n");
        print_scope(p, m->body, indent + 1, 0, NULL);
        tabs(p, indent);
        scad_buf_puts(p->b, "}\n");
    }
    for (int i = 0; i < s->nassigns && !p->b->oom; i++) {
        const scad_assign *as = &s->assigns[i];
        if (notes && notes[i].parameter) {
            print_annotation(p, "Group", notes[i].group);
            print_annotation(p, "Description", notes[i].description);
            print_annotation(p, "Parameter", notes[i].parameter);
        }
        tabs(p, indent);
        scad_buf_printf(p->b, "%s = ", as->name);
        scad_expr_format(p->b, as->value);
        scad_buf_puts(p->b, ";\n");
    }
    for (int i = 0; i < s->nstmts && !p->b->oom; i++)
        if (!s->stmts[i]->disable) print_stmt(p, s->stmts[i], indent, inlined);
}

void scad_ast_print(scad_buf *b, const scad_scope *top, const scad_annotation *notes)
{
    printer p = {b};
    print_scope(&p, top, 0, 0, notes);
}
