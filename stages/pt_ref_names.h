/*
** stages/pt_ref_names.h -- the stage functions' names in the reference copy
** See LICENSE for copyright and license.
**
** Put in front of stages/s1_model2camera.c .. s6_fb2index.c by the Makefile
** (-include) to compile them a second time as ptref_model2camera() ..
** ptref_fb2index() (pt_ref.h says why).  Only the six stage functions are
** renamed; every other name stays the shared one.
*/
#ifndef PT_REF_NAMES_H
#define PT_REF_NAMES_H

#include "pt_ref.h"

#define pt_model2camera   ptref_model2camera
#define pt_camera2image   ptref_camera2image
#define pt_image2pixel    ptref_image2pixel
#define pt_pixel2viewport ptref_pixel2viewport
#define pt_viewport2fb    ptref_viewport2fb
#define pt_fb2index       ptref_fb2index

#endif
