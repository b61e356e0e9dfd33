/* prism.h: what polygon, prism and text share (src/prism.c): a set of edges in
 * a plane (scene_outline), swept along that plane's normal between two
 * heights, with POV-Ray's even-odd inside.
 *
 * The shape's own space ("prism space") is POV-Ray's prism's: the edges lie in
 * the xz plane, the sweep goes along y from h1 to h2 (h1 <= h2). Each class
 * says how that space sits in its object space:
 *   prism: prism space is object space; radius = Height1, param[0] = Height2
 *     (sorted), param[1] = 1 for conic_sweep (the cross section at height y
 *     is the outline scaled by y).
 *   polygon: p[0] is the origin and n[0], n[1], n[2] the images of x, y, z (an
 *     orthonormal frame, n[1] the polygon's normal); one flat face at y = 0.
 *   text: (x, y, z) of prism space is (x, z, y) of the text's, the glyphs in
 *     the text's xy plane; radius = the thickness, the sweep along the text's z.
 *
 * On the device every one is PRIM_PRISM (kernels/shape_prism.cl), its rows
 * the map from world space to prism space and link its records:
 *   [0] h1, h2, the number of chunks (int bits), PRISM_ flags (int bits);
 *   [1] the box of the edges in the plane: xmin, zmin, xmax, zmax;
 *   then each chunk: its box (xmin, zmin, xmax, zmax), (its edge count, 1 when
 *   it starts a glyph (ints), 0, 0), and its edges (x0, z0, x1, z1), at most
 *   PRISM_CHUNK of them, all of one glyph. */
#ifndef ECLAT_PRISM_H
#define ECLAT_PRISM_H

#include <stdbool.h>

#include "shape.h"

#define PRISM_CHUNK 8

/* A shape of the three in prism space. */
typedef struct {
	const scene_outline *ol;
	int first, last;     /* the glyphs it covers: [first, last) */
	double h1, h2;
	int flags;           /* PRISM_ (kernels/shared.h) */
	xform local;         /* prism space to object space */
	xform inverse;       /* object space to prism space */
} prism_view;

/* The view of a polygon, prism or text object (all its glyphs). */
prism_view prism_view_of(const scene *s, const scene_object *o);

void prism_bounds(const prism_view *v, const xform *xf, double lo[3], double hi[3]);
void prism_trace(const prism_view *v, const double ro[3], const double rd[3], double tmin, shape_hit *h);
bool prism_inside(const prism_view *v, const double p[3]);
/* Its primitives: one per glyph outside CSG, one for all in CSG. */
int prism_lower(struct lowering *lw, const prism_view *v, const scene_object *o, int mat, int id);

/* Turns each edge of the outline so that the inside is on its left (the
 * outward normal of (x0, z0)-(x1, z1) is (z1 - z0, x0 - x1)), and drops the
 * edges of no length. */
void prism_orient(scene_outline *ol);

/* Whether the point (x, z) of the plane is inside glyphs [first, last) of ol. */
bool prism_in_outline(const scene_outline *ol, int first, int last, double x, double z);

/* The class functions (shape.h) of polygon, prism and text, on their outline. */
void prism_shape_bounds(const scene *s, const scene_object *o, double lo[3], double hi[3]);
void prism_shape_trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                       shape_hit *h);
bool prism_shape_inside(const scene *s, const scene_object *o, const double p[3]);
int prism_shape_lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id);

#endif
