/*
** src/wasm/pt_wasm_alloc.c -- the WebAssembly module's heap: one arena, emptied as a whole
** See LICENSE for copyright and license.
*/
#include <stdlib.h>                         /* src/wasm/stdlib.h */
#include <string.h>
#include "wasm/pt_wasm_alloc.h"

static unsigned char arena[PT_WASM_ARENA] __attribute__((aligned(8)));
static size_t top, mark, last = (size_t)-1;     /* last: the newest block's offset */

/* A block: its size (8 bytes), then the bytes handed out. */
static size_t *head(void *p)
{
    return (size_t *)((unsigned char *)p - 8);
}

void *malloc(size_t n)
{
    size_t need = (n + 7u) / 8u * 8u + 8u;

    if (n > PT_WASM_ARENA || need > PT_WASM_ARENA - top) return NULL;
    last = top;
    *(size_t *)(void *)(arena + top) = n;
    top += need;
    return arena + last + 8;
}

void *realloc(void *p, size_t n)
{
    size_t old, need;
    unsigned char *q;

    if (!p) return malloc(n);
    old = *head(p);
    if ((unsigned char *)p == arena + last + 8) {   /* the newest: grow in place */
        need = (n + 7u) / 8u * 8u + 8u;
        if (n > PT_WASM_ARENA || need > PT_WASM_ARENA - last) return NULL;
        *head(p) = n;
        top = last + need;
        return p;
    }
    if (!(q = malloc(n))) return NULL;
    __builtin_memcpy(q, p, old < n ? old : n);
    return q;
}

void free(void *p)
{
    if (p && (unsigned char *)p == arena + last + 8 && last >= mark) {
        top = last;
        last = (size_t)-1;
    }
}

void pt_wasm_alloc_reset(int to_start)
{
    if (to_start) mark = 0;
    top = mark;
    last = (size_t)-1;
}

void pt_wasm_alloc_mark(void)
{
    mark = top;
    last = (size_t)-1;
}
