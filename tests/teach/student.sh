#!/bin/sh
# tests/teach/student.sh -- a stage of stages/ with one known mistake, made when needed
# See LICENSE for copyright and license.
#
# Usage: sh tests/teach/student.sh NAME OUT.c      write the mistaken stage to OUT.c
#        sh tests/teach/student.sh --list          the names, their stage and mistake
#
# Each mistake is one sed edit of today's stage file, so a student stage never
# drifts from stages/: when a stage changes so that the edit no longer applies,
# this script fails (it checks how many lines the edit changed) instead of
# building yesterday's copy.  Build with it: make STAGE_VAR=OUT.c (the Makefile's
# student block), e.g.
#   sh tests/teach/student.sh s3_two build/s3_two.c && make STAGE_pixel=build/s3_two.c
# tests/teach/diff.sh checks that pipetrace diff names each mistake.

# NAME  STAGE-FILE  MAKE-VAR  LINES  MISTAKE   (the sed edit is in edit() below)
table='s1_subtract s1_model2camera camera      3 x_c = x_m - x_t: the translation subtracted
s2_divz     s2_camera2image projection  2 x_ip = x_c / z_c: the image mirrored
s2_silent   s2_camera2image projection  1 the right numbers, but no pt_emit(): no image records
s3_two      s3_image2pixel  pixel       2 x_pp = 0.5 + w/2 * (x_ip + 1): 2 (in integers) for 2.001
s3_two2     s3_image2pixel  pixel       2 x_pp = 0.5 + w/2.0 * (x_ip + 1): 2 (in doubles) for 2.001
s3_swapwh   s3_image2pixel  pixel       2 x_pp = 0.5 + h/2.001 * (x_ip + 1): w and h swapped
s3_float    s3_image2pixel  pixel       2 x_pp in float arithmetic: about 7 digits
s4_cround   s4_pixel2viewport viewport  2 C round(): ties away from zero
s4_floor    s4_pixel2viewport viewport  2 floor(x + 0.5): the sum rounds first
s4_noflip   s4_pixel2viewport viewport  1 y_vp = round(y_pp) - 1: no y flip
s4_nominus1 s4_pixel2viewport viewport  1 x_vp = round(x_pp): no -1
s4_yminus1  s4_pixel2viewport viewport  1 y_vp = h - 1 - round(y_pp): one row too high
s4_trunc    s4_pixel2viewport viewport  1 (int64_t)(x_pp + 0.5): truncation toward zero
s5_nooffset s5_viewport2fb  framebuffer 2 x_fb = x_vp: the viewport offset forgotten
s6_xh       s6_fb2index     index       1 idx = x_fb * H + y_fb: column by column
s6_vpw      s6_fb2index     index       1 idx = y_fb * 24 + x_fb: the viewport width (24 in tests/data/diff/offset.scene)
u_s2_ynodiv s2_camera2image projection  1 y_ip = y_c: y not divided (no mistake of the catalogue)
u_s3_ww     s3_image2pixel  pixel       1 y_pp = 0.5 + w/2.001 * (y_ip + 1): w for h in y only (none)
u_s6_wm1    s6_fb2index     index       1 idx = y_fb * (W - 1) + x_fb (none)
u_s6_xle    s6_fb2index     index       1 inside when x_fb <= W: the bounds test off by one (none)
u_s6_xm1    s6_fb2index     index       1 inside when -1 <= x_fb: the bounds test off by one (none)'

edit() {    # edit NAME: the sed program of mistake NAME
    case $1 in
    s1_subtract) printf '%s\n' 's/ + t\./ - t./' ;;
    s2_divz)     printf '%s\n' 's| / -c\.z;| / c.z;|' ;;
    s2_silent)   printf '%s\n' 's|pt_emit(sink, &r);|(void)sink; (void)r;|' ;;
    s3_two)      printf '%s\n' 's|/ 2\.001 \*|/ 2 *|' ;;
    s3_two2)     printf '%s\n' 's|/ 2\.001 \*|/ 2.0 *|' ;;
    s3_float)    printf '%s\n' 's|= 0\.5 + \([wh]\) / 2\.001 \* (ip\.\([xy]\) + 1);|= (float)(0.5f + \1 / 2.001f * (float)(ip.\2 + 1));|' ;;
    s3_swapwh)   printf '%s\n' 's|0\.5 + w / 2\.001 \* (ip\.x|0.5 + h / 2.001 * (ip.x|
                       s|0\.5 + h / 2\.001 \* (ip\.y|0.5 + w / 2.001 * (ip.y|' ;;
    s4_cround)   printf '%s\n' 's|^#include <assert\.h>$|&\n#include <math.h>|
                       s|pt_pix_round(pp\.\([xy]\), |pt_pix_round(round(pp.\1), |g' ;;
    s4_floor)    printf '%s\n' 's|^#include <assert\.h>$|&\n#include <math.h>|
                       s|pt_pix_round(pp\.\([xy]\), |pt_pix_round(floor(pp.\1 + 0.5), |g' ;;
    s4_noflip)   printf '%s\n' 's|vp\.y = h - ry;|vp.y = ry - 1;|' ;;
    s4_nominus1) printf '%s\n' 's|vp\.x = rx - 1;|vp.x = rx;|' ;;
    s4_yminus1)  printf '%s\n' 's|vp\.y = h - ry;|vp.y = h - 1 - ry;|' ;;
    s4_trunc)    printf '%s\n' 's|pt_pix_round(pp\.\([xy]\), |pt_pix_round((double)(int64_t)(pp.\1 + 0.5), |g' ;;
    s5_nooffset) printf '%s\n' 's|? [xy]_ul + vp\.\([xy]\) :|? vp.\1 :|' ;;
    u_s2_ynodiv) printf '%s\n' 's|ip\.y = c\.y / -c\.z;|ip.y = c.y;|' ;;
    u_s3_ww)     printf '%s\n' 's|0\.5 + h / 2\.001 \* (ip\.y|0.5 + w / 2.001 * (ip.y|' ;;
    u_s6_wm1)    printf '%s\n' 's|fb\.y \* (int64_t)W + fb\.x;|fb.y * (int64_t)(W - 1) + fb.x;|' ;;
    u_s6_xle)    printf '%s\n' 's|pt_inside(fb\.x, fb\.y, W, H)|fb.x >= 0 \&\& fb.x <= W \&\& fb.y >= 0 \&\& fb.y < H|' ;;
    u_s6_xm1)    printf '%s\n' 's|pt_inside(fb\.x, fb\.y, W, H)|fb.x >= -1 \&\& fb.x < W \&\& fb.y >= 0 \&\& fb.y < H|' ;;
    s6_xh)       printf '%s\n' 's|fb\.y \* (int64_t)W + fb\.x;|fb.x * (int64_t)H + fb.y;|' ;;
    s6_vpw)      printf '%s\n' 's|fb\.y \* (int64_t)W + fb\.x;|fb.y * (int64_t)24 + fb.x;|' ;;
    esac
}

if [ "$1" = --list ]; then
    printf '%s\n' "$table"
    exit 0
fi
if [ $# -ne 2 ]; then
    echo "usage: sh tests/teach/student.sh NAME OUT.c | --list" >&2
    exit 2
fi
row=$(printf '%s\n' "$table" | awk -v n="$1" '$1 == n')
if [ -z "$row" ]; then
    echo "tests/teach/student.sh: no mistake named '$1' (sh tests/teach/student.sh --list)" >&2
    exit 2
fi
set -f; set -- "$1" "$2" $row; set +f
name=$1 out=$2 file=stages/$4.c lines=$6
shift 6
mkdir -p "$(dirname "$out")" || exit 2
{
    printf '/* %s, made by tests/teach/student.sh %s: %s */\n' "$file" "$name" "$*"
    sed "$(edit "$name")" "$file"
} > "$out.tmp" || exit 2
changed=$(tail -n +2 "$out.tmp" | diff "$file" - | grep -c '^>')
if [ "$changed" != "$lines" ]; then
    echo "tests/teach/student.sh: $name changes $changed lines of $file, not $lines: update its edit" >&2
    rm -f "$out.tmp"
    exit 2
fi
mv "$out.tmp" "$out"
