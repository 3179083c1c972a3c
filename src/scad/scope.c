/*
 * scope.c — a scope's functions and modules found by name in O(1).
 *
 * When a parse ends, every scope that defines something gets two small
 * hash tables (open addressing on the interned name's hash, at most half
 * full): slot k holds 1 + the index of the last definition of that name in
 * the scope, or 0.  The last one, because a later definition of a name
 * replaces an earlier one in OpenSCAD.  The tables live in the parse's
 * arena and are read-only afterwards, like the rest of the AST.
 */
#include "ast.h"

static uint32_t table_size(int n)
{
    uint32_t cap = 4;
    while (cap < 2 * (uint32_t)n)
        cap *= 2;
    return cap;
}

static int *build(scad_arena *a, int n, const char *(*name_of)(const scad_scope *, int),
                  const scad_scope *s, uint32_t *mask)
{
    if (n == 0) return NULL;
    uint32_t cap = table_size(n);
    int *slot = scad_arena_alloc(a, sizeof *slot * cap);
    if (!slot) return NULL;
    for (int i = 0; i < n; i++) {
        const char *name = name_of(s, i);
        uint32_t k = scad_name_hash(name) & (cap - 1);
        while (slot[k] && name_of(s, slot[k] - 1) != name)
            k = (k + 1) & (cap - 1);
        slot[k] = i + 1;
    }
    *mask = cap - 1;
    return slot;
}

static const char *func_name(const scad_scope *s, int i)
{
    return s->funcs[i]->name;
}

static const char *mod_name(const scad_scope *s, int i)
{
    return s->mods[i]->name;
}

int scad_scope_index(scad_arena *a, scad_scope *s)
{
    s->fslot = build(a, s->nfuncs, func_name, s, &s->fmask);
    s->mslot = build(a, s->nmods, mod_name, s, &s->mmask);
    return (s->nfuncs && !s->fslot) || (s->nmods && !s->mslot) ? -1 : 0;
}

static int find(const int *slot, uint32_t mask, const scad_scope *s,
                const char *(*name_of)(const scad_scope *, int), const char *name)
{
    if (!slot) return -1;
    for (uint32_t k = scad_name_hash(name) & mask;; k = (k + 1) & mask) {
        if (!slot[k]) return -1;
        if (name_of(s, slot[k] - 1) == name) return slot[k] - 1;
    }
}

const scad_funcdef *scad_scope_function(const scad_scope *s, const char *name)
{
    int i = find(s->fslot, s->fmask, s, func_name, name);
    return i < 0 ? NULL : s->funcs[i];
}

const scad_moddef *scad_scope_module(const scad_scope *s, const char *name)
{
    int i = find(s->mslot, s->mmask, s, mod_name, name);
    return i < 0 ? NULL : s->mods[i];
}
