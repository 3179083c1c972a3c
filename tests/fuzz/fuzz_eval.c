/*
 * fuzz_eval.c — libFuzzer harness for the evaluator: any bytes, as a
 * NUL-terminated source, go through scad_eval_string (parse, evaluate, build
 * csg trees) and scad_dump_csg_string (the .csg text), both with small
 * recursion and step limits so that runaway recursion and loops are cut off
 * quickly.  No outside services are given, so import(), surface(), text()
 * and the 2D operations report "not available" errors; include/use open
 * files relative to the current folder.  Checked besides the sanitizers: a
 * failed evaluation sent at least one error line, and every error line
 * carries a location.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/scad/scad.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct seen {
    int errors;
} seen;

static void on_message(void *ud, scad_msg_kind kind, const char *line)
{
    seen *s = ud;
    if (kind != RAYSCAD_MSG_ERROR) return;
    s->errors++;
    if (!strchr(line, ':')) abort(); /* an error without its location */
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = malloc(size + 1);
    if (!src) return 0;
    memcpy(src, data, size);
    src[size] = 0;
    seen s = {0};
    scad_options opt = {.message = on_message, .ud = &s, .max_recursion = 200, .max_steps = 100000};
    scad_result r;
    if (scad_eval_string("fuzz.scad", src, &opt, &r) == 0)
        scad_result_free(&r);
    else if (s.errors == 0)
        abort(); /* failed without saying why */
    s.errors = 0;
    char *text = NULL;
    size_t len = 0;
    if (scad_dump_csg_string("fuzz.scad", src, &opt, &text, &len) == 0) {
        if (!text || strlen(text) != len) abort();
        free(text);
    }
    free(src);
    return 0;
}
