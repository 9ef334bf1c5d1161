/*
** stages/rv_project.h -- renderers 7 and 9: camera -> image plane (projection)
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_RV_PROJECT_H
#define PT_RV_PROJECT_H
#include "rv_model.h"
pt_vec4 pt_rv_project(pt_vec4 v, int perspective);
#endif
