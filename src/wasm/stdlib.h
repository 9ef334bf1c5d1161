/*
** src/wasm/stdlib.h -- <stdlib.h> for the stages compiled to WebAssembly (no libc)
** See LICENSE for copyright and license.
**
** The course's clip stages (stages/rv_model.c, rv_nearclip.c, rv_clip.c)
** grow a model's lists with realloc and free them: an arena in the module
** (src/wasm/pt_wasm_alloc.c) that the page empties before every run.
*/
#ifndef PT_WASM_STDLIB_H
#define PT_WASM_STDLIB_H

#include <stddef.h>                         /* NULL, size_t: clang's own header */

void *malloc(size_t n);
void *realloc(void *p, size_t n);
void free(void *p);

#endif
