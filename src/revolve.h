/* revolve.h: sor and lathe, drawn as one: a profile of radius against height
 * revolved about the y axis, in pieces.
 *
 * A scene object of either keeps its points as written in its outline
 * (scene.outlines): edge[i] = { x (radius), y (height), 0, 0 }; a lathe keeps
 * its spline kind in param[0] (REVOLVE_LINEAR...); shape_flags: SHAPE_OPEN (a
 * sor without caps), SHAPE_STURM (read, changes nothing: the roots are found
 * the same way either way).
 *
 * The pieces: a curve, whose squared radius is the cubic
 *   r^2 = ((c0 u + c1) u + c2) u + c3, u = h - hc, for h1 <= h <= h2
 * (a sor's segment, POV-Ray's Compute_Sor; a lathe's straight segment, a cone
 * piece: r = x0 + s (h - y0) squared, about hc = y0, which keeps a nearly
 * level segment's numbers precise), or a disc at height h1 with r^2 between c0 and
 * c1 (a sor's caps, a lathe's level segment). A lathe's curved splines are
 * flattened into straight segments, finely enough that no segment strays more
 * than REVOLVE_FLAT of the lathe's size from the curve (POV-Ray solves them
 * exactly). Each piece has a side: +1 when the normal (x, -f'(h) / 2, z) of a
 * curve, or +y of a disc, points out of the solid, else -1. A lathe's piece
 * keeps POV-Ray's v (Lathe::UVCoord: the spline segment's number plus its
 * parameter, over the number of segments) at its ends, v[0] at h1 (a disc's
 * smaller radius) and v[1] at h2 (its larger): on the flattened piece the
 * parameter runs with the height (a disc's with the radius). */
#ifndef ECLAT_REVOLVE_H
#define ECLAT_REVOLVE_H

#include <stdbool.h>

#include "shape.h"

enum { REVOLVE_LINEAR, REVOLVE_QUADRATIC, REVOLVE_CUBIC, REVOLVE_BEZIER };
enum { REVOLVE_CURVE = 0, REVOLVE_DISC = 1 };
#define REVOLVE_FLAT 1e-4   /* of the lathe's size */

typedef struct {
	int kind;            /* REVOLVE_CURVE, REVOLVE_DISC */
	double h1, h2;       /* a curve's heights; a disc's height in h1 */
	double c[4];         /* a curve's: r^2 = the cubic of h - hc */
	double hc;
	double side;         /* +1 or -1 */
	double v[2];         /* a lathe's: POV-Ray's v at h1 and h2 (a disc: at its smaller and larger radius) */
} revolve_piece;

typedef struct {
	revolve_piece *piece;
	int n;
	bool lathe;          /* inside by counting crossings (lathe), else POV-Ray's sor rule */
	double rmax, hmin, hmax;
} revolve_profile;

/* The profile of a sor or lathe (free it with revolve_free); NULL message,
 * else what is wrong with the points (POV-Ray's errors). */
const char *revolve_profile_of(const scene *s, const scene_object *o, revolve_profile *pr);
void revolve_free(revolve_profile *pr);
void revolve_bounds(const revolve_profile *pr, const xform *xf, double lo[3], double hi[3]);
void revolve_trace(const revolve_profile *pr, const double ro[3], const double rd[3], double tmin, shape_hit *h);
bool revolve_inside(const revolve_profile *pr, const double p[3]);
int revolve_lower(struct lowering *lw, const revolve_profile *pr, const scene_object *o, int mat, int id);
/* A message when the points make no sor (POV-Ray's), else NULL: a count of
 * points n, then the points P[i] = (radius, height). */
const char *revolve_sor_points(const double (*P)[2], int n);
const char *revolve_lathe_points(int kind, const double (*P)[2], int n);

/* A sor's or lathe's class functions (shape.h), on its profile. */
void revolve_shape_bounds(const scene *s, const scene_object *o, double lo[3], double hi[3]);
void revolve_shape_trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                         shape_hit *h);
bool revolve_shape_inside(const scene *s, const scene_object *o, const double p[3]);
int revolve_shape_lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id);

#endif
