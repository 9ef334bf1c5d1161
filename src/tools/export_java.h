/*
** src/tools/export_java.h -- the Java program pipetrace export java writes
** See LICENSE for copyright and license.
**
** The program builds a scene with the API of its course renderer (4, 7 or 9)
** as the course's harness does, renders it with the debug flags asked for
** and writes the image as PPM (src/tools/cmd_export.c has the command line
** and the limits; docs/java.md the program).  Java limits a method to 64 KiB
** of bytecode and a class to 65535 constants, so a model's vertices,
** colours, primitives and matrix operations go, PT_EXPORT_CHUNK at a time,
** into small nested classes MKPartI of their own (K the model, Part one of
** pt_export_parts[], I the chunk); model K is built by class MK.
*/
#ifndef PT_EXPORT_JAVA_H
#define PT_EXPORT_JAVA_H

#include <stdio.h>
#include "core/pipetrace.h"

#define PT_EXPORT_CHUNK 400      /* addVertex, addColor, ... calls a class */
#define PT_EXPORT_NPARTS 4       /* vertices, colours, primitives, matrices */

/* The course's debug flags the program sets (the harness's names). */
#define PT_JDBG_SCENE     0x01u  /* scene.debug */
#define PT_JDBG_POSITION  0x02u  /* every Position.debug */
#define PT_JDBG_RASTERIZE 0x04u  /* Rasterize.debug */
#define PT_JDBG_CLIP      0x08u  /* Clip.debug (renderers 7, 9) */
#define PT_JDBG_NEARCLIP  0x10u  /* NearClip.debug (renderers 7, 9) */

/* The parts' names in the nested classes: "Vertices", "Colors", "Segments"
** (segments and points), "Matrices". */
extern const char *const pt_export_parts[PT_EXPORT_NPARTS];

/* How many items part kind (0 .. PT_EXPORT_NPARTS-1) of model m has in the
** program for renderer.  This function can't fail. */
size_t pt_export_count(const pt_model *m, int kind, int renderer);

/* Write the program of scene s to f: class cls[0..ncls), file the name its
** comment gives for the source, dbg the PT_JDBG_ flags.  s uses a course
** renderer's pipeline (not the matrix camera).  Write errors show in
** ferror(f). */
void pt_export_java(FILE *f, const pt_scene *s, const char *cls, size_t ncls,
                    const char *file, unsigned dbg);

#endif
