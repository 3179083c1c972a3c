/*
 * arena.c — the parse's and the evaluation's allocations: an iv_arena
 * (intervals.h) that is never reset, freed whole with the parse.
 */
#include <string.h>

#include "ast.h"

void *scad_arena_alloc(scad_arena *a, size_t bytes)
{
    void *p = scad_arena_alloc_raw(a, bytes);
    if (p) memset(p, 0, bytes);
    return p;
}

char *scad_arena_strndup(scad_arena *a, const char *s, size_t n)
{
    char *p = scad_arena_alloc_raw(a, n + 1);
    if (!p) return NULL;
    memcpy(p, s, n);
    p[n] = 0;
    return p;
}
