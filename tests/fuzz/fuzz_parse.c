/*
 * fuzz_parse.c — libFuzzer harness for the lexer and parser (src/scad/lex.c,
 * parse.c): any bytes, as a NUL-terminated source, are tokenised and parsed
 * into an AST in a fresh arena, which is printed as openscad's .ast (the
 * printer and the customizer comments' grammar, ast_print.c and
 * annotations.c) and then freed.  Nothing is evaluated; include and use
 * read their files (relative to the current folder) as the parser does.
 * Checked besides the sanitizers: every error line reads
 * "name:line:col: error: ..." (name: this input's or an included file's).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/scad/ast.h"
#include "../../src/scad/ast_print.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* 1 when line holds "name:line:col: error: " (name may be an included
 * file's). */
static int located(const char *line)
{
    for (const char *p = strchr(line, ':'); p; p = strchr(p + 1, ':')) {
        int l, c, n = 0;
        if (sscanf(p, ":%d:%d: error: %n", &l, &c, &n) == 2 && n > 0) return 1;
    }
    return 0;
}

static void on_message(void *ud, scad_msg_kind kind, const char *line)
{
    (void)ud;
    if (kind == RAYSCAD_MSG_ERROR && !located(line)) abort(); /* an error without its location */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = malloc(size + 1);
    if (!src) return 0;
    memcpy(src, data, size);
    src[size] = 0;
    scad_options opt = {.message = on_message};
    scad_diag d;
    memset(&d, 0, sizeof d);
    d.opt = &opt;
    d.base_dir = "";
    scad_arena *a = scad_arena_new();
    scad_names *names = a ? scad_names_new(a) : NULL;
    if (names) {
        scad_token *toks;
        (void)scad_lex(a, &d, names, "fuzz.scad", src, &toks);
        free(toks);
    }
    scad_arena_free(a);
    memset(&d, 0, sizeof d);
    d.opt = &opt;
    d.base_dir = "";
    a = scad_arena_new();
    names = a ? scad_names_new(a) : NULL;
    scad_scope *top = names ? scad_parse(a, &d, names, "fuzz.scad", src) : NULL;
    if (top) {
        scad_buf b = {0};
        scad_ast_print(&b, top, scad_annotations_collect(a, top, "fuzz.scad", src));
        scad_buf_free(&b);
    }
    scad_arena_free(a);
    free(src);
    return 0;
}
