/*
** src/core/shapes.c -- the course's model library, built as renderer 4 builds it
** See LICENSE for copyright and license.
**
** Design.  pt_shape_make() reads "NAME ARGS...", fills in the defaults of the
** shorter overloads, refuses what the Java constructor refuses (same checks,
** same order, same words), counts the vertices and segments the shape will
** make (sizes()), allocates its arrays once, and then runs the shape's
** builder.  A builder computes every coordinate with the Java expression's
** operations in their order (Java evaluates left to right: `-r * s2 * s1` is
** ((-r)*s2)*s1, and `0 + xs` turns -0.0 into 0.0) and emits vertices and
** segments in the order the Java constructor adds them, with indices from 0.
** The scene parser appends them to the model, offsetting the indices by the
** vertices the model had before, so `shape` mixes with `v` and `l` lines.
** The enum below lists the shapes in pt_shapes[]'s order.
*/
#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/shapes.h"
#include "core/numparse.h"

#define PI         3.141592653589793   /* Math.PI: the double nearest pi */

enum { SPHERE, CYLINDER, CONE, TORUS, DISK, RING, CIRCLE, SQUARE, SQUAREGRID,
       CUBE, BOX, TETRAHEDRON, OCTAHEDRON, DODECAHEDRON, ICOSAHEDRON,
       ICOSIDODECAHEDRON, PYRAMID, AXES3D };

#define A(c) (1u << (c))               /* arities: c arguments accepted */

const pt_shape_info pt_shapes[] = {
    { "sphere", "Sphere", 3, { "r", "n", "k" }, "rii", { "1", "15", "16" }, A(0)|A(1)|A(3),
      "n circles of latitude of k points each, and the two poles; n >= 1, k >= 3" },
    { "cylinder", "Cylinder", 4, { "r", "h", "n", "k" }, "rrii", { "1", "1", "15", "16" },
      A(0)|A(2)|A(4),
      "n circles of k points from y = h down to y = -h (the last point repeats the first), "
      "and the two centers; n >= 2, k >= 4" },
    { "cone", "Cone", 4, { "r", "h", "n", "k" }, "rrii", { "1", "1", "15", "16" },
      A(0)|A(2)|A(4),
      "n circles of k points from the base (y = 0, radius r) up towards the apex (0, h, 0) "
      "(the last point repeats the first); n >= 2, k >= 4" },
    { "torus", "Torus", 4, { "r1", "r2", "n", "k" }, "rrii", { "0.75", "0.25", "12", "16" },
      A(0)|A(2)|A(4),
      "n circles of k points around the y axis (r1: to the tube's center, r2: the tube); "
      "n >= 3, k >= 3" },
    { "disk", "Disk", 3, { "r", "n", "k" }, "rii", { "1", "6", "12" }, A(0)|A(1)|A(3),
      "n circles of k points in the xy-plane, radii r/n, 2r/n, ..., r, and the "
      "center; n >= 1, k >= 3" },
    { "ring", "Ring", 4, { "r1", "r2", "n", "k" }, "rrii", { "1", "0.33", "4", "12" },
      A(0)|A(2)|A(4),
      "n+1 circles of k points in the xy-plane, radii r2 ... r1; n >= 1, k >= 3" },
    { "circle", "Circle", 2, { "r", "n" }, "ri", { "1", "16" }, A(0)|A(1)|A(2),
      "n points on a circle in the xy-plane; n >= 3" },
    { "square", "Square", 1, { "r" }, "r", { "1" }, A(0)|A(1),
      "the square [-r, r] x [-r, r] in the xy-plane; r > 0" },
    { "squaregrid", "SquareGrid", 3, { "r", "n", "k" }, "rii", { "1", "0", "n" },
      A(0)|A(1)|A(2)|A(3),
      "the square [-r, r] x [-r, r] with n inner horizontal and k inner vertical lines; "
      "n >= 0, k >= 0, r > 0" },
    { "cube", "Cube", 0, { NULL }, "", { NULL }, A(0), "the cube [-1, 1]^3" },
    { "box", "Box", 3, { "xs", "ys", "zs" }, "rrr", { "1", "1", "1" }, A(0)|A(3),
      "the box [0, xs] x [0, ys] x [0, zs]" },
    { "tetrahedron", "Tetrahedron", 0, { NULL }, "", { NULL }, A(0),
      "the regular tetrahedron in the cube [-1, 1]^3" },
    { "octahedron", "Octahedron", 0, { NULL }, "", { NULL }, A(0),
      "the regular octahedron with its corners on the axes at distance 1" },
    { "dodecahedron", "Dodecahedron", 0, { NULL }, "", { NULL }, A(0),
      "the regular dodecahedron: corners (+-1/t, +-1/t, +-1/t) and (0, +-1/t^2, +-1) "
      "and its rotations, t the golden ratio" },
    { "icosahedron", "Icosahedron", 0, { NULL }, "", { NULL }, A(0),
      "the regular icosahedron: corners (+-1/t, +-1, 0) and their rotations" },
    { "icosidodecahedron", "Icosidodecahedron", 0, { NULL }, "", { NULL }, A(0),
      "the icosidodecahedron of radius 1.051462 (the course's 7-digit coordinates)" },
    { "pyramid", "Pyramid", 4, { "s", "h", "n", "k" }, "rrii", { "2", "1", "15", "4" },
      A(0)|A(2)|A(4),
      "a pyramid of base s x s and apex (0, h, 0): with n and k (also with no argument) "
      "k fan lines a side and n squares up the sides; with only s and h its 8 edges; "
      "n >= 1, k >= 1" },
    { "axes3d", "Axes3D", 3, { "xmax", "ymax", "zmax" }, "rrr", { "1", "1", "1" },
      A(0)|A(3),
      "the three axes from the origin to xmax, ymax and zmax" },
};
const int pt_nshapes = (int)(sizeof pt_shapes / sizeof pt_shapes[0]);

/* What a Java constructor refuses, in the order it checks: parameter k less
** than min (ints) or not greater than 0 (min is ignored for reals). */
typedef struct refusal {
    int shape, k, min;
    const char *says;                  /* the IllegalArgumentException's words */
} refusal;

static const refusal refusals[] = {
    { SPHERE, 1, 1, "n must be greater than 0" },
    { SPHERE, 2, 3, "k must be greater than 2" },
    { CYLINDER, 2, 2, "n must be greater than 1" },
    { CYLINDER, 3, 4, "k must be greater than 3" },
    { CONE, 2, 2, "n must be greater than 1" },
    { CONE, 3, 4, "k must be greater than 3" },
    { TORUS, 2, 3, "n must be greater than 2" },
    { TORUS, 3, 3, "k must be greater than 2" },
    { DISK, 1, 1, "n must be greater than 0" },
    { DISK, 2, 3, "k must be greater than 2" },
    { RING, 2, 1, "n must be greater than 0" },
    { RING, 3, 3, "k must be greater than 2" },
    { CIRCLE, 1, 3, "n must be greater than 2" },
    { SQUARE, 0, 0, "r must be greater than 0" },
    { SQUAREGRID, 1, 0, "n must be greater than or equal to 0" },
    { SQUAREGRID, 2, 0, "k must be greater than or equal to 0" },
    { SQUAREGRID, 0, 0, "r must be greater than 0" },
    { PYRAMID, 2, 1, "n must be greater than 0" },
    { PYRAMID, 3, 1, "k must be greater than 0" },
};

/* ===== building: vertices and segments into the model's arrays ===== */

/* The shape being built, in arrays counted beforehand (sizes()). */
typedef struct build {
    pt_vec3 *v;                        /* its vertices */
    size_t nv;                         /* vertices so far */
    uint32_t (*s)[2];                  /* its segments */
    size_t ns;                         /* segments so far */
} build;

static void vert(build *b, double x, double y, double z)
{
    b->v[b->nv].x = x;
    b->v[b->nv].y = y;
    b->v[b->nv].z = z;
    b->nv++;
}

/* Segment between the shape's vertices i and j (0-based, < PT_SHAPE_MAXV). */
static void seg(build *b, size_t i, size_t j)
{
    b->s[b->ns][0] = (uint32_t)i;
    b->s[b->ns][1] = (uint32_t)j;
    b->ns++;
}

/* Segments first, first+stride, ... (count vertices), closed: back to first. */
static void chain(build *b, size_t first, size_t count, size_t stride, int closed)
{
    size_t i;

    for (i = 0; i + 1 < count; i++)
        seg(b, first + i * stride, first + (i + 1) * stride);
    if (closed)
        seg(b, first + (count - 1) * stride, first);
}

/* rows chains of len vertices, row i starting at i*step: the circles. */
static void rings(build *b, size_t rows, size_t step, size_t len, size_t stride, int closed)
{
    size_t i;

    for (i = 0; i < rows; i++)
        chain(b, i * step, len, stride, closed);
}

/* k meridians of len vertices, meridian j starting at j*step: from the vertex
** from (none: SIZE_MAX) along the meridian to the vertex to (none: SIZE_MAX). */
static void spokes(build *b, size_t k, size_t step, size_t len, size_t stride,
                   size_t from, size_t to)
{
    size_t j;

    for (j = 0; j < k; j++) {
        if (from != SIZE_MAX)
            seg(b, from, j * step);
        chain(b, j * step, len, stride, 0);
        if (to != SIZE_MAX)
            seg(b, j * step + (len - 1) * stride, to);
    }
}

/* Segments listed as index pairs. */
static void edges(build *b, const unsigned char (*e)[2], size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        seg(b, e[i][0], e[i][1]);
}

/* Vertices listed as integer triples (Java's `new Vertex(1, -1, 0)`). */
static void corners(build *b, const signed char (*c)[3], size_t n)
{
    size_t i;

    for (i = 0; i < n; i++)
        vert(b, c[i][0], c[i][1], c[i][2]);
}

static const unsigned char box_edges[12][2] = {
    {0,1}, {1,2}, {2,3}, {3,0}, {4,5}, {5,6}, {6,7}, {7,4}, {0,4}, {1,5}, {2,6}, {3,7} };

/* ----------------------------------------------------- round shapes */

/* Sphere(r, n, k): latitude i at angle (i+1)*pi/(n+1) from the north pole. */
static void make_sphere(build *b, double r, size_t n, size_t k)
{
    double dphi = PI / (double)(n + 1), dtheta = (2 * PI) / (double)k;
    size_t i, j;

    for (i = 0; i < n; i++)
        for (j = 0; j < k; j++) {
            double c1 = cos((double)j * dtheta), s1 = sin((double)j * dtheta);
            double c2 = cos(dphi + (double)i * dphi), s2 = sin(dphi + (double)i * dphi);
            vert(b, r * s2 * c1, r * c2, -r * s2 * s1);
        }
    vert(b, 0, r, 0);                                   /* north pole, n*k */
    vert(b, 0, -r, 0);                                  /* south pole */
    rings(b, n, k, k, 1, 1);
    spokes(b, k, 1, n, k, n * k, n * k + 1);
}

/* Cylinder(r, h, n, k): circle i at y = h - i*(2h/(n-1)). */
static void make_cylinder(build *b, double r, double h, size_t n, size_t k)
{
    double dh = (2.0 * h) / (double)(n - 1), dtheta = (2.0 * PI) / (double)(k - 1);
    size_t i, j;

    for (i = 0; i < n; i++)
        for (j = 0; j < k; j++) {
            double c = cos((double)j * dtheta), s = sin((double)j * dtheta);
            vert(b, r * c, h - (double)i * dh, -r * s);
        }
    vert(b, 0, h, 0);                                   /* top center, n*k */
    vert(b, 0, -h, 0);                                  /* bottom center */
    rings(b, n, k, k, 1, 0);
    spokes(b, k, 1, n, k, n * k, n * k + 1);
}

/* Cone(r, h, n, k): the Java code adds its vertices meridian by meridian
** (vertex j*n + i), unlike the other round shapes. */
static void make_cone(build *b, double r, double h, size_t n, size_t k)
{
    double dh = h / (double)(n - 1), dtheta = (2.0 * PI) / (double)(k - 1);
    size_t i, j;

    for (j = 0; j < k; j++) {
        double c = cos((double)j * dtheta), s = sin((double)j * dtheta);
        for (i = 0; i < n; i++) {
            double slant = r * (1 - (double)i * dh / h);
            vert(b, slant * c, (double)i * dh, slant * s);
        }
    }
    vert(b, 0, h, 0);                                   /* apex, n*k */
    vert(b, 0, 0, 0);                                   /* bottom center */
    rings(b, n, 1, k, n, 0);
    spokes(b, k, n, n, 1, n * k + 1, n * k);
}

/* Torus(r1, r2, n, k): circle i of the tube at angle i*2pi/n. */
static void make_torus(build *b, double r1, double r2, size_t n, size_t k)
{
    double dphi = (2 * PI) / (double)n, dtheta = (2 * PI) / (double)k;
    size_t i, j;

    for (i = 0; i < n; i++)
        for (j = 0; j < k; j++) {
            double c1 = cos((double)j * dtheta), s1 = sin((double)j * dtheta);
            double c2 = cos((double)i * dphi), s2 = sin((double)i * dphi);
            vert(b, (r1 + r2 * s2) * c1, r2 * c2, -(r1 + r2 * s2) * s1);
        }
    for (j = 0; j < k; j++)
        chain(b, j, n, k, 1);
    rings(b, n, k, k, 1, 1);
}

/* Disk(r, n, k) and Ring(r1, r2, n, k): circles of radius ri in the xy-plane;
** ri(i) = (i+1)*(r/n) for the disk (plus its center), r2 + i*((r1-r2)/n) for
** the ring. */
static void flat_circles(build *b, double r0, double dr, int disk, size_t rows, size_t k)
{
    double dtheta = (2 * PI) / (double)k;
    size_t i, j;

    for (i = 0; i < rows; i++)
        for (j = 0; j < k; j++) {
            double c = cos((double)j * dtheta), s = sin((double)j * dtheta);
            double ri = disk ? (double)(i + 1) * dr : r0 + (double)i * dr;
            vert(b, ri * c, ri * s, 0);
        }
}

static void make_disk(build *b, double r, size_t n, size_t k)
{
    flat_circles(b, 0, r / (double)n, 1, n, k);
    vert(b, 0, 0, 0);                                   /* center, n*k */
    spokes(b, k, 1, n, k, n * k, SIZE_MAX);
    rings(b, n, k, k, 1, 1);
}

static void make_ring(build *b, double r1, double r2, size_t n, size_t k)
{
    flat_circles(b, r2, (r1 - r2) / (double)n, 0, n + 1, k);
    rings(b, n + 1, k, k, 1, 1);
    spokes(b, k, 1, n + 1, k, SIZE_MAX, SIZE_MAX);
}

static void make_circle(build *b, double r, size_t n)
{
    double dtheta = (2.0 * PI) / (double)n;
    size_t i;

    for (i = 0; i < n; i++)
        vert(b, r * cos((double)i * dtheta), r * sin((double)i * dtheta), 0);
    chain(b, 0, n, 1, 1);
}

/* ----------------------------------------------------- flat and boxy shapes */

static void make_square(build *b, double r)
{
    vert(b, -r, -r, 0);
    vert(b, -r, r, 0);
    vert(b, r, r, 0);
    vert(b, r, -r, 0);
    chain(b, 0, 4, 1, 1);
}

/* SquareGrid(r, n, k): (n+2) rows of (k+2) points, row i at y = -r + i*yStep. */
static void make_squaregrid(build *b, double r, size_t n, size_t k)
{
    double xstep = (2 * r) / (double)(1 + k), ystep = (2 * r) / (double)(1 + n);
    size_t i, j;

    for (i = 0; i <= n + 1; i++)
        for (j = 0; j <= k + 1; j++)
            vert(b, r - (double)j * xstep, -r + (double)i * ystep, 0);
    rings(b, n + 2, k + 2, k + 2, 1, 0);
    spokes(b, k + 2, 1, n + 2, k + 2, SIZE_MAX, SIZE_MAX);
}

static void make_box(build *b, double xs, double ys, double zs)
{
    vert(b, 0, 0, 0);
    vert(b, 0 + xs, 0, 0);
    vert(b, 0 + xs, 0, 0 + zs);
    vert(b, 0, 0, 0 + zs);
    vert(b, 0, 0 + ys, 0);
    vert(b, 0 + xs, 0 + ys, 0);
    vert(b, 0 + xs, 0 + ys, 0 + zs);
    vert(b, 0, 0 + ys, 0 + zs);
    edges(b, box_edges, 12);
}

static void make_cube(build *b)
{
    static const signed char c[8][3] = {
        {-1,-1,-1}, {1,-1,-1}, {1,-1,1}, {-1,-1,1}, {-1,1,-1}, {1,1,-1}, {1,1,1}, {-1,1,1} };

    corners(b, c, 8);
    edges(b, box_edges, 12);
}

/* Pyramid(s, h): the base square and four edges up to the apex. */
static void make_pyramid_plain(build *b, double s, double h)
{
    static const unsigned char e[8][2] = {
        {0,1}, {1,2}, {2,3}, {3,0}, {4,0}, {4,1}, {4,2}, {4,3} };

    vert(b, -s / 2, 0, -s / 2);
    vert(b, -s / 2, 0, s / 2);
    vert(b, s / 2, 0, s / 2);
    vert(b, s / 2, 0, -s / 2);
    vert(b, 0, h, 0);
    edges(b, e, 8);
}

/* Pyramid(s, h, n, k): the apex, k+1 and k-1 pairs of base points each fanned
** to the apex, then n squares whose half-side shrinks by s/(2n) a step (the
** Java code subtracts as it goes, and so does this). */
static void make_pyramid(build *b, double s, double h, size_t n, size_t k)
{
    double delta, dh, ds;
    size_t i, j, index = 1;

    vert(b, 0, h, 0);                                   /* apex, 0 */
    s = s / 2;
    delta = (2 * s) / (double)k;
    for (j = 0; j < 2 * k; j++) {
        double d = (double)(j <= k ? j : j - k) * delta;

        if (j <= k) {                                   /* j = 0 .. k */
            vert(b, -s + d, 0, -s);
            vert(b, s - d, 0, s);
        } else {                                        /* j - k = 1 .. k-1 */
            vert(b, s, 0, -s + d);
            vert(b, -s, 0, s - d);
        }
        seg(b, 0, index);
        seg(b, index, index + 1);
        seg(b, index + 1, 0);
        index += 2;
    }
    dh = h / (double)n;
    ds = s / (double)n;
    for (i = 0; i < n; i++) {
        double y = (double)i * dh;

        vert(b, s, y, s);
        vert(b, s, y, -s);
        vert(b, -s, y, -s);
        vert(b, -s, y, s);
        chain(b, index, 4, 1, 1);
        s -= ds;
        index += 4;
    }
}

static void make_axes3d(build *b, double xmax, double ymax, double zmax)
{
    vert(b, 0.0, 0, 0);
    vert(b, xmax, 0, 0);
    vert(b, 0, 0.0, 0);
    vert(b, 0, ymax, 0);
    vert(b, 0, 0, 0.0);
    vert(b, 0, 0, zmax);
    chain(b, 0, 2, 1, 0);
    chain(b, 2, 2, 1, 0);
    chain(b, 4, 2, 1, 0);
}

/* ----------------------------------------------------- the Platonic solids */

static void make_tetrahedron(build *b)
{
    static const signed char c[4][3] = { {1,1,1}, {-1,1,-1}, {1,-1,-1}, {-1,-1,1} };
    static const unsigned char e[6][2] = { {0,1}, {2,3}, {0,2}, {0,3}, {1,2}, {1,3} };

    corners(b, c, 4);
    edges(b, e, 6);
}

static void make_octahedron(build *b)
{
    static const signed char c[6][3] = {
        {1,0,0}, {0,0,-1}, {-1,0,0}, {0,0,1}, {0,1,0}, {0,-1,0} };
    static const unsigned char e[12][2] = {
        {0,1}, {1,2}, {2,3}, {3,0}, {0,4}, {1,4}, {2,4}, {3,4}, {0,5}, {1,5}, {2,5}, {3,5} };

    corners(b, c, 6);
    edges(b, e, 12);
}

/* Vertices whose coordinates are 0, +-1 or +-a (code 0, +-1, +-2), for the
** dodecahedron and the icosahedron. */
static void coded(build *b, const signed char (*c)[3], size_t n, double a, double a2)
{
    size_t i;
    int k;

    for (i = 0; i < n; i++) {
        double x[3];

        for (k = 0; k < 3; k++)
            x[k] = c[i][k] == 2 ? a : c[i][k] == -2 ? -a : c[i][k] == 3 ? a2
                 : c[i][k] == -3 ? -a2 : (double)c[i][k];
        vert(b, x[0], x[1], x[2]);
    }
}

/* Dodecahedron: t = (1 + sqrt 5)/2, r = 1/t (code 2), r*r (code 3). */
static void make_dodecahedron(build *b)
{
    static const signed char c[20][3] = {
        {-2,-2,-2}, {-2,-2,2}, {-2,2,-2}, {-2,2,2}, {2,-2,-2}, {2,-2,2}, {2,2,-2}, {2,2,2},
        {0,-3,-1}, {0,-3,1}, {0,3,-1}, {0,3,1},
        {-3,-1,0}, {-3,1,0}, {3,-1,0}, {3,1,0},
        {-1,0,-3}, {1,0,-3}, {-1,0,3}, {1,0,3} };
    static const unsigned char e[30][2] = {
        {3,11}, {11,7}, {7,15}, {15,13}, {13,3}, {7,19}, {19,17}, {17,6}, {6,15},
        {17,4}, {4,8}, {8,10}, {10,6}, {8,0}, {0,16}, {16,2}, {2,10},
        {0,12}, {12,1}, {1,18}, {18,16}, {2,13}, {18,3}, {1,9}, {9,11},
        {4,14}, {14,12}, {9,5}, {5,19}, {5,14} };
    double t = (1 + sqrt(5)) / 2, r = 1 / t;

    coded(b, c, 20, r, r * r);
    edges(b, e, 30);
}

/* Icosahedron: r = 1/t (code 2). */
static void make_icosahedron(build *b)
{
    static const signed char c[12][3] = {
        {-2,1,0}, {2,1,0}, {-2,-1,0}, {2,-1,0}, {0,-2,1}, {0,2,1},
        {0,-2,-1}, {0,2,-1}, {1,0,-2}, {1,0,2}, {-1,0,-2}, {-1,0,2} };
    static const unsigned char e[30][2] = {
        {0,1}, {0,5}, {0,7}, {0,11}, {0,10}, {1,5}, {1,7}, {1,9}, {1,8}, {5,11},
        {5,9}, {5,4}, {7,10}, {7,8}, {7,6}, {11,10}, {11,4}, {11,2}, {9,8}, {9,4},
        {9,3}, {10,6}, {10,2}, {8,6}, {8,3}, {4,2}, {4,3}, {6,2}, {6,3}, {2,3} };
    double t = (1 + sqrt(5)) / 2;

    coded(b, c, 12, 1 / t, 0);
    edges(b, e, 30);
}

/* Icosidodecahedron: the course's coordinates, 7 digits, and r = t - 1, the
** only computed one (TR in the table stands for r, -TR for -r). */
#define TR 9.0
static void make_icosidodecahedron(build *b)
{
    static const double c[30][3] = {
        {0, 0, 1.051462}, {TR, 0, 0.8506508}, {0.2763932, 0.5527864, 0.8506508},
        {-TR, 0, 0.8506508}, {-0.2763932, -0.5527864, 0.8506508}, {1, 0, 0.3249197},
        {0.7236068, -0.5527864, 0.5257311}, {-0.1708204, 0.8944272, 0.5257311},
        {0.4472136, 0.8944272, 0.3249197}, {-1, 0, 0.3249197},
        {-0.7236068, 0.5527864, 0.5257311}, {0.1708204, -0.8944272, 0.5257311},
        {-0.4472136, -0.8944272, 0.3249197}, {1, 0, -0.3249197},
        {0.8944272, 0.5527864, 0}, {0.5527864, -0.8944272, 0},
        {-0.5527864, 0.8944272, 0}, {0.4472136, 0.8944272, -0.3249197},
        {-1, 0, -0.3249197}, {-0.8944272, -0.5527864, 0},
        {-0.4472136, -0.8944272, -0.3249197}, {TR, 0, -0.8506508},
        {0.7236068, -0.5527864, -0.5257311}, {0.1708204, -0.8944272, -0.5257311},
        {-0.7236068, 0.5527864, -0.5257311}, {-0.1708204, 0.8944272, -0.5257311},
        {0.2763932, 0.5527864, -0.8506508}, {-TR, 0, -0.8506508},
        {-0.2763932, -0.5527864, -0.8506508}, {0, 0, -1.051462} };
    static const unsigned char e[60][2] = {
        {0,2}, {2,7}, {7,10}, {10,3}, {3,0}, {0,4}, {4,11}, {11,6}, {6,1}, {1,0},
        {1,5}, {5,14}, {14,8}, {8,2}, {2,1}, {3,9}, {9,19}, {19,12}, {12,4}, {4,3},
        {5,6}, {6,15}, {15,22}, {22,13}, {13,5}, {7,8}, {8,17}, {17,25}, {25,16}, {16,7},
        {9,10}, {10,16}, {16,24}, {24,18}, {18,9}, {11,12}, {12,20}, {20,23}, {23,15},
        {15,11}, {13,21}, {21,26}, {26,17}, {17,14}, {14,13}, {18,27}, {27,28}, {28,20},
        {20,19}, {19,18}, {21,22}, {22,23}, {23,28}, {28,29}, {29,21}, {24,25}, {25,26},
        {26,29}, {29,27}, {27,24} };
    double t = (1 + sqrt(5)) / 2, r = t - 1;
    size_t i;

    for (i = 0; i < 30; i++)
        vert(b, c[i][0] == TR ? r : c[i][0] == -TR ? -r : c[i][0], c[i][1], c[i][2]);
    edges(b, e, 60);
}

/* ===== reading the arguments ===== */

/* The next token of p[0..end) (spaces and tabs between) in *t, *n; 0: none. */
static int word(const char **p, const char *end, const char **t, size_t *n)
{
    const char *q = *p;

    while (q < end && (*q == ' ' || *q == '\t'))
        q++;
    *t = q;
    while (q < end && *q != ' ' && *q != '\t')
        q++;
    *n = (size_t)(q - *t);
    *p = q;
    return *n > 0;
}

/* t[0..n) as a number: reals as a scene's coordinates are written and read
** (core/numparse.h: digits, sign, point, exponent), ints also within Java's
** int range.  Returns 0, or -1 with a message in err. */
static int number(const char *t, size_t n, char kind, const char *name,
                  double *out, char *err, size_t errlen)
{
    char buf[512];
    size_t i;
    int rc = -1;

    for (i = 0; i < n; i++)
        if (strchr(kind == 'i' ? "0123456789+-" : "0123456789+-.eE", t[i]) == NULL)
            break;
    if (i == n && n < sizeof buf) rc = pt_parse_decimal(t, n, out);
    if (rc == -2) {
        snprintf(err, errlen, "%s: out of memory", name);
        return -1;
    }
    if (rc != 0) {
        snprintf(err, errlen, "%s '%.*s' is not %s", name, (int)(n < 40 ? n : 40), t,
                 kind == 'i' ? "an integer" : "a decimal number");
        return -1;
    }
    memcpy(buf, t, n);
    buf[n] = '\0';
    if (!isfinite(*out)) {
        snprintf(err, errlen, "%s '%s' is not finite", name, buf);
        return -1;
    }
    if (kind == 'i' && (*out < -2147483648.0 || *out > 2147483647.0)) {
        snprintf(err, errlen, "%s %s is out of range (a Java int: -2147483648..2147483647)",
                 name, buf);
        return -1;
    }
    return 0;
}

void pt_shape_counts(unsigned arities, char *buf, size_t len)
{
    size_t used = 0;
    int c, left = 0;

    for (c = 0; c <= PT_SHAPE_MAXP; c++)
        left += (arities >> c) & 1;
    buf[0] = '\0';
    for (c = 0; c <= PT_SHAPE_MAXP && used < len; c++) {
        if (!((arities >> c) & 1))
            continue;
        left--;
        used += (size_t)snprintf(buf + used, len - used, "%d%s", c,
                                 left > 1 ? ", " : left == 1 ? " or " : "");
    }
}

/* The shape's last two parameters n and k when they are ints (only k for the
** circle; 0 when there are none).  They are >= 0 here (the refusals ran). */
static void ints(int id, const double *x, size_t *n, size_t *k)
{
    int np = pt_shapes[id].nparam;

    *n = *k = 0;
    if (np >= 1 && pt_shapes[id].kind[np - 1] == 'i')
        *k = (size_t)x[np - 1];
    if (np >= 2 && pt_shapes[id].kind[np - 2] == 'i')
        *n = (size_t)x[np - 2];
}

/* How many vertices (*nv) and segments (*ns) shape id makes from x[]; the
** ints are >= their Java minimum and < 2^31, so no product overflows. */
static void sizes(int id, int given, const double *x, uint64_t *nv, uint64_t *ns)
{
    size_t sn, sk;
    uint64_t n, k;

    ints(id, x, &sn, &sk);
    n = sn;
    k = sk;
    switch (id) {
    case SPHERE:     *nv = n * k + 2; *ns = n * k + k * (n + 1); break;
    case CYLINDER:
    case CONE:       *nv = n * k + 2; *ns = n * (k - 1) + k * (n + 1); break;
    case TORUS:      *nv = n * k; *ns = 2 * n * k; break;
    case DISK:       *nv = n * k + 1; *ns = 2 * n * k; break;
    case RING:       *nv = (n + 1) * k; *ns = (n + 1) * k + n * k; break;
    case CIRCLE:     *nv = k; *ns = k; break;
    case SQUARE:     *nv = 4; *ns = 4; break;
    case SQUAREGRID: *nv = (n + 2) * (k + 2); *ns = (n + 2) * (k + 1) + (k + 2) * (n + 1); break;
    case TETRAHEDRON: *nv = 4; *ns = 6; break;
    case OCTAHEDRON: *nv = 6; *ns = 12; break;
    case DODECAHEDRON: *nv = 20; *ns = 30; break;
    case ICOSAHEDRON: *nv = 12; *ns = 30; break;
    case ICOSIDODECAHEDRON: *nv = 30; *ns = 60; break;
    case PYRAMID:
        if (given == 2) { *nv = 5; *ns = 8; }
        else { *nv = 1 + 4 * k + 4 * n; *ns = 6 * k + 4 * n; }
        break;
    case AXES3D:     *nv = 6; *ns = 3; break;
    default:         *nv = 8; *ns = 12; break;          /* CUBE, BOX */
    }
}

static void make(build *b, int id, int given, const double *x)
{
    size_t n, k;

    ints(id, x, &n, &k);
    switch (id) {
    case SPHERE:       make_sphere(b, x[0], n, k); break;
    case CYLINDER:     make_cylinder(b, x[0], x[1], n, k); break;
    case CONE:         make_cone(b, x[0], x[1], n, k); break;
    case TORUS:        make_torus(b, x[0], x[1], n, k); break;
    case DISK:         make_disk(b, x[0], n, k); break;
    case RING:         make_ring(b, x[0], x[1], n, k); break;
    case CIRCLE:       make_circle(b, x[0], k); break;
    case SQUARE:       make_square(b, x[0]); break;
    case SQUAREGRID:   make_squaregrid(b, x[0], n, k); break;
    case CUBE:         make_cube(b); break;
    case BOX:          make_box(b, x[0], x[1], x[2]); break;
    case TETRAHEDRON:  make_tetrahedron(b); break;
    case OCTAHEDRON:   make_octahedron(b); break;
    case DODECAHEDRON: make_dodecahedron(b); break;
    case ICOSAHEDRON:  make_icosahedron(b); break;
    case ICOSIDODECAHEDRON: make_icosidodecahedron(b); break;
    case PYRAMID:
        if (given == 2) make_pyramid_plain(b, x[0], x[1]);
        else make_pyramid(b, x[0], x[1], n, k);
        break;
    default:           make_axes3d(b, x[0], x[1], x[2]); break;
    }
}

/* ===== the public functions ===== */

const pt_shape_info *pt_shape_find(const char *name, size_t n)
{
    int i;

    for (i = 0; i < pt_nshapes; i++)
        if (strlen(pt_shapes[i].name) == n && memcmp(pt_shapes[i].name, name, n) == 0)
            return &pt_shapes[i];
    return NULL;
}

void pt_shape_free(pt_shape *sh)
{
    free(sh->v);
    free(sh->seg);
    memset(sh, 0, sizeof *sh);
}

int pt_shape_make(pt_shape *sh, const char *p, const char *end, const char **at,
                  char *err, size_t errlen)
{
    const pt_shape_info *in;
    const char *t, *extra = NULL, *argp[PT_SHAPE_MAXP], *whole = *at;
    size_t argn[PT_SHAPE_MAXP];
    double x[PT_SHAPE_MAXP];
    char list[64], names[64];
    uint64_t nv, ns;
    size_t n, i, used;
    int id, given = 0, k;
    build b;

    if (!word(&p, end, &t, &n)) {
        snprintf(err, errlen, "expected a shape name after 'shape' (pipetrace shapes lists them)");
        return -1;
    }
    in = pt_shape_find(t, n);
    if (in == NULL) {
        *at = t;
        snprintf(err, errlen, "unknown shape '%.*s' (pipetrace shapes lists them)",
                 (int)(n < 40 ? n : 40), t);
        return -1;
    }
    id = (int)(in - pt_shapes);
    for (; word(&p, end, &t, &n); given++) {
        if (given >= in->nparam) {
            if (extra == NULL)
                extra = t;
            continue;
        }
        *at = argp[given] = t;
        argn[given] = n;
        if (number(t, n, in->kind[given], in->param[given], &x[given], err, errlen) < 0)
            return -1;
    }
    *at = whole;
    if (given > in->nparam || !((in->arities >> given) & 1)) {
        pt_shape_counts(in->arities, list, sizeof list);
        for (k = 0, used = 0; k < in->nparam; k++)
            used += (size_t)snprintf(names + used, sizeof names - used, "%s%s",
                                     k ? " " : "", in->param[k]);
        if (extra != NULL)
            *at = extra;
        if (in->nparam == 0)
            snprintf(err, errlen, "shape %s takes no arguments, found %d", in->name, given);
        else
            snprintf(err, errlen, "shape %s takes %s arguments (%s), found %d",
                     in->name, list, names, given);
        return -1;
    }
    for (k = given; k < in->nparam; k++) {           /* the shorter overloads */
        int from = -1, j;

        for (j = 0; j < k; j++)
            if (strcmp(in->dflt[k], in->param[j]) == 0)
                from = j;
        x[k] = 0;
        if (from >= 0) x[k] = x[from];
        else if (pt_parse_decimal(in->dflt[k], strlen(in->dflt[k]), &x[k]) != 0)
            assert(!"a default is a plain decimal");
        argp[k] = NULL;
    }
    for (i = 0; i < sizeof refusals / sizeof refusals[0]; i++) {
        const refusal *r = &refusals[i];

        if (r->shape != id || !(in->kind[r->k] == 'i' ? x[r->k] < r->min : !(x[r->k] > 0)))
            continue;
        assert(argp[r->k] != NULL);  /* defaults pass every check */
        *at = argp[r->k];
        snprintf(err, errlen, "shape %s: %s, found %.*s", in->name, r->says,
                 (int)argn[r->k], argp[r->k]);
        return -1;
    }
    sizes(id, given, x, &nv, &ns);
    if (nv > PT_SHAPE_MAXV || ns > PT_SHAPE_MAXV) {
        snprintf(err, errlen, "shape %s would make %llu vertices and %llu segments "
                 "(at most %u each)", in->name, (unsigned long long)nv,
                 (unsigned long long)ns, PT_SHAPE_MAXV);
        return -1;
    }
    b.v = malloc((size_t)nv * sizeof *b.v);
    b.s = malloc((size_t)ns * sizeof *b.s);
    b.nv = b.ns = 0;
    if (b.v == NULL || b.s == NULL) {
        free(b.v);
        free(b.s);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    make(&b, id, given, x);
    assert(b.nv == nv && b.ns == ns);
    sh->v = b.v;
    sh->nv = b.nv;
    sh->seg = b.s;
    sh->nseg = b.ns;
    for (i = 0; i < b.nv; i++)
        if (!isfinite(b.v[i].x) || !isfinite(b.v[i].y) || !isfinite(b.v[i].z)) {
            snprintf(err, errlen, "shape %s: vertex %zu is not finite (the arguments "
                     "overflow or divide 0 by 0)", in->name, i + 1);
            pt_shape_free(sh);
            return -1;
        }
    return 0;
}
