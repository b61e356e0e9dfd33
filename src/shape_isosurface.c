/* shape_isosurface.c: isosurface { function { ... } [contained_by { box | sphere }]
 * [threshold T] [accuracy A] [max_gradient G] [max_trace N | all_intersections]
 * [open] [polarity P] [evaluate ...] }, POV-Ray 3.7's isosurface: the points
 * of its container where its function is below the threshold (above it with a
 * positive polarity). src/eval_isosurface.c reads it; the function is a
 * program of scene.functions, which the device runs as OpenCL C.
 *
 * Its numbers in scene_object: p[0], p[1] the container box's corners (p[0]
 * the sphere's centre and radius the sphere's radius, for a sphere); param[0]
 * threshold, [1] accuracy, [2] max_gradient, [3] max_trace; n[0][0] 1 for a
 * sphere container, n[0][1] 1 for a positive polarity; function, the
 * program, or -1 when --skip-unsupported left out a function the device
 * cannot run.
 *
 * trace() is POV-Ray's IsoSurface::All_Intersections in double: the same as
 * kernels/shape_isosurface.cl, which the device is held to (tests/test_shapes.c). */
#include <math.h>
#include <stdbool.h>

#include "ast.h"
#include "lower.h"
#include "shape.h"

#define MAX_TRACE 10
#define STACK 48

enum { ISO_OPEN = 1, ISO_POSITIVE = 2, ISO_SPHERE = 4 };   /* as the kernel's */

struct iso {
	const scene *s;
	const scene_object *o;
	bool open, positive, sphere;
	double threshold, accuracy, max_gradient;
	int max_trace;
};

static struct iso iso_of(const scene *s, const scene_object *o)
{
	return (struct iso){ .s = s, .o = o, .open = o->shape_flags & SHAPE_OPEN, .positive = o->n[0][1] != 0,
	                     .sphere = o->n[0][0] != 0, .threshold = o->param[0], .accuracy = o->param[1],
	                     .max_gradient = o->param[2], .max_trace = (int)o->param[3] };
}

/* The function less the threshold, negative inside. */
static double value(const struct iso *c, const double x[3])
{
	double f = scene_function_eval(c->s, c->o->function, x);
	return c->positive ? c->threshold - f : f - c->threshold;
}

static double value_at(const struct iso *c, const double P[3], const double D[3], double t)
{
	double x[3] = { P[0] + t * D[0], P[1] + t * D[1], P[2] + t * D[2] };
	return value(c, x);
}

static bool container(const struct iso *c, const double P[3], const double D[3], double *t1, double *t2)
{
	const scene_object *o = c->o;
	if (c->sphere) {
		double oc[3] = { P[0] - o->p[0][0], P[1] - o->p[0][1], P[2] - o->p[0][2] };
		double a = D[0] * D[0] + D[1] * D[1] + D[2] * D[2], b = oc[0] * D[0] + oc[1] * D[1] + oc[2] * D[2];
		double disc = b * b - a * (oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - o->radius * o->radius);
		if (!(disc > 0) || a == 0)
			return false;
		*t1 = (-b - sqrt(disc)) / a;
		*t2 = (-b + sqrt(disc)) / a;
	} else {
		*t1 = -INFINITY;
		*t2 = INFINITY;
		for (int k = 0; k < 3; k++) {
			double ta = (o->p[0][k] - P[k]) / D[k], tb = (o->p[1][k] - P[k]) / D[k];
			*t1 = fmax(*t1, fmin(ta, tb));
			*t2 = fmin(*t2, fmax(ta, tb));
		}
	}
	return *t2 > *t1 && *t2 > 0;
}

/* POV-Ray's Function_Find_Root, as iso_find_root in the kernel. */
static bool find_root(const struct iso *c, const double P[3], const double D[3], double t1, double t2, int *inv,
                      double *root)
{
	double vlen = sqrt(D[0] * D[0] + D[1] * D[1] + D[2] * D[2]);
	double at = t1, af = *inv * value_at(c, P, D, t1);
	if (c->open && af < 0) {
		*inv = -*inv;
		af = -af;
	}
	double bt = t2, bf = *inv * value_at(c, P, D, t2);
	double t21 = t2 - t1, dt = c->max_gradient * vlen * t21;
	double stack_t[STACK], stack_f[STACK];
	int n = 0;
	for (;;) {
		if (t21 < c->accuracy || n == STACK) {
			if (bf < 0) {
				*root = bt;
				return true;
			}
		} else if (af + bf - dt < 0) {
			t21 *= 0.5;
			dt *= 0.5;
			stack_t[n] = bt;
			stack_f[n] = bf;
			n++;
			bt = at + t21;
			bf = *inv * value_at(c, P, D, bt);
			continue;
		}
		if (n == 0)
			return false;
		at = bt;
		af = bf;
		n--;
		bt = stack_t[n];
		bf = stack_f[n];
		t21 = bt - at;
		dt = c->max_gradient * vlen * t21;
	}
}

/* The container's outward normal at x on its surface. */
static void container_normal(const struct iso *c, const double x[3], double n[3])
{
	const scene_object *o = c->o;
	if (c->sphere) {
		for (int k = 0; k < 3; k++)
			n[k] = x[k] - o->p[0][k];
		return;
	}
	double best = INFINITY;
	for (int k = 0; k < 3; k++)
		for (int side = 0; side < 2; side++) {
			double dist = fabs(x[k] - o->p[side][k]);
			if (dist < best) {
				best = dist;
				n[0] = n[1] = n[2] = 0;
				n[k] = side ? 1 : -1;
			}
		}
}

static void gradient(const struct iso *c, const double x[3], double n[3])
{
	double f = value(c, x);
	for (int k = 0; k < 3; k++) {
		double y[3] = { x[0], x[1], x[2] };
		y[k] += c->accuracy;
		n[k] = value(c, y) - f;
	}
	if (n[0] == 0 && n[1] == 0 && n[2] == 0)
		n[0] = 1;
}

static void trace(const scene *s, const scene_object *o, const double P[3], const double D[3], double tmin,
                  shape_hit *h)
{
	if (o->function < 0)
		return;
	struct iso c = iso_of(s, o);
	double t1, t2;
	if (!container(&c, P, D, &t1, &t2))
		return;
	double acc = c.accuracy, near = 4 * c.max_gradient * acc;
	double hits[MAX_TRACE + 2];
	bool on_container[MAX_TRACE + 2];
	int n = 0, traced = 0, inv = 1;
	t1 = fmax(t1, 0);
	if (!c.open) {
		double v = value_at(&c, P, D, t1);
		if (t1 > acc) {
			if (v < 0) {
				on_container[n] = true;
				hits[n++] = t1;
				traced++;
				inv = -1;
			}
		} else {
			if (v < near) {
				t1 = acc * 5;
				if (value_at(&c, P, D, t1) < 0)
					inv = -1;
			}
			if (value_at(&c, P, D, t2) < 0) {
				on_container[n] = true;
				hits[n++] = t2;
			}
		}
	}
	t1 = fmin(t1, t2);
	if (t2 - t1 < acc)
		return;
	if (t1 < acc && inv == 1 && fabs(value_at(&c, P, D, t1)) < near) {
		t1 = acc * 5;
		if (value_at(&c, P, D, t1) < 0)
			inv = -1;
	}
	for (; traced < c.max_trace; traced++) {
		double root;
		if (!find_root(&c, P, D, t1, t2, &inv, &root))
			break;
		on_container[n] = false;
		hits[n++] = root;
		t1 = root + acc * 5;
		if (t2 - t1 < acc)
			break;
		inv = -inv;
	}
	int best = -1;
	for (int i = 0; i < n; i++)
		if (hits[i] > tmin && hits[i] < h->t && (best < 0 || hits[i] < hits[best]))
			best = i;
	if (best < 0)
		return;
	h->t = hits[best];
	double x[3] = { P[0] + h->t * D[0], P[1] + h->t * D[1], P[2] + h->t * D[2] };
	if (on_container[best])
		container_normal(&c, x, h->n);
	else
		gradient(&c, x, h->n);
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	if (o->function < 0)
		return false;
	struct iso c = iso_of(s, o);
	bool in;
	if (c.sphere) {
		double d2 = 0;
		for (int k = 0; k < 3; k++)
			d2 += (p[k] - o->p[0][k]) * (p[k] - o->p[0][k]);
		in = d2 <= o->radius * o->radius;
	} else {
		in = true;
		for (int k = 0; k < 3; k++)
			in = in && p[k] >= o->p[0][k] && p[k] <= o->p[1][k];
	}
	return in && value(&c, p) < 0;
}

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	(void)s;
	if (o->n[0][0] != 0) {
		double a[3], b[3];
		for (int k = 0; k < 3; k++) {
			a[k] = o->p[0][k] - o->radius;
			b[k] = o->p[0][k] + o->radius;
		}
		shape_grow_xformed_box(&o->xf, a, b, lo, hi);
	} else {
		shape_grow_xformed_box(&o->xf, o->p[0], o->p[1], lo, hi);
	}
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	if (o->function < 0)
		return 0;   /* --skip-unsupported: warned when read */
	dev_prim p = { .type = PRIM_ISOSURFACE };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "isosurface with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	bool sphere = o->n[0][0] != 0;
	int flags = (o->shape_flags & SHAPE_OPEN ? ISO_OPEN : 0) | (o->n[0][1] != 0 ? ISO_POSITIVE : 0) |
	            (sphere ? ISO_SPHERE : 0);
	const double *hi = sphere ? (double[3]){ o->radius, 0, 0 } : o->p[1];
	p.link = lower_add_data(lw, (float4){ (float)o->p[0][0], (float)o->p[0][1], (float)o->p[0][2], (float)o->function });
	lower_add_data(lw, (float4){ (float)hi[0], (float)hi[1], (float)hi[2], (float)o->param[0] });
	lower_add_data(lw, (float4){ (float)o->param[1], (float)o->param[2], (float)o->param[3], (float)flags });
	double blo[3] = { INFINITY, INFINITY, INFINITY }, bhi[3] = { -INFINITY, -INFINITY, -INFINITY };
	bounds(s, o, blo, bhi);
	lower_add_prim(lw, p, mat, id, blo, bhi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "isosurface function %d", o->function);
	if (o->n[0][0] != 0) {
		scene_dump_vec(out, "sphere", o->p[0]);
		fputc(' ', out);
		scene_dump_num(out, o->radius);
	} else {
		scene_dump_vec(out, "box", o->p[0]);
		scene_dump_vec(out, "", o->p[1]);
	}
	static const char *const names[] = { " threshold ", " accuracy ", " max_gradient ", " max_trace " };
	for (int i = 0; i < 4; i++) {
		fputs(names[i], out);
		scene_dump_num(out, o->param[i]);
	}
	if (o->shape_flags & SHAPE_OPEN)
		fputs(" open", out);
	if (o->n[0][1] != 0)
		fputs(" polarity 1", out);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_isosurface = {
	.name = AST_WORD_ISOSURFACE, .args = NULL, .needs = "a function", .flags = SHAPE_OPEN,
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
