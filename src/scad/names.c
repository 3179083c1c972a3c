/*
 * names.c — interned names: one copy of every identifier of a parse, so
 * that names compare by pointer and hash by address.
 *
 * A name lives in the parse's arena behind a small header (its hash, its
 * length and, for the words the language reserves, the keyword's token
 * kind, so the lexer tells keywords by one lookup), as Lua keeps its short
 * strings.  The table is open addressing with
 * linear probing over pointers to the names, at most half full; it only
 * grows, its old slot arrays left in the arena (their total is less than
 * the last one).  Invariant: two interned names are equal strings exactly
 * when they are the same pointer — every name the evaluator compares
 * (variables, parameters, definitions) comes from here.
 */
#include <stdint.h>
#include <string.h>

#include "ast.h"

struct scad_names {
    scad_arena *a;
    const char **slot; /* NULL: empty */
    uint32_t cap, n;   /* cap a power of two */
};

uint32_t scad_names_hash(const char *s, size_t n)
{
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h;
}

static scad_name_header *header_of(const char *name)
{
    return (scad_name_header *)(uintptr_t)(name - offsetof(scad_name_header, s));
}

static int grow(scad_names *t)
{
    uint32_t cap = t->cap ? t->cap * 2 : 256;
    const char **slot = scad_arena_alloc(t->a, sizeof *slot * cap);
    if (!slot) return -1;
    for (uint32_t i = 0; i < t->cap; i++) {
        const char *s = t->slot[i];
        if (!s) continue;
        uint32_t k = header_of(s)->hash & (cap - 1);
        while (slot[k])
            k = (k + 1) & (cap - 1);
        slot[k] = s;
    }
    t->slot = slot;
    t->cap = cap;
    return 0;
}

static const struct {
    const char *word;
    scad_tok_kind kind;
} keywords[] = {
    {"module", TK_MODULE}, {"function", TK_FUNCTION}, {"if", TK_IF},         {"else", TK_ELSE},
    {"for", TK_FOR},       {"let", TK_LET},           {"assert", TK_ASSERT}, {"echo", TK_ECHO},
    {"each", TK_EACH},     {"true", TK_TRUE},         {"false", TK_FALSE},   {"undef", TK_UNDEF},
};

scad_names *scad_names_new(scad_arena *a)
{
    scad_names *t = scad_arena_alloc(a, sizeof *t);
    if (!t) return NULL;
    t->a = a;
    if (grow(t) != 0) return NULL;
    for (size_t i = 0; i < sizeof keywords / sizeof keywords[0]; i++) {
        const char *s = scad_names_intern(t, keywords[i].word, strlen(keywords[i].word));
        if (!s) return NULL;
        header_of(s)->keyword = (int)keywords[i].kind;
    }
    return t;
}

/* The slot that holds s[0..n), or the empty slot where it would go. */
static uint32_t find_slot(const scad_names *t, const char *s, size_t n, uint32_t h)
{
    uint32_t k = h & (t->cap - 1);
    for (;; k = (k + 1) & (t->cap - 1)) {
        const char *x = t->slot[k];
        if (!x) return k;
        const scad_name_header *hd = header_of(x);
        if (hd->hash == h && hd->len == n && memcmp(x, s, n) == 0) return k;
    }
}

const char *scad_names_intern(scad_names *t, const char *s, size_t n)
{
    uint32_t h = scad_names_hash(s, n);
    uint32_t k = find_slot(t, s, n, h);
    if (t->slot[k]) return t->slot[k];
    if (n > UINT32_MAX) return NULL;
    if (2 * (t->n + 1) > t->cap) {
        if (grow(t) != 0) return NULL;
        k = find_slot(t, s, n, h);
    }
    scad_name_header *hd = scad_arena_alloc_raw(t->a, sizeof *hd + n + 1);
    if (!hd) return NULL;
    hd->hash = h;
    hd->len = (uint32_t)n;
    hd->keyword = 0;
    memcpy(hd->s, s, n);
    hd->s[n] = 0;
    t->slot[k] = hd->s;
    t->n++;
    return hd->s;
}

const char *scad_names_find(const scad_names *t, const char *s)
{
    size_t n = strlen(s);
    const char *x = t->slot[find_slot(t, s, n, scad_names_hash(s, n))];
    return x;
}
