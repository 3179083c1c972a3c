/*
 * arena.c — the bump allocator that owns a parse's AST and its strings.
 *
 * Chunks form a singly linked list, newest first; an allocation takes the
 * next 16-byte aligned bytes of the newest chunk or opens a new chunk at
 * least twice as large as the last.  Nothing is freed before
 * scad_arena_free, which releases every chunk at once.
 */
#include <stdlib.h>
#include <string.h>

#include "ast.h"

typedef struct chunk {
    struct chunk *next;
    size_t size, used;
    _Alignas(16) unsigned char data[];
} chunk;

struct scad_arena {
    chunk *head;
    size_t next_size;
};

scad_arena *scad_arena_new(void)
{
    scad_arena *a = calloc(1, sizeof *a);
    if (a) a->next_size = 16384;
    return a;
}

void scad_arena_free(scad_arena *a)
{
    if (!a) return;
    chunk *c = a->head;
    while (c) {
        chunk *n = c->next;
        free(c);
        c = n;
    }
    free(a);
}

void *scad_arena_alloc_raw(scad_arena *a, size_t bytes)
{
    bytes = (bytes + 15) & ~(size_t)15;
    if (bytes == 0) bytes = 16;
    chunk *c = a->head;
    if (!c || c->size - c->used < bytes) {
        size_t size = a->next_size;
        while (size < bytes)
            size *= 2;
        c = malloc(sizeof *c + size);
        if (!c) return NULL;
        c->size = size;
        c->used = 0;
        c->next = a->head;
        a->head = c;
        if (a->next_size < (size_t)1 << 24) a->next_size = size * 2;
    }
    void *p = c->data + c->used;
    c->used += bytes;
    return p;
}

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
