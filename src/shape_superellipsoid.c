/* shape_superellipsoid.c: superellipsoid { <E, N> }, POV-Ray's superellipsoid:
 * the points of [-1, 1]^3 with
 *     (|x|^(2/E) + |y|^(2/E))^(E/N) + |z|^(2/N) = 1,
 * which POV-Ray evaluates as G(G(|x|, |y|, 2/E), |z|, 2/N) = 1 with
 * G(a, b, p) = (a^p + b^p)^(1/p) (super.cpp); inside, less than 1. E or N 0 is
 * the limit, a square section.
 *
 * POV-Ray finds a ray's roots by sampling it between the planes that cut the
 * shape into 48 symmetric pieces. eclat bounds the function instead: within
 * an octant |x|, |y| and |z| are affine along the ray and the function grows
 * with each of them, so over a stretch of the ray it lies between its values
 * at the stretch's smallest and largest |x|, |y|, |z|. Halving the stretches
 * that may hold the surface, nearest first, finds the nearest crossing
 * without losing one. That is trace() here, the reference the device is held
 * to (tests/test_torus.c); kernels/shape_superellipsoid.cl does the same for
 * the shapes that are neither convex nor concave, and takes Newton's steps,
 * which cannot pass a crossing there, for the others. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "ast.h"
#include "lower.h"
#include "shape.h"

#define LEVELS 18   /* the halvings of an octant's stretch before its roots are bracketed */

/* POV-Ray's exponents: 2/E for x and y, 2/N for that and z (infinite for 0). */
struct se {
	double p, q;
	double o[3], d[3];   /* the ray */
	double oct[3];       /* the signs of the octant the ray is in (0: any) */
};

/* (a^p + b^p)^(1/p) for a, b >= 0, without overflow. */
static double gauge2(double a, double b, double p)
{
	double hi = fmax(a, b), lo = fmin(a, b);
	if (hi == 0)
		return 0;
	return hi * pow(1 + pow(lo / hi, p), 1 / p);
}

static double gauge(const struct se *s, double x, double y, double z)
{
	return gauge2(gauge2(fabs(x), fabs(y), s->p), fabs(z), s->q);
}

/* |x|, |y| or |z| at the ray's t in its octant: where the ray crosses into
 * it, a coordinate that rounding puts across 0 counts as 0 (with an exponent
 * below 1 its power would not be small). */
static double coord(const struct se *s, int k, double t)
{
	double x = s->o[k] + t * s->d[k];
	return s->oct[k] != 0 ? fmax(s->oct[k] * x, 0) : fabs(x);
}

/* The function along the ray: below 0 inside, above outside. */
static double along(const struct se *s, double t)
{
	return gauge(s, coord(s, 0, t), coord(s, 1, t), coord(s, 2, t)) - 1;
}

/* Whether the surface may cross the ray in [t0, t1], a stretch within one octant. */
static bool may_cross(const struct se *s, double t0, double t1)
{
	double lo[3], hi[3];
	for (int k = 0; k < 3; k++) {
		double a = coord(s, k, t0), b = coord(s, k, t1);
		lo[k] = fmin(a, b);
		hi[k] = fmax(a, b);
	}
	return gauge(s, lo[0], lo[1], lo[2]) <= 1 && gauge(s, hi[0], hi[1], hi[2]) >= 1;
}

/* The crossing in [a, b], where the function changes sign (fa, fb): the
 * Illinois variant of regula falsi. */
static double bracketed(const struct se *s, double a, double fa, double b, double fb)
{
	double tol = 1e-15 * (fabs(a) + fabs(b)) + DBL_MIN, c = a;
	int side = 0;
	for (int i = 0; i < 100 && b - a > tol; i++) {
		double prev = c;
		c = (a * fb - b * fa) / (fb - fa);
		if (!(c > a && c < b))
			c = 0.5 * (a + b);
		double fc = along(s, c);
		if (fc == 0 || fabs(c - prev) <= tol)
			return c;
		if ((fc < 0) == (fb < 0)) {
			b = c, fb = fc;
			if (side == -1)
				fa *= 0.5;
			side = -1;
		} else {
			a = c, fa = fc;
			if (side == 1)
				fb *= 0.5;
			side = 1;
		}
	}
	return c;
}

/* The nearest crossing in (a, b], a stretch within one octant, or NAN: the
 * stretches of a binary tree over it, depth first and nearest first, those
 * that cannot hold the surface left out; at the deepest level a sign change
 * (at the ends or the middle) brackets the crossing. */
static double first_crossing(const struct se *s, double a, double b)
{
	int level = 0;
	long idx = 0;
	double t0 = a;
	for (;;) {
		double t1 = idx + 1 == 1L << level ? b : a + (b - a) * ldexp((double)(idx + 1), -level);
		if (may_cross(s, t0, t1)) {
			if (level < LEVELS) {
				level++;
				idx *= 2;
				continue;
			}
			double f0 = along(s, t0), f1 = along(s, t1), tm = 0.5 * (t0 + t1), fm = along(s, tm);
			if (fm == 0)
				return tm;
			if (f0 != 0 && (f0 < 0) != (fm < 0))
				return bracketed(s, t0, f0, tm, fm);
			if (f1 == 0 || (fm < 0) != (f1 < 0))
				return f1 == 0 ? t1 : bracketed(s, tm, fm, t1, f1);
		}
		t0 = t1;
		while (idx & 1) {
			idx >>= 1;
			level--;
		}
		if (level == 0)
			return NAN;
		idx++;
	}
}

static void setup(struct se *s, const scene_object *o, const double ro[3], const double rd[3])
{
	s->p = 2 / o->p[0][0];
	s->q = 2 / o->p[0][1];
	memcpy(s->o, ro, sizeof s->o);
	memcpy(s->d, rd, sizeof s->d);
	s->oct[0] = s->oct[1] = s->oct[2] = 0;
}

/* POV-Ray's normal (super.cpp), the function's gradient, at a point of the surface. */
static void normal_at(const struct se *s, const double x[3], double n[3])
{
	double z2n = 0, r = 0, g1q = pow(gauge2(fabs(x[0]), fabs(x[1]), s->p), s->q);
	n[0] = n[1] = n[2] = 0;
	if (x[2] != 0) {
		z2n = pow(fabs(x[2]), s->q);
		n[2] = z2n / x[2];
	}
	if (fabs(x[0]) > fabs(x[1])) {
		r = pow(fabs(x[1] / x[0]), s->p);
		n[0] = g1q / x[0];
		n[1] = x[1] != 0 ? g1q * r / x[1] : 0;
	} else if (x[1] != 0) {
		r = pow(fabs(x[0] / x[1]), s->p);
		n[0] = x[0] != 0 ? g1q * r / x[0] : 0;
		n[1] = g1q / x[1];
	}
	n[2] *= 1 + r;
}

static const char *check(const scene_object *o)
{
	return o->p[0][0] >= 0 && o->p[0][1] >= 0 ? NULL : "a superellipsoid needs <E, N> with neither below 0";
}

/* POV-Ray's box, a little wider than the shape. */
static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	double a[3] = { -1.0001, -1.0001, -1.0001 }, b[3] = { 1.0001, 1.0001, 1.0001 };
	shape_grow_xformed_box(&o->xf, a, b, lo, hi);
}

static void trace(const scene *sc, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)sc;
	struct se s;
	setup(&s, o, ro, rd);
	/* the cube around it, a little larger */
	double ta = tmin, tb = h->t, cut[5];
	for (int k = 0; k < 3; k++) {
		if (rd[k] == 0) {
			if (fabs(ro[k]) > 1 + 1e-9)
				return;
			continue;
		}
		double a = (-1 - 1e-9 - ro[k]) / rd[k], b = (1 + 1e-9 - ro[k]) / rd[k];
		ta = fmax(ta, fmin(a, b));
		tb = fmin(tb, fmax(a, b));
	}
	if (!(ta < tb))
		return;
	/* the octants it crosses */
	int n = 0;
	cut[n++] = ta;
	for (int k = 0; k < 3; k++) {
		double t = rd[k] != 0 ? -ro[k] / rd[k] : NAN;
		if (t > ta && t < tb) {
			int i = n++;
			for (; i > 1 && cut[i - 1] > t; i--)
				cut[i] = cut[i - 1];
			cut[i] = t;
		}
	}
	cut[n++] = tb;
	for (int i = 0; i + 1 < n; i++) {
		for (int k = 0; k < 3; k++) {
			double mid = ro[k] + 0.5 * (cut[i] + cut[i + 1]) * rd[k];
			s.oct[k] = mid > 0 ? 1 : mid < 0 ? -1 : 0;
		}
		double t = first_crossing(&s, cut[i], cut[i + 1]);
		if (t > tmin && t < h->t) {
			double x[3] = { ro[0] + t * rd[0], ro[1] + t * rd[1], ro[2] + t * rd[2] };
			h->t = t;
			normal_at(&s, x, h->n);
			return;
		}
	}
}

static bool inside(const scene *sc, const scene_object *o, const double p[3])
{
	(void)sc;
	struct se s;
	setup(&s, o, p, p);
	return gauge(&s, p[0], p[1], p[2]) - 1 < 1e-10;   /* POV-Ray's EPSILON */
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	dev_prim p = { .type = PRIM_SUPERELLIPSOID };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "superellipsoid with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	/* p = 2/E and q = 2/N, each as a float and the float of what that leaves:
	 * double on the device (infinite for 0) */
	double e[2] = { 2 / o->p[0][0], 2 / o->p[0][1] };
	float f[4];
	for (int i = 0; i < 2; i++) {
		f[2 * i] = (float)e[i];
		f[2 * i + 1] = isfinite(e[i]) ? (float)(e[i] - f[2 * i]) : 0;
	}
	p.link = lower_add_data(lw, (float4){ f[0], f[1], f[2], f[3] });
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs("superellipsoid e ", out);
	scene_dump_num(out, o->p[0][0]);
	fputs(" n ", out);
	scene_dump_num(out, o->p[0][1]);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_superellipsoid = {
	.name = AST_WORD_SUPERELLIPSOID, .args = "v", .needs = "<E, N>",
	.check = check, .bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
