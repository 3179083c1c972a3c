/*
 * ast_print.h — private to src/scad: OpenSCAD 2021.01's .ast output, the
 * parsed main file printed back (ast_print.c), with the customizer
 * annotations its comments give the top-level assignments (annotations.c).
 */
#ifndef RAYSCAD_SCAD_AST_PRINT_H
#define RAYSCAD_SCAD_AST_PRINT_H

#include "ast.h"
#include "value.h"

/* One top-level assignment's annotations, each the text of its expression
 * as printed ("[0 : 10]", "\"Size\""): parameter NULL when the assignment
 * has none, else always set; description and group NULL when absent. */
typedef struct scad_annotation {
    const char *parameter, *description, *group;
} scad_annotation;

/* The annotations of top's assignments (top->nassigns of them, in arena a),
 * as 2021.01's CommentParser::collectParameters finds them in text — the
 * main file's source with "\n\x03\n" and the -D assignments appended, as
 * openscad parses it: an assignment of a literal in main_file (its name as
 * the assignments' locations give it) on a line before the first '{' gets
 * a Parameter from the comment that ends its line ("// [0:10]", "" when
 * there is none or it does not parse), a Description from a line comment
 * just above it, and the Group of the last one-line comment "/ * [Name] * /"
 * above it.  NULL when out of memory. */
scad_annotation *scad_annotations_collect(scad_arena *a, const scad_scope *top,
                                          const char *main_file, const char *text);

/* Print top as `openscad -o x.ast` writes it (FileModule::print): in each
 * scope its functions, modules, assignments and instantiations, in that
 * order; notes (may be NULL) annotate top's assignments.  Out of memory:
 * b->oom. */
void scad_ast_print(scad_buf *b, const scad_scope *top, const scad_annotation *notes);

#endif
