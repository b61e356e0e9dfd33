/* shape_poly.c: POV-Ray's polynomial surfaces, the points where a polynomial
 * in x, y and z is zero, inside where it is below POV-Ray's INSIDE_TOLERANCE:
 *
 *   poly { Order, <c0, c1, ...> [sturm] }         Order 2 to 35
 *   cubic { <c0, ..., c19> [sturm] }              poly of order 3
 *   quartic { <c0, ..., c34> [sturm] }            poly of order 4
 *   polynomial { Order, [xyz(i, j, k): c]... [sturm] }
 *
 * The coefficients are in POV-Ray's order (scene_poly), read by
 * src/eval_poly.c. Like POV-Ray, a poly has no bounds: lowering puts it among
 * the unbounded primitives every ray tests, unless a CSG (clipped_by, an
 * intersection) bounds it. A bounded_by of one sphere or box is POV-Ray's
 * Ray_In_Bound: a ray that misses it from outside misses the poly, which may
 * cut a poly that reaches past it (src/eval_poly.c keeps it).
 *
 * A ray's hits, as in POV-Ray's Poly::intersect: the ray with a unit
 * direction in the poly's space, the polynomial expanded into one in the
 * distance s along it (about the ray's point nearest the origin, where
 * POV-Ray expands it about the ray's start and loses high orders' digits), and its roots between POV-Ray's DEPTH_TOLERANCE and
 * MAX_DISTANCE (beyond which POV-Ray's Sturm solver does not look) found by
 * src/roots.c (kernels/shape_poly.cl and kernels/roots.cl on the device, in
 * double). POV-Ray's sturm picks its Sturm-sequence solver for cubics and
 * quartics (it always uses it above); eclat's finder isolates every root that
 * crosses zero, so sturm is read and changes nothing. The expansion keeps the
 * size of each coefficient's terms beside it, and a leading coefficient that
 * is no bigger than its rounding (a ray along an asymptotic direction) is
 * taken as zero, where POV-Ray drops those below 1e-10 (SMALL_ENOUGH). */
#include <float.h>
#include <math.h>

#include "lower.h"
#include "roots.h"
#include "shape.h"

#define DEPTH_TOLERANCE 1e-4    /* POV-Ray's: nearer hits (in the poly's space) are skipped */
#define INSIDE_TOLERANCE 1e-4   /* POV-Ray's: a value below it is inside */
#define MAX_DISTANCE 1e7        /* POV-Ray's: its solver looks no further (in the poly's space) */
#define FAR_COEFF 1e37          /* beyond float, which the device keeps them in */

static const scene_poly *poly_of(const scene *s, const scene_object *o)
{
	return &s->polys[o->poly];
}

/* The polynomial's value at p, by Horner's rule in z, then y, then x. */
static double value_at(const scene_poly *pl, const double p[3])
{
	int n = pl->order, term = 0;
	double vx = 0;
	for (int i = n; i >= 0; i--) {
		double vy = 0;
		for (int j = n - i; j >= 0; j--) {
			double vz = 0;
			for (int k = n - i - j; k >= 0; k--)
				vz = vz * p[2] + pl->c[term++];
			vy = vy * p[1] + vz;
		}
		vx = vx * p[0] + vy;
	}
	return vx;
}

/* The gradient at p, POV-Ray's normal; (1, 0, 0) where it vanishes. */
static void gradient(const scene_poly *pl, const double p[3], double g[3])
{
	int n = pl->order, term = 0;
	double pw[3][ROOTS_MAX_ORDER + 1];
	for (int a = 0; a < 3; a++) {
		pw[a][0] = 1;
		for (int i = 1; i <= n; i++)
			pw[a][i] = pw[a][i - 1] * p[a];
	}
	g[0] = g[1] = g[2] = 0;
	for (int i = n; i >= 0; i--)
		for (int j = n - i; j >= 0; j--)
			for (int k = n - i - j; k >= 0; k--) {
				double c = pl->c[term++];
				if (c == 0)
					continue;
				if (i > 0)
					g[0] += i * c * pw[0][i - 1] * pw[1][j] * pw[2][k];
				if (j > 0)
					g[1] += j * c * pw[0][i] * pw[1][j - 1] * pw[2][k];
				if (k > 0)
					g[2] += k * c * pw[0][i] * pw[1][j] * pw[2][k - 1];
			}
	if (g[0] == 0 && g[1] == 0 && g[2] == 0)
		g[0] = 1;
}

/* acc = acc (p + d s) + add, polynomials in s of degrees *deg and adeg (-1:
 * zero), and the same with every number's size, which bounds the rounding. */
static void horner_step(double *acc, double *mag, int *deg, double p, double d, const double *add,
                        const double *amag, int adeg)
{
	int n = *deg;
	if (n >= 0) {
		acc[n + 1] = acc[n] * d;
		mag[n + 1] = mag[n] * fabs(d);
		for (int h = n; h >= 1; h--) {
			acc[h] = acc[h] * p + acc[h - 1] * d;
			mag[h] = mag[h] * fabs(p) + mag[h - 1] * fabs(d);
		}
		acc[0] *= p;
		mag[0] *= fabs(p);
		n++;
	}
	for (int h = n + 1; h <= adeg; h++)
		acc[h] = mag[h] = 0;
	for (int h = 0; h <= adeg; h++) {
		acc[h] += add[h];
		mag[h] += amag[h];
	}
	*deg = n > adeg ? n : adeg;
}

/* The polynomial along the ray P + s D: its coefficients into q (q[h] of s^h);
 * returns its degree, leading coefficients lost in rounding dropped. */
static int along(const scene_poly *pl, const double P[3], const double D[3], double *q)
{
	int n = pl->order, term = 0, dx = -1;
	double mx[ROOTS_MAX_ORDER + 1], ay[ROOTS_MAX_ORDER + 1], my[ROOTS_MAX_ORDER + 1];
	double az[ROOTS_MAX_ORDER + 1], mz[ROOTS_MAX_ORDER + 1];
	for (int i = n; i >= 0; i--) {
		int dy = -1;
		for (int j = n - i; j >= 0; j--) {
			int dz = -1;
			for (int k = n - i - j; k >= 0; k--) {
				double c = pl->c[term++], m = fabs(c);
				horner_step(az, mz, &dz, P[2], D[2], &c, &m, 0);
			}
			horner_step(ay, my, &dy, P[1], D[1], az, mz, dz);
		}
		horner_step(q, mx, &dx, P[0], D[0], ay, my, dy);
	}
	while (dx > 0 && fabs(q[dx]) <= 8 * (n + 1) * DBL_EPSILON * mx[dx])
		dx--;
	return dx;
}

/* The map from the poly's space to its bound's unit sphere or cube
 * (scene_poly); -1 when there is none or it is singular. */
static int bound_map(const scene_poly *pl, const scene_object *o, xform *m)
{
	xform inv;
	if (pl->bound == SCENE_BOUND_NONE || lower_invert(&pl->bound_xf, &inv))
		return -1;
	*m = scene_xform_then(&o->xf, &inv);
	return 0;
}

/* POV-Ray's Ray_In_Bound: whether the ray (P, D) in the bound's unit space
 * meets the bound ahead of P, or starts inside it. */
static bool ray_in_bound(int kind, const double P[3], const double D[3])
{
	if (kind == SCENE_BOUND_SPHERE) {
		double pp = P[0] * P[0] + P[1] * P[1] + P[2] * P[2], pd = P[0] * D[0] + P[1] * D[1] + P[2] * D[2];
		double dd = D[0] * D[0] + D[1] * D[1] + D[2] * D[2];
		return pp <= 1 || (pd < 0 && pd * pd - dd * (pp - 1) >= 0);
	}
	double near = -INFINITY, far = INFINITY;
	for (int k = 0; k < 3; k++) {
		if (D[k] == 0) {
			if (fabs(P[k]) > 1)
				return false;
			continue;
		}
		double a = (-1 - P[k]) / D[k], b = (1 - P[k]) / D[k];
		near = fmax(near, fmin(a, b));
		far = fmin(far, fmax(a, b));
	}
	return near <= far && far >= 0;
}

static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	const scene_poly *pl = poly_of(s, o);
	double len = sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
	if (!(len > 0))
		return;
	xform m;
	if (bound_map(pl, o, &m) == 0) {
		double bp[3], bd[3];
		scene_xform_point(&m, ro, bp);
		scene_xform_vector(&m, rd, bd);
		if (!ray_in_bound(pl->bound, bp, bd))
			return;
	}
	double D[3] = { rd[0] / len, rd[1] / len, rd[2] / len }, q[ROOTS_MAX_ORDER + 1], u;
	/* expanded about the ray's point nearest the poly's origin, where its
	 * terms are smallest: about a far start their cancellation loses every
	 * digit of a high order (7^34 beside the 1 of x^34 + y^34 + z^34 = 1) */
	double b = -(ro[0] * D[0] + ro[1] * D[1] + ro[2] * D[2]);
	double C[3] = { ro[0] + b * D[0], ro[1] + b * D[1], ro[2] + b * D[2] };
	int n = along(pl, C, D, q);
	double lo = fmax(tmin * len, DEPTH_TOLERANCE) - b, hi = fmin(h->t * len, MAX_DISTANCE) - b;
	for (int i = 0; i < n && roots_find(q, n, lo, hi, &u, 1) == 1; i++) {
		double t = (u + b) / len;
		if (t > tmin) {   /* as the device, which rounds t to a float */
			if (t < h->t) {
				h->t = t;
				double x[3] = { C[0] + u * D[0], C[1] + u * D[1], C[2] + u * D[2] };
				gradient(pl, x, h->n);
			}
			return;
		}
		lo = u;
	}
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	return value_at(poly_of(s, o), p) < INSIDE_TOLERANCE;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	const scene_poly *pl = poly_of(s, o);
	int count = (pl->order + 1) * (pl->order + 2) * (pl->order + 3) / 6;
	for (int i = 0; i < count; i++)
		if (!(fabs(pl->c[i]) < FAR_COEFF)) {
			diag_warning(o->loc, "%s with a coefficient of %g skipped: past single precision", shape_of(o)->name,
			             pl->c[i]);
			return 0;
		}
	dev_prim p = { .type = PRIM_POLY };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "%s with a singular transform (a scale of 0?) skipped", shape_of(o)->name);
		return 0;
	}
	xform m;
	int bound = bound_map(pl, o, &m) == 0 ? pl->bound : SCENE_BOUND_NONE;
	p.link = lower_add_data(lw, (float4){ (float)pl->order, (float)bound, 0, 0 });
	for (int r = 0; bound != SCENE_BOUND_NONE && r < 3; r++)
		lower_add_data(lw, (float4){ (float)m.m[r][0], (float)m.m[r][1], (float)m.m[r][2], (float)m.m[r][3] });
	for (int i = 0; i < count; i += 2) {
		float h0 = (float)pl->c[i], h1 = i + 1 < count ? (float)pl->c[i + 1] : 0;
		float l0 = (float)(pl->c[i] - h0), l1 = i + 1 < count ? (float)(pl->c[i + 1] - h1) : 0;
		lower_add_data(lw, (float4){ h0, l0, h1, l1 });
	}
	double lo[3], hi[3];
	shape_unbounded(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "%s order %d", shape_of(o)->name, (int)o->param[0]);
	if (o->shape_flags & SHAPE_STURM)
		fputs(" sturm", out);
	scene_dump_xform(out, &o->xf);
}

#define POLY_CLASS(kw, what) \
	{ .name = kw, .args = NULL, .needs = what, .flags = SHAPE_STURM, .bounds = shape_unbounded, .trace = trace, \
	  .inside = inside, .lower = lower, .dump = dump }

const shape_class shape_poly = POLY_CLASS("poly", "an order and its coefficients");
const shape_class shape_cubic = POLY_CLASS("cubic", "20 coefficients");
const shape_class shape_quartic = POLY_CLASS("quartic", "35 coefficients");
const shape_class shape_polynomial = POLY_CLASS("polynomial", "an order and its xyz() terms");
