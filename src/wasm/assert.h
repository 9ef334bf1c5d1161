/*
** src/wasm/assert.h -- <assert.h> for the stages compiled to WebAssembly (no libc)
** See LICENSE for copyright and license.
**
** A failed assertion traps (WebAssembly's unreachable): the page's script
** catches the trap.  The page only calls the stages with sizes >= 1.
*/
#ifndef PT_WASM_ASSERT_H
#define PT_WASM_ASSERT_H

#define assert(e)  ((e) ? (void)0 : __builtin_trap())

#endif
