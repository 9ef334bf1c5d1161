/*
** src/core/builtin.h -- the scene pipetrace renders when given none
** See LICENSE for copyright and license.
*/
#ifndef PT_BUILTIN_H
#define PT_BUILTIN_H

/* The text of the built-in scene (docs/examples/builtin.scene is a copy). */
extern const char pt_builtin_scene[];

#endif
