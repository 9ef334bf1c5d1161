/*
** src/core/nameset.c -- a hash set of model names: is this name taken, and by which model?
** See LICENSE for copyright and license.
*/
#include <stdlib.h>
#include <string.h>
#include "core/nameset.h"

/* FNV-1a, 64 bits (Fowler, Noll, Vo: offset basis and prime of the spec). */
static uint64_t fnv1a(const char *p, size_t n)
{
    uint64_t h = UINT64_C(14695981039346656037);
    size_t i;

    for (i = 0; i < n; i++) {
        h ^= (unsigned char)p[i];
        h *= UINT64_C(1099511628211);
    }
    return h;
}

/* The slot holding name (hash h), or the empty slot where it would go.
** Requires cap > n: there is an empty slot, so the probe ends. */
static pt_name_slot *probe(pt_nameset *t, const char *name, size_t len, uint64_t h)
{
    size_t mask = t->cap - 1, i = (size_t)h & mask;

    for (;; i = (i + 1) & mask) {
        pt_name_slot *s = &t->slot[i];
        if (s->name == NULL) return s;
        if (s->hash == h && s->len == len) {
            t->compares++;
            if (memcmp(s->name, name, len) == 0) return s;
        }
    }
}

size_t pt_nameset_find(pt_nameset *t, const char *name, size_t len)
{
    pt_name_slot *s;

    if (t->cap == 0) return SIZE_MAX;
    s = probe(t, name, len, fnv1a(name, len));
    return s->name != NULL ? s->index : SIZE_MAX;
}

/* Double the table (from 64 slots) and put every name back. */
static int grow(pt_nameset *t)
{
    size_t cap = t->cap ? 2 * t->cap : 64, k;
    pt_name_slot *old = t->slot, *s;
    pt_nameset bigger = {NULL, 0, 0, 0};

    if (cap > SIZE_MAX / sizeof *old) return -1;
    bigger.slot = calloc(cap, sizeof *old);
    if (bigger.slot == NULL) return -1;
    bigger.cap = cap;
    for (k = 0; k < t->cap; k++) {
        if (old[k].name == NULL) continue;
        s = probe(&bigger, old[k].name, old[k].len, old[k].hash);
        *s = old[k];
    }
    free(old);
    t->slot = bigger.slot;
    t->cap = cap;
    return 0;
}

int pt_nameset_add(pt_nameset *t, const char *name, size_t len, size_t index)
{
    uint64_t h = fnv1a(name, len);
    pt_name_slot *s;

    if (2 * (t->n + 1) > t->cap && grow(t) != 0) return -1;
    s = probe(t, name, len, h);
    s->name = name;
    s->len = len;
    s->index = index;
    s->hash = h;
    t->n++;
    return 0;
}

void pt_nameset_free(pt_nameset *t)
{
    free(t->slot);
    t->slot = NULL;
    t->cap = t->n = 0;
}
