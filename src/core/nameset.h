/*
** src/core/nameset.h -- a hash set of model names: is this name taken, and by which model?
** See LICENSE for copyright and license.
**
** The scene parser asks, for every `model` line, whether an earlier model has
** the name.  Comparing it with every earlier name made 80,000 models take 15 s;
** this table makes each question a hash and, on average, about one string
** comparison: open addressing (linear probing) on an FNV-1a hash, at most half
** full, grown by doubling.  The table does not own the names: each entry
** points at a name its caller keeps alive (the model's own copy) as long as
** the table is used.  `compares` counts the string comparisons made, so a test
** can check that the work stays linear without timing anything.
*/
#ifndef PT_NAMESET_H
#define PT_NAMESET_H

#include <stddef.h>
#include <stdint.h>

typedef struct pt_name_slot {
    const char *name;            /* NULL: an empty slot; not owned */
    size_t len;                  /* its length in bytes */
    size_t index;                /* what the caller stored with it */
    uint64_t hash;               /* FNV-1a of name[0..len) */
} pt_name_slot;

/* Zeroed (= {0}) is an empty table. */
typedef struct pt_nameset {
    pt_name_slot *slot;          /* cap slots, owned; NULL when cap == 0 */
    size_t cap;                  /* 0 or a power of two */
    size_t n;                    /* names stored, n <= cap / 2 */
    uint64_t compares;           /* string comparisons made so far */
} pt_nameset;

/* The index stored with name[0..len), or SIZE_MAX when the name is not in
** the table.  This function can't fail. */
size_t pt_nameset_find(pt_nameset *t, const char *name, size_t len);

/* Store name[0..len) (not yet in the table; kept alive by the caller) with
** index.  Returns 0, or -1 when out of memory (the table is unchanged). */
int pt_nameset_add(pt_nameset *t, const char *name, size_t len, size_t index);

/* Free the table's slots and leave it empty.  This function can't fail. */
void pt_nameset_free(pt_nameset *t);

#endif
