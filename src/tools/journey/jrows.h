/*
** src/tools/journey/jrows.h -- who draws each pipeline's panels: a row per pipeline and stage
** See LICENSE for copyright and license.
*/
#ifndef PT_JROWS_H
#define PT_JROWS_H

#include "tools/journey/jmodel.h"

/* pt_jpipes[id]: pipeline id's panels (jmodel.h), indexed by pt_pipe_id; its
** stage rows, indexed by pt_stage, are filled for every stage of its order
** (tests/unit/test_journey.c checks).  A new pipeline adds its row here. */
extern const pt_jrows pt_jpipes[PT_NPIPES];

#endif
