/*
** src/wasm/pt_wasm_alloc.h -- the WebAssembly module's heap: one arena, emptied as a whole
** See LICENSE for copyright and license.
**
** malloc, realloc and free (src/wasm/stdlib.h) take from a fixed arena of
** PT_WASM_ARENA bytes, bump by bump, 8-byte aligned; realloc grows the last
** block in place and moves any other; free gives back only the last block.
** What a run allocates is dropped at once by pt_wasm_alloc_reset(), back to
** a mark (what outlives the runs: the page's model).  Out of arena: NULL,
** which the stages report as out of memory.
*/
#ifndef PT_WASM_ALLOC_H
#define PT_WASM_ALLOC_H

#include <stddef.h>

#define PT_WASM_ARENA (32u << 20)

/* Drop every block allocated since the mark (to = 1: the mark becomes the
** arena's start, everything dropped).  This function can't fail. */
void pt_wasm_alloc_reset(int to_start);

/* Keep what is allocated now: later resets stop here.  Can't fail. */
void pt_wasm_alloc_mark(void);

#endif
