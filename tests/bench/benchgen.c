/*
** tests/bench/benchgen.c -- write the benchmark scene: N closed 8-gons, 1920 x 1080
** See LICENSE for copyright and license.
**
** Usage: benchgen [N [PER_MODEL [RENDERER [aa] [case]]]]  (defaults 25000, 1000,
** 4).  Writes to standard output a perspective scene of N octagons (8 vertices
** and one `f` line each, so 8 segments), PER_MODEL of them a model, scattered
** over the view by a fixed linear congruential generator: the same N gives
** the same bytes on every machine.  Coordinates have six decimals, as an
** exporter writes them.  N = 25000 is 200,000 vertices and segments, about
** 2.3 million pixels; `make bench` times pipetrace and tests/bench/baseline.c on
** it.  RENDERER 7 or 9 writes the same octagons for the course's renderer 7
** (each model placed by `translate`) or 9 (by `matrix translate`), white,
** gamma on; `aa` turns the course's anti-aliasing on.  `case` writes the
** scene as a case file of the course's Java harnesses (KraftN.java: `fb`,
** `camera persp`, `t`, `c`, `v`, `l` with indices from 0, and `debug none`:
** no log), for timing the Java renderer on the same numbers (the harness
** parses the same six-decimal text; renderer 9's `t` is Position.translate,
** a translation matrix with the same entries as the identity times it).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static unsigned long long state = 88172645463325252ULL;

/* A number in [0, 1) from a 64-bit LCG (Knuth's MMIX constants). */
static double uniform(void)
{
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(state >> 11) * 0x1p-53;
}

int main(int argc, char **argv)
{
    /* the octagon's corners on the unit circle, (cos, sin) of k * 45 degrees */
    static const double ring[8][2] = {
        {1, 0}, {0.70710678, 0.70710678}, {0, 1}, {-0.70710678, 0.70710678},
        {-1, 0}, {-0.70710678, -0.70710678}, {0, -1}, {0.70710678, -0.70710678}};
    long n = argc > 1 ? atol(argv[1]) : 25000;
    long per = argc > 2 ? atol(argv[2]) : 1000;
    long renderer = argc > 3 ? atol(argv[3]) : 4;
    int aa = 0, kase = 0, bad = 0, a;
    long i, k;

    for (a = 4; a < argc; a++) {
        if (strcmp(argv[a], "aa") == 0) aa = 1;
        else if (strcmp(argv[a], "case") == 0) kase = 1;
        else bad = 1;
    }
    if (n < 1 || per < 1 || (renderer != 4 && renderer != 7 && renderer != 9) || bad
        || (aa && renderer == 4)) {
        fprintf(stderr, "usage: benchgen [N [PER_MODEL [4|7|9 [aa] [case]]]]\n");
        return 1;
    }
    if (kase)
        printf("# the benchmark scene: %ld octagons (tests/bench/benchgen.c)\n"
               "fb 1920 1080\ncamera persp\naa %d\ngamma 1\ndebug none\n", n, aa);
    else {
        printf("# the benchmark scene: %ld octagons (tests/bench/benchgen.c)\n", n);
        printf("framebuffer 1920 1080\ncamera perspective\n");
        if (renderer != 4)
            printf("renderer %ld\nantialias %s\n", renderer, aa ? "on" : "off");
    }
    for (i = 0; i < n; i++) {
        double cx = 7.6 * uniform() - 3.8, cy = 4.2 * uniform() - 2.1;
        double cz = 0.8 * uniform() - 0.4, r = 0.03 + 0.09 * uniform();
        long first = 8 * (i % per);             /* the octagon's first vertex, from 0 */

        if (i % per == 0 && kase)
            printf("model m%ld\nt 0 0 -4\n", i / per + 1);
        else if (i % per == 0)
            printf("model m%ld\n%s\n", i / per + 1,
                   renderer == 9 ? "matrix translate 0 0 -4\ncolor 255 255 255"
                   : renderer == 7 ? "translate 0 0 -4\ncolor 255 255 255" : "translate 0 0 -4");
        for (k = 0; k < 8; k++) {
            if (kase) printf("c 255 255 255\n");
            printf("v %.6f %.6f %.6f\n", cx + r * ring[k][0], cy + r * ring[k][1], cz);
        }
        if (!kase) printf("f -8 -7 -6 -5 -4 -3 -2 -1\n");
        else for (k = 0; k < 8; k++) printf("l %ld %ld\n", first + k, first + (k + 1) % 8);
    }
    return ferror(stdout) ? 1 : 0;
}
