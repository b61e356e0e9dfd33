/* shape_julia_fractal.c: julia_fractal { <Julia4D> [quaternion | hypercomplex]
 * [sqr | cube] [max_iteration N] [precision P] [slice <Slice4D>, Dist] },
 * POV-Ray 3.7's 3-D slice of a 4-D Julia set (fractal.cpp, quatern.cpp,
 * hcmplx.cpp): the points whose orbit under z -> z^2 + c (or z^3 + c) stays
 * within the exit radius for max_iteration steps, z the point with the fourth
 * component the slice gives it.
 *
 * POV-Ray marches a ray from its bounding sphere with steps of the distance
 * estimate (quaternions) or of a step made from the normal (hypercomplex
 * numbers), never shorter than 1/precision, until the set's inside changes,
 * and bisects the last step to 1e-7. trace() does that here, in double, and
 * kernels/shape_julia_fractal.cl does the same in real; the normal is POV-Ray's
 * derivative of the orbit at the point just inside.
 *
 * scene_object: p[0] the constant's x, y, z and p[1][0] its w; p[1][1] the
 * slice's distance, p[1][2] 1/precision; n[0] the slice's x, y, z and n[1][0]
 * its t (unit length); param[0] max_iteration, param[1] the algebra
 * (JULIA_QUATERNION, JULIA_HYPERCOMPLEX), param[2] the function (JULIA_SQR,
 * JULIA_CUBE). */
#include <math.h>
#include <string.h>

#include "ast.h"
#include "lower.h"
#include "shape.h"

#define TOLERANCE 1e-7   /* POV-Ray's Fractal_Tolerance */

struct julia {
	double c[4], slice[4], slice_dist, precision, exit, radius;
	int iterations, algebra, function;
};

static double radius_of(const struct julia *j, double *exit);

static struct julia julia_of(const scene_object *o)
{
	struct julia j = {
		.c = { o->p[0][0], o->p[0][1], o->p[0][2], o->p[1][0] },
		.slice = { o->n[0][0], o->n[0][1], o->n[0][2], o->n[1][0] },
		.slice_dist = o->p[1][1], .precision = o->p[1][2],
		.iterations = (int)o->param[0], .algebra = (int)o->param[1], .function = (int)o->param[2],
	};
	j.radius = radius_of(&j, &j.exit);
	return j;
}

/* POV-Ray's Compute_BBox: the bounding sphere's radius, and the exit value. */
static double radius_of(const struct julia *j, double *exit)
{
	if (j->algebra == JULIA_HYPERCOMPLEX) {
		*exit = 16;
		return 4;
	}
	double r = 1 + sqrt(j->c[0] * j->c[0] + j->c[1] * j->c[1] + j->c[2] * j->c[2] + j->c[3] * j->c[3]) + TOLERANCE;
	r = fmin(r, 2);
	*exit = r * r + TOLERANCE;
	return r;
}

/* The orbit of a point: whether it stays (inside), and what the marching and
 * the normal need, computed forward along it. */
struct orbit {
	bool inside;
	double dist;      /* the step the marching may take from here */
	double normal[3]; /* at a point inside: the derivative's normal */
};

static void qmul(double r[4], const double a[4], const double b[4])
{
	double x = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
	double y = a[0] * b[1] + a[1] * b[0] + a[3] * b[2] - a[2] * b[3];
	double z = a[0] * b[2] + a[2] * b[0] + a[1] * b[3] - a[3] * b[1];
	double w = a[0] * b[3] + a[3] * b[0] + a[2] * b[1] - a[1] * b[2];
	r[0] = x, r[1] = y, r[2] = z, r[3] = w;
}

/* POV-Ray's HMult(r, a, b) of hypercomplex numbers. */
static void hmul(double r[4], const double a[4], const double b[4])
{
	double x = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] + a[3] * b[3];
	double y = a[1] * b[0] + a[0] * b[1] - a[3] * b[2] - a[2] * b[3];
	double z = a[2] * b[0] - a[3] * b[1] + a[0] * b[2] - a[1] * b[3];
	double w = a[3] * b[0] + a[2] * b[1] + a[1] * b[2] + a[0] * b[3];
	r[0] = x, r[1] = y, r[2] = z, r[3] = w;
}

/* The hypercomplex normal from h (the product along the orbit) and n (the
 * orbit's last point, scaled). */
static void hnormal(double out[3], const double h[4], const double n[4])
{
	out[0] = h[0] * n[0] + h[1] * n[1] + h[2] * n[2] + h[3] * n[3];
	out[1] = -h[1] * n[0] + h[0] * n[1] - h[3] * n[2] + h[2] * n[3];
	out[2] = -h[2] * n[0] - h[3] * n[1] + h[0] * n[2] + h[1] * n[3];
}

/* The quaternion normal's rows, one step of the orbit at z (POV-Ray's
 * Deriv_z2 and Deriv_z3). */
static void qderiv(double n[3][4], const double z[4], bool cube)
{
	double x = z[0], y = z[1], zz = z[2], w = z[3];
	double d = y * y + zz * zz + w * w, x2 = x * x, x3 = x2 - d, x4 = 3 * x2 - d;
	for (int r = 0; r < 3; r++) {
		double *m = n[r];
		if (cube) {
			double dt = 2 * (m[1] * y + m[2] * zz + m[3] * w), dt2 = 6 * x * m[0] - dt;
			m[0] = (m[0] * x3 - x * dt) * 3;
			m[1] = m[1] * x4 + y * dt2;
			m[2] = m[2] * x4 + zz * dt2;
			m[3] = m[3] * x4 + w * dt2;
		} else {
			double t = m[0] * x - m[1] * y - m[2] * zz - m[3] * w;
			m[1] = m[0] * y + x * m[1];
			m[2] = m[0] * zz + x * m[2];
			m[3] = m[0] * w + x * m[3];
			m[0] = t;
		}
	}
}

static void step(const struct julia *j, double z[4])
{
	double x = z[0], y = z[1], zz = z[2], w = z[3];
	if (j->algebra == JULIA_HYPERCOMPLEX) {
		double yz = y * y + zz * zz, xw = x * x + w * w;
		z[0] = xw - yz + j->c[0];
		z[1] = 2 * (x * y - zz * w) + j->c[1];
		z[2] = 2 * (x * zz - w * y) + j->c[2];
		z[3] = 2 * (x * w + y * zz) + j->c[3];
	} else if (j->function == JULIA_CUBE) {
		double d = y * y + zz * zz + w * w, x2 = x * x, t = 3 * x2 - d;
		z[0] = x * (x2 - 3 * d) + j->c[0];
		z[1] = y * t + j->c[1];
		z[2] = zz * t + j->c[2];
		z[3] = w * t + j->c[3];
	} else {
		double d = y * y + zz * zz + w * w, x2 = x * x;
		z[1] = 2 * x * y + j->c[1];
		z[2] = 2 * x * zz + j->c[2];
		z[3] = 2 * x * w + j->c[3];
		z[0] = x2 - d + j->c[0];
	}
}

/* POV-Ray's Iteration and D_Iteration (dir not NULL: the step too) and,
 * inside, its Normal_Calc, at p in the fractal's space. */
static struct orbit orbit_at(const struct julia *j, const double p[3], const double *dir)
{
	struct orbit r = { .dist = j->precision };
	double z[4] = { p[0], p[1], p[2], (j->slice_dist - j->slice[0] * p[0] - j->slice[1] * p[1] -
	                                   j->slice[2] * p[2]) / j->slice[3] };
	bool hyper = j->algebra == JULIA_HYPERCOMPLEX, cube = j->function == JULIA_CUBE;
	double prod[4], qn[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
	double pw = hyper ? 2 : cube ? 1.0 / 3 : 0.5;
	memcpy(prod, z, sizeof z);
	for (int i = 1; i <= j->iterations; i++) {
		double norm = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + z[3] * z[3];
		if (norm > j->exit) {
			if (!dir)
				return r;
			if (!hyper) {   /* the distance estimate */
				double p2 = prod[0] * prod[0] + prod[1] * prod[1] + prod[2] * prod[2] + prod[3] * prod[3];
				r.dist = pw * sqrt(norm / p2) * log(norm);
				return r;
			}
			double n[4], hn[3], s = cube ? 1 : pw;
			for (int k = 0; k < 4; k++)
				n[k] = z[k] * s;   /* z is the orbit's point i - 1, POV-Ray's N_Max */
			hnormal(hn, prod, n);
			double st = hn[0] * dir[0] + hn[1] * dir[1] + hn[2] * dir[2];
			if (st < -TOLERANCE) {
				st = -2 * st;
				if (norm > j->precision * st && norm < 30 * j->precision * st)
					r.dist = norm / st;
			}
			return r;
		}
		if (!hyper)
			qderiv(qn, z, cube);
		else if (i >= 2) {
			hmul(prod, z, prod);
			pw *= 2;
		}
		step(j, z);
		if (!hyper) {
			qmul(prod, prod, z);
			pw /= cube ? 3 : 2;
		}
	}
	r.inside = true;
	if (hyper) {
		double n[4], s = cube ? 1 : pw;
		for (int k = 0; k < 4; k++)
			n[k] = z[k] * s;
		hnormal(r.normal, prod, n);
	} else {
		for (int k = 0; k < 3; k++)
			r.normal[k] = qn[k][0] * z[0] + qn[k][1] * z[1] + qn[k][2] * z[2] + qn[k][3] * z[3];
	}
	return r;
}

static const char *check(const scene_object *o)
{
	(void)o;
	return NULL;
}

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	struct julia j = julia_of(o);
	double r = j.radius, a[3] = { -r, -r, -r }, b[3] = { r, r, r };
	shape_grow_xformed_box(&o->xf, a, b, lo, hi);
}

static void point(double out[3], const double o[3], const double d[3], double t)
{
	for (int k = 0; k < 3; k++)
		out[k] = o[k] + t * d[k];
}

/* POV-Ray's All_Intersections, the first hit past tmin (in unit steps s). */
static void trace(const scene *sc, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)sc;
	struct julia j = julia_of(o);
	double len = sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
	if (!(len > 0))
		return;
	double d[3] = { rd[0] / len, rd[1] / len, rd[2] / len };
	double b = ro[0] * d[0] + ro[1] * d[1] + ro[2] * d[2];
	double c = ro[0] * ro[0] + ro[1] * ro[1] + ro[2] * ro[2] - j.radius * j.radius, disc = b * b - c;
	if (disc < 0)
		return;
	double depth = -b - sqrt(disc), depth_max = fmin(-b + sqrt(disc), h->t * len);
	depth = fmax(depth, fmax(TOLERANCE, tmin * len));
	if (depth_max < TOLERANCE || depth >= depth_max)
		return;
	double next[3], ip[3], mid[3];
	point(next, ro, d, depth);
	struct orbit cur = orbit_at(&j, next, d);
	bool current = cur.inside;
	double dist = cur.dist;
	if (current) {   /* starting inside */
		depth += 2 * TOLERANCE;
		if (depth > depth_max)
			return;
		point(next, ro, d, depth);
		cur = orbit_at(&j, next, d);
		current = cur.inside, dist = cur.dist;
	}
	for (;;) {
		if (dist < j.precision)
			dist = j.precision;
		depth += dist;
		if (depth > depth_max)
			return;
		memcpy(ip, next, sizeof ip);
		point(next, ro, d, depth);
		struct orbit nx = orbit_at(&j, next, d);
		if (nx.inside != current) {
			depth -= dist;
			break;
		}
		dist = nx.dist;
	}
	bool last = current;
	while (dist > TOLERANCE) {   /* bisection */
		dist *= 0.5;
		point(mid, ip, d, dist);
		last = orbit_at(&j, mid, NULL).inside;
		if (last == current) {
			memcpy(ip, mid, sizeof ip);
			depth += dist;
			if (depth > depth_max)
				return;
		}
	}
	if (!current) {
		point(ip, ip, d, dist);
		depth += dist;
	}
	(void)last;
	struct orbit in = orbit_at(&j, ip, NULL);
	double t = depth / len;
	if (!(t > tmin && t < h->t))
		return;
	h->t = t;
	memcpy(h->n, in.normal, sizeof h->n);
}

static bool inside(const scene *sc, const scene_object *o, const double p[3])
{
	(void)sc;
	struct julia j = julia_of(o);
	return orbit_at(&j, p, NULL).inside;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	dev_prim p = { .type = PRIM_JULIA_FRACTAL };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "julia_fractal with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	struct julia j = julia_of(o);
	p.link = lower_add_data(lw, (float4){ (float)j.c[0], (float)j.c[1], (float)j.c[2], (float)j.c[3] });
	lower_add_data(lw, (float4){ (float)j.slice[0], (float)j.slice[1], (float)j.slice[2], (float)j.slice[3] });
	lower_add_data(lw, (float4){ (float)j.slice_dist, (float)j.precision, (float)j.exit, (float)j.radius });
	lower_add_data(lw, (float4){ (float)j.iterations, (float)j.algebra, (float)j.function, 0 });
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	struct julia j = julia_of(o);
	fprintf(out, "julia_fractal <%g, %g, %g, %g> %s %s max_iteration %d precision %g", j.c[0], j.c[1], j.c[2],
	        j.c[3], j.algebra == JULIA_HYPERCOMPLEX ? "hypercomplex" : "quaternion",
	        j.function == JULIA_CUBE ? "cube" : "sqr", j.iterations, 1 / j.precision);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_julia_fractal = {
	.name = AST_WORD_JULIA_FRACTAL, .args = NULL, .needs = "<Julia4D>",
	.check = check, .bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
