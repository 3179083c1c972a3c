/*
 * arena.c — the per-thread bump allocator behind every interval list.
 *
 * An arena is a singly linked list of chunks.  `cur` is the chunk being
 * filled; every chunk before it in the list is (treated as) full, every chunk
 * after it is empty and waiting for reuse.  An allocation bumps `cur->used`;
 * when it does not fit, the next chunk in the list that is large enough
 * becomes current (smaller ones are skipped until the next reset), and only
 * when none is left is a new chunk malloc'd and linked in after `cur`.  A
 * reset rewinds `cur` to the head and zeroes every `used`, so a workload that
 * repeats the same pattern of requests after a reset (one ray after another)
 * touches malloc only while warming up.  `held` is the sum of all chunk
 * capacities, which is what the optional limit caps.
 *
 * The arena also carries two fields for the per-ray work that draws on it
 * (intervals.h says why): the list limit csg_trace enforces, and the first
 * failure recorded, which a reset keeps so that a worker can still ask for
 * the reason after it has rewound its scratch.
 */
#define _DEFAULT_SOURCE /* madvise */
#include "intervals.h"

#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>

#define ALIGN 16u
#define DEFAULT_CHUNK (64u * 1024u)

typedef struct chunk {
    struct chunk *next;
    size_t cap;          /* usable bytes from base */
    size_t used;         /* bytes handed out from base */
    unsigned char *base; /* 16-byte aligned start of the usable bytes */
} chunk;

struct iv_arena {
    chunk *head, *cur;
    size_t first; /* size of the first chunk, and the floor for later ones */
    size_t held;  /* sum of cap over all chunks */
    size_t limit; /* 0: none */

    /* for the per-ray work that draws on the arena */
    int list_limit;                /* >= 1: spans one list may hold */
    iv_arena_failure_kind failure; /* the first recorded, or IV_ARENA_OK */
};

/* Round up to a multiple of ALIGN; returns 0 on overflow. */
static size_t round_up(size_t n)
{
    if (n > SIZE_MAX - (ALIGN - 1)) return 0;
    return (n + (ALIGN - 1)) & ~(size_t)(ALIGN - 1);
}

/* Chunks this large are asked to be backed by huge pages: a big parse
 * (BOSL2's 2.8 MB of source) then takes a few hundred page faults where it
 * took thousands, a third of its time. */
#define HUGE_CHUNK ((size_t)2 << 20)

static chunk *chunk_new(size_t cap)
{
    /* malloc only promises alignof(max_align_t); over-allocate by ALIGN and
     * align base by hand so the 16-byte promise holds everywhere. */
    if (cap > SIZE_MAX - sizeof(chunk) - ALIGN) return NULL;
    chunk *c = NULL;
#ifdef MADV_HUGEPAGE
    if (cap >= HUGE_CHUNK) {
        void *p = NULL;
        size_t bytes = sizeof(chunk) + ALIGN + cap;
        if (posix_memalign(&p, HUGE_CHUNK, bytes) == 0) {
            madvise(p, bytes, MADV_HUGEPAGE); /* advice only: ignored where refused */
            c = p;
        }
    }
#endif
    if (!c) c = malloc(sizeof(chunk) + ALIGN + cap);
    if (!c) return NULL;
    uintptr_t p = (uintptr_t)(c + 1);
    p = (p + (ALIGN - 1)) & ~(uintptr_t)(ALIGN - 1);
    c->base = (unsigned char *)p;
    c->next = NULL;
    c->cap = cap;
    c->used = 0;
    return c;
}

iv_arena *iv_arena_new(size_t first_chunk)
{
    iv_arena *a = malloc(sizeof *a);
    if (!a) return NULL;
    a->first = round_up(first_chunk ? first_chunk : DEFAULT_CHUNK);
    if (a->first == 0) a->first = DEFAULT_CHUNK;
    a->head = a->cur = NULL;
    a->held = 0;
    a->limit = 0;
    a->list_limit = IV_LIST_LIMIT_DEFAULT;
    a->failure = IV_ARENA_OK;
    return a;
}

void iv_arena_free(iv_arena *a)
{
    if (!a) return;
    chunk *c = a->head;
    while (c) {
        chunk *next = c->next;
        free(c);
        c = next;
    }
    free(a);
}

void iv_arena_reset(iv_arena *a)
{
    for (chunk *c = a->head; c; c = c->next)
        c->used = 0;
    a->cur = a->head;
}

void iv_arena_set_limit(iv_arena *a, size_t bytes)
{
    a->limit = bytes;
}

void iv_arena_set_list_limit(iv_arena *a, int n)
{
    a->list_limit = n > 0 ? n : IV_LIST_LIMIT_DEFAULT;
}

int iv_arena_list_limit(const iv_arena *a)
{
    return a->list_limit;
}

iv_arena_failure_kind iv_arena_failure(const iv_arena *a)
{
    return a->failure;
}

void iv_arena_record_failure(iv_arena *a, iv_arena_failure_kind why)
{
    if (a->failure == IV_ARENA_OK) a->failure = why;
}

void iv_arena_clear_failure(iv_arena *a)
{
    a->failure = IV_ARENA_OK;
}

/* Every NULL iv_arena_alloc returns goes through here. */
static void *refuse(iv_arena *a)
{
    iv_arena_record_failure(a, IV_ARENA_OUT_OF_MEMORY);
    return NULL;
}

void *iv_arena_alloc(iv_arena *a, size_t bytes)
{
    /* Zero-byte requests still get a distinct, aligned pointer. */
    size_t need = round_up(bytes ? bytes : 1);
    if (need == 0) return refuse(a);
    if (a->cur && a->cur->cap - a->cur->used >= need) {
        void *p = a->cur->base + a->cur->used;
        a->cur->used += need;
        return p;
    }
    /* Reuse a later, empty chunk that is large enough. */
    if (a->cur) {
        for (chunk *c = a->cur->next; c; c = c->next) {
            if (c->cap >= need) {
                a->cur = c;
                c->used = need;
                return c->base;
            }
        }
    }
    /* Grow: double the last chunk's size so the number of chunks stays
     * logarithmic in the peak use, and never less than the request. */
    size_t cap = a->cur ? a->cur->cap : a->first;
    if (a->cur && cap <= SIZE_MAX / 2) cap *= 2;
    if (cap < need) cap = need;
    if (a->limit && (a->held > a->limit || cap > a->limit - a->held)) {
        if (need > a->limit || a->held > a->limit - need) return refuse(a);
        cap = need; /* what still fits under the cap */
    }
    chunk *c = chunk_new(cap);
    if (!c && cap > need) c = chunk_new(cap = need); /* near a memory limit */
    if (!c) return refuse(a);
    a->held += cap;
    if (!a->cur) {
        /* Empty arena, or every chunk is skipped: link at the tail. */
        chunk **link = &a->head;
        while (*link)
            link = &(*link)->next;
        *link = c;
    } else {
        c->next = a->cur->next;
        a->cur->next = c;
    }
    a->cur = c;
    c->used = need;
    return c->base;
}
