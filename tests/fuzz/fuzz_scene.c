/*
** tests/fuzz/fuzz_scene.c -- fuzz target: the scene reader, then the whole run
** See LICENSE for copyright and license.
**
** The bytes are a .scene text; when it parses, the plan and the run follow
** with every stage traced (to a sink that drops the records), so what the
** parser lets through is checked by the pipeline too.
*/
#include <string.h>
#include "fuzz.h"
#include "core/pipeline.h"

static void drop_vertex(void *ud, const pt_vrec *r) { (void)ud; (void)r; }

int pt_fuzz_scene(const uint8_t *data, size_t size)
{
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    char err[PT_ERRLEN];

    err[0] = '\0';
    if (pt_scene_parse(&s, "fuzz", (const char *)data, size, err, sizeof err) != 0)
        return pt_fuzz_message_ok(err, "fuzz") ? 1 : -1;
    pt_options_default(&o);
    o.all_stages = 1;
    memset(&l, 0, sizeof l);
    l.sink.vertex = drop_vertex;
    if (pt_plan_make(&p, &s, &o) == 0) {
        pt_run(&s, &p, &o, &l, NULL, &sum);
        pt_plan_free(&p);
    }
    pt_scene_free(&s);
    return 0;
}

PT_FUZZ_TARGET(pt_fuzz_scene)
