/*
** src/wasm/string.h -- <string.h> for the stages compiled to WebAssembly (no libc)
** See LICENSE for copyright and license.
**
** stages/pt_stage.c's pt_stage_by_name() compares names with strcmp; the
** page never calls it, but the file is compiled whole.  pt_wasm.c defines it.
*/
#ifndef PT_WASM_STRING_H
#define PT_WASM_STRING_H

#include <stddef.h>                         /* NULL, size_t: clang's own header */

int strcmp(const char *a, const char *b);

/* stages/pt_mat4.c clears a matrix: memory.fill (-mbulk-memory); stages/
** rv_raster.c copies pixels: memory.copy (its drawing is not in the module,
** but the file is compiled whole). */
#define memset(d, c, n)  __builtin_memset((d), (c), (n))
#define memcpy(d, s, n)  __builtin_memcpy((d), (s), (n))

#endif
