/* shape_quadric.c: quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: POV-Ray's
 * general second-order surface
 *   A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0,
 * inside where the polynomial is not positive (POV-Ray's Inside). It is
 * unbounded, as in POV-Ray: lowering puts it among the unbounded primitives
 * that every ray tests, unless a CSG bounds it. On the device it keeps the map
 * from world space to its own space and its ten numbers in three PRIM_DATA
 * records (kernels/shape_quadric.cl). */
#include <math.h>

#include "lower.h"
#include "shape.h"

/* The ten coefficients, in the order written: A..J. */
static void coefficients(const scene_object *o, double q[10])
{
	for (int i = 0; i < 3; i++)
		for (int k = 0; k < 3; k++)
			q[3 * i + k] = o->p[i][k];
	q[9] = o->radius;
}

static double value_at(const double q[10], const double p[3])
{
	double x = p[0], y = p[1], z = p[2];
	return x * (q[0] * x + q[3] * y + q[4] * z + q[6]) + y * (q[1] * y + q[5] * z + q[7]) + z * (q[2] * z + q[8]) +
	       q[9];
}

static void gradient(const double q[10], const double p[3], double n[3])
{
	n[0] = 2 * q[0] * p[0] + q[3] * p[1] + q[4] * p[2] + q[6];
	n[1] = q[3] * p[0] + 2 * q[1] * p[1] + q[5] * p[2] + q[7];
	n[2] = q[4] * p[0] + q[5] * p[1] + 2 * q[2] * p[2] + q[8];
	if (n[0] == 0 && n[1] == 0 && n[2] == 0)
		n[0] = 1;   /* POV-Ray's choice where the normal is undefined */
}

/* The quadratic a t^2 + 2 b t + c along the ray, as POV-Ray's Intersect. */
static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	(void)s;
	double q[10];
	coefficients(o, q);
	double dx = rd[0], dy = rd[1], dz = rd[2], ox = ro[0], oy = ro[1], oz = ro[2];
	double a = dx * (q[0] * dx + q[3] * dy + q[4] * dz) + dy * (q[1] * dy + q[5] * dz) + dz * q[2] * dz;
	double b = dx * (q[0] * ox + 0.5 * (q[3] * oy + q[4] * oz + q[6])) +
	           dy * (q[1] * oy + 0.5 * (q[3] * ox + q[5] * oz + q[7])) +
	           dz * (q[2] * oz + 0.5 * (q[4] * ox + q[5] * oy + q[8]));
	double c = value_at(q, ro), t[2];
	int n = 0;
	if (a != 0) {
		double disc = b * b - a * c;
		if (disc <= 0)
			return;
		double r = -(b + copysign(sqrt(disc), b));
		t[0] = r / a;
		t[1] = r != 0 ? c / r : t[0];
		n = 2;
	} else if (b != 0) {
		t[0] = -0.5 * c / b;
		n = 1;
	}
	double best = h->t;
	for (int i = 0; i < n; i++)
		if (t[i] > tmin && t[i] < best)
			best = t[i];
	if (best == h->t)
		return;
	double p[3] = { ox + best * dx, oy + best * dy, oz + best * dz };
	h->t = best;
	gradient(q, p, h->n);
}

static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	(void)s;
	double q[10];
	coefficients(o, q);
	return value_at(q, p) <= 0;
}

static int lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	(void)s;
	double q[10];
	coefficients(o, q);
	dev_prim p = { .type = PRIM_QUADRIC };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "quadric with a singular transform (a scale of 0?) skipped");
		return 0;
	}
	p.link = lower_add_data(lw, (float4){ (float)q[0], (float)q[1], (float)q[2], (float)q[9] });
	lower_add_data(lw, (float4){ (float)q[3], (float)q[4], (float)q[5], 0 });
	lower_add_data(lw, (float4){ (float)q[6], (float)q[7], (float)q[8], 0 });
	double lo[3], hi[3];
	shape_unbounded(s, o, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

static void dump(FILE *out, const scene_object *o)
{
	fputs("quadric", out);
	scene_dump_vec(out, "", o->p[0]);
	scene_dump_vec(out, "", o->p[1]);
	scene_dump_vec(out, "", o->p[2]);
	fputs(" ", out);
	scene_dump_num(out, o->radius);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_quadric = {
	.name = "quadric", .args = "vvvf", .needs = "three vectors and a constant",
	.bounds = shape_unbounded, .trace = trace, .inside = inside, .lower = lower, .dump = dump,
};
