/* test_shapes.c: every shape of the table (src/shape.h) on the device against
 * its own class on the host. Random shapes under random transformations are
 * lowered as eclat lowers a scene, and the kernels (kernels/raycast.cl: the
 * renderer's traversal, intersection and surface normal, and the inside test)
 * are held to the class's trace() and inside test, which work in double
 * precision in the shape's object space:
 *   - each ray hits what the host says, at the same distance (1e-4 relative),
 *     on the same object with the same normal (the same line for a shape with
 *     no inside, whose side is the ray's), and any-hit agrees;
 *   - points are inside exactly where the host says (always outside a shape
 *     with no inside);
 * except within rounding, delta: 4 float ulps of the largest coordinate the
 * ray meets. A miss may be the host's answer for the ray moved by delta along
 * an axis or turned by a few ulps; a hit's point must lie within delta of the
 * object's surface, with its normal there (or between the two roots of a ray
 * within delta that grazes a curved surface), and the host must find nothing
 * nearer on the ray or on one so moved; a point may be the host's answer once
 * moved by delta. The rays are random, aimed at points of the surfaces, and
 * found by bisection on the host between two rays with different answers, so
 * they graze silhouettes and cross rims and edges exactly: there the device
 * may take either side, but must take one (a ray that slips between a
 * cylinder's cap and side fails), and 2 delta to either side it must answer
 * as the host (an edge drawn too far in or out fails). Every fourth scene lies
 * some hundreds of units from the origin.
 *
 *   test_shapes [-n SCENES] [-s SEED] [SHAPE...]
 *
 * tests the shapes named (all of them by default) in SCENES scenes each (24)
 * of OBJECTS objects, the random numbers seeded by SEED and the shape's name
 * (a shape's scenes are the same whichever others run).
 *
 * A shape is tested through one row of makers[] below: its keyword and a
 * function that fills a scene_object with a random one of its arguments and
 * flags, about the unit cube (the test transforms it). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "lower.h"
#include "shape.h"

static int failures;
static uint64_t seed = 0x2545f4914f6cdd1dull, rng_state;

static double uniform(void)   /* splitmix64 */
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

static double between(double a, double b)
{
	return a + (b - a) * uniform();
}

static void random_point(double p[3], double r)
{
	for (int k = 0; k < 3; k++)
		p[k] = between(-r, r);
}

static void random_direction(double d[3])
{
	double z = between(-1, 1), phi = 2 * M_PI * uniform(), s = sqrt(1 - z * z);
	d[0] = s * cos(phi), d[1] = s * sin(phi), d[2] = z;
}

/* ---- the shapes: one maker each ---- */

static void make_sphere(scene_object *o)
{
	random_point(o->p[0], 0.5);
	o->radius = between(0.2, 1);
}

static void make_box(scene_object *o)
{
	random_point(o->p[0], 1);
	for (int k = 0; k < 3; k++)   /* corners in any order */
		o->p[1][k] = o->p[0][k] + (uniform() < 0.5 ? -1 : 1) * between(0.1, 1.2);
}

static void make_plane(scene_object *o)
{
	random_direction(o->p[0]);
	for (int k = 0; k < 3; k++)
		o->p[0][k] *= between(0.5, 2);   /* the distance is in units of its length */
	o->radius = between(-1, 1);
}

static void make_triangle(scene_object *o)
{
	for (int i = 0; i < 3; i++)
		random_point(o->p[i], 1);
}

static void make_cylinder(scene_object *o)
{
	random_point(o->p[0], 1);
	random_point(o->p[1], 1);
	if (uniform() < 0.2)   /* along an axis, where POV-Ray's frame turns by 0 or 180 degrees */
		for (int k = 0; k < 3; k++)
			o->p[1][k] = k == 1 ? o->p[0][k] + (uniform() < 0.5 ? -1 : 1) : o->p[0][k];
	o->radius = between(0.1, 0.8) * (uniform() < 0.1 ? -1 : 1);
	o->shape_flags = uniform() < 0.4 ? SHAPE_OPEN : 0;
}

static void make_cone(scene_object *o)
{
	make_cylinder(o);
	double u = uniform();
	o->radius = between(0.1, 0.9);
	/* a point, a frustum either way up, two cones point to point (radii of opposite signs) */
	o->param[0] = u < 0.25 ? 0 : u < 0.8 ? between(0.05, 0.9) : -between(0.1, 0.9);
	if (uniform() < 0.5) {
		double r = o->radius;
		o->radius = o->param[0];
		o->param[0] = r;
	}
	if (uniform() < 0.1) {   /* both negative: a cylinder, as POV-Ray makes it */
		o->radius = -fabs(o->radius);
		o->param[0] = -fabs(o->param[0]) - 0.05;
	}
}

static void make_disc(scene_object *o)
{
	random_point(o->p[0], 1);
	random_direction(o->p[1]);
	for (int k = 0; k < 3; k++)
		o->p[1][k] *= between(0.2, 3);   /* any length */
	o->radius = between(0.2, 1.2);
	o->param[0] = uniform() < 0.5 ? 0 : between(0, 0.9) * o->radius;
}

/* The polynomial surfaces keep their coefficients in the scene: make_scene
 * sets this before it calls a maker. */
static scene *maker_scene;

/* The index of x^i y^j z^k in POV-Ray's order (src/eval_poly.c). */
static int term_index(int order, int i, int j, int k)
{
	int a = order - i, b = order - i - j, c = order - i - j - k;
	return a * (a + 1) * (a + 2) / 6 + b * (b + 1) / 2 + c;
}

static double *new_poly(scene_object *o, int order)
{
	int n = (order + 1) * (order + 2) * (order + 3) / 6;
	scene_poly pl = { .order = order, .c = calloc((size_t)n, sizeof(double)) };
	o->param[0] = order;
	o->poly = scene_add_poly(maker_scene, &pl);
	return pl.c;
}

/* POV-Ray's torus as a quartic (shapesq.inc's form), a spindle one now and
 * then: (x^2 + y^2 + z^2)^2 - 2 (R^2 + r^2)(x^2 + y^2 + z^2) + 4 R^2 y^2 + (R^2 - r^2)^2. */
static void make_torus_quartic(double *c)
{
	double R = between(0.4, 0.8), r = uniform() < 0.2 ? between(0.8, 1.1) * R : between(0.1, 0.6) * R;
	double k = -2 * (R * R + r * r);
	c[term_index(4, 4, 0, 0)] = c[term_index(4, 0, 4, 0)] = c[term_index(4, 0, 0, 4)] = 1;
	c[term_index(4, 2, 2, 0)] = c[term_index(4, 2, 0, 2)] = c[term_index(4, 0, 2, 2)] = 2;
	c[term_index(4, 2, 0, 0)] = c[term_index(4, 0, 0, 2)] = k;
	c[term_index(4, 0, 2, 0)] = k + 4 * R * R;
	c[term_index(4, 0, 0, 0)] = (R * R - r * r) * (R * R - r * r);
}

/* Random numbers on every term of the order, small beside a closed surface
 * x^n + y^n + z^n = 1 (n even) when closed is set. */
static void make_random_poly(double *c, int order, bool closed)
{
	int n = (order + 1) * (order + 2) * (order + 3) / 6;
	for (int i = 0; i < n; i++)
		c[i] = uniform() < 0.5 ? between(-1, 1) * (closed ? 0.2 : 1) : 0;
	if (closed) {
		c[term_index(order, order, 0, 0)] = c[term_index(order, 0, order, 0)] = 1;
		c[term_index(order, 0, 0, order)] = 1;
		c[term_index(order, 0, 0, 0)] = -between(0.2, 0.8);
	}
}

static void make_poly(scene_object *o)
{
	int order = 2 + (int)(uniform() * 5);   /* 2 to 6 */
	make_random_poly(new_poly(o, order), order, order % 2 == 0 && uniform() < 0.7);
	o->shape_flags = uniform() < 0.5 ? SHAPE_STURM : 0;
}

/* Two to six components, spheres and cylinders, a negative one now and then,
 * some in a space of their own (scaled unevenly and turned, as POV-Ray's
 * ellipsoidal components), overlapping about the unit cube. */
static void make_blob(scene_object *o)
{
	scene_blob bl = { .threshold = between(0.2, 0.8) };
	bl.n_parts = 2 + (int)(uniform() * 5);
	bl.part = calloc((size_t)bl.n_parts, sizeof *bl.part);
	for (int j = 0; j < bl.n_parts; j++) {
		scene_blob_part *p = &bl.part[j];
		random_point(p->a, 0.7);
		if (uniform() < 0.4)
			random_point(p->b, 0.7);
		else
			memcpy(p->b, p->a, sizeof p->a);
		p->r = between(0.3, 0.9);
		p->s = uniform() < 0.15 ? -between(0.2, 1) : between(0.5, 1.5);
		if (uniform() < 0.3) {   /* about its centre, so that it stays near the others */
			double sc[3] = { between(0.4, 1.6), between(0.4, 1.6), between(0.4, 1.6) };
			double deg[3] = { between(-90, 90), between(-90, 90), between(-90, 90) }, back[3], there[3];
			for (int i = 0; i < 3; i++)
				back[i] = -p->a[i], there[i] = p->a[i];
			xform t = scene_xform_translate(back), s1 = scene_xform_scale(sc), r = scene_xform_rotate(deg);
			xform m = scene_xform_then(&t, &s1);
			m = scene_xform_then(&m, &r);
			t = scene_xform_translate(there);
			p->xf = scene_xform_then(&m, &t);
			p->xformed = lower_invert(&p->xf, &p->inv) == 0;
		}
	}
	o->poly = scene_add_blob(maker_scene, &bl);
}

static void make_cubic(scene_object *o)
{
	make_random_poly(new_poly(o, 3), 3, false);
}

static void make_quartic(scene_object *o)
{
	double *c = new_poly(o, 4);
	if (uniform() < 0.6)
		make_torus_quartic(c);
	else
		make_random_poly(c, 4, uniform() < 0.5);
	double u = uniform(), r[3] = { between(0.3, 1), between(0.3, 1), between(0.3, 1) };
	if (u < 0.4) {   /* bounded_by a sphere or box of world space, which may cut it */
		scene_poly *pl = &maker_scene->polys[o->poly];
		pl->bound = u < 0.2 ? SCENE_BOUND_SPHERE : SCENE_BOUND_BOX;
		pl->bound_xf = scene_xform_scale(r);
	}
}

/* A few terms, up to order 6, beside x^n + y^n + z^n - k: a sparse random
 * polynomial alone often factors with a square (x^2 y: the plane x = 0
 * twice), a surface no ray crosses, which POV-Ray's solvers miss too. */
static void make_polynomial(scene_object *o)
{
	int order = 2 + (int)(uniform() * 5);
	double *c = new_poly(o, order);
	make_random_poly(c, order, true);
	for (int i = 0; i < (order + 1) * (order + 2) * (order + 3) / 6; i++)
		if (uniform() < 0.7)
			c[i] = 0;
	c[term_index(order, order, 0, 0)] = c[term_index(order, 0, order, 0)] = 1;
	c[term_index(order, 0, 0, order)] = 1;
	c[term_index(order, 0, 0, 0)] = -between(0.2, 0.8);
}

static const struct maker {
	const char *name;   /* the shape's keyword */
	void (*make)(scene_object *o);
} makers[] = {
	{ "sphere", make_sphere },
	{ "box", make_box },
	{ "plane", make_plane },
	{ "triangle", make_triangle },
	{ "cylinder", make_cylinder },
	{ "cone", make_cone },
	{ "disc", make_disc },
	{ "poly", make_poly },
	{ "cubic", make_cubic },
	{ "quartic", make_quartic },
	{ "polynomial", make_polynomial },
	{ "blob", make_blob },
};

/* ---- scenes ---- */

#define OBJECTS 4   /* in a scene: they may overlap and hide each other */

struct test_scene {
	scene sc;
	xform inv[OBJECTS];   /* world to each object's space */
	double lo[3], hi[3];  /* where the rays aim: the objects' box, within [-3, 3]^3 about them */
	double far[3];        /* the scene's offset from the origin */
};

/* A random transformation: turned, scaled evenly or not (a mirror now and
 * then), moved within the unit cube and then by far. */
static xform random_xform(const double far[3])
{
	double deg[3], s[3], t[3];
	for (int k = 0; k < 3; k++) {
		deg[k] = between(-180, 180);
		t[k] = between(-1, 1) + far[k];
	}
	double even = between(0.5, 1.5);
	int uneven = uniform() < 0.5;
	for (int k = 0; k < 3; k++)
		s[k] = uneven ? between(0.3, 1.8) * (uniform() < 0.1 ? -1 : 1) : even;
	xform a = scene_xform_scale(s), b = scene_xform_rotate(deg), c = scene_xform_translate(t);
	xform x = scene_xform_then(&a, &b);
	return scene_xform_then(&x, &c);
}

static void make_scene(struct test_scene *ts, const struct maker *m, scene_shape kind, int far)
{
	scene_init(&ts->sc);
	for (int k = 0; k < 3; k++)
		ts->far[k] = far ? between(-400, 400) : 0;
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	for (int i = 0; i < OBJECTS; i++) {
		scene_object o = { .shape = kind, .xf = scene_xform_identity(), .material = scene_default_material(),
		                   .mesh = -1, .loc = SRC_NOWHERE };
		const char *bad;
		maker_scene = &ts->sc;
		do {   /* arguments the class accepts */
			memset(o.p, 0, sizeof o.p);
			memset(o.param, 0, sizeof o.param);
			o.radius = 0;
			o.shape_flags = 0;
			m->make(&o);
			bad = shape_of(&o)->check ? shape_of(&o)->check(&o) : NULL;
		} while (bad);
		o.xf = random_xform(ts->far);
		lower_invert(&o.xf, &ts->inv[i]);
		shape_of(&o)->bounds(&ts->sc, &o, lo, hi);
		scene_add_object(&ts->sc, &o);
	}
	for (int k = 0; k < 3; k++) {   /* a plane's box is unbounded */
		ts->lo[k] = fmax(lo[k], ts->far[k] - 3);
		ts->hi[k] = fmin(hi[k], ts->far[k] + 3);
	}
}

/* ---- the host's answers ---- */

struct answer {
	double t;        /* INFINITY: none */
	int object;      /* -1: none */
	double n[3];     /* the unit normal in world space */
};

/* Object i's nearest hit past tmin of the ray (o, d) in world space (its trace() in object space). */
static struct answer trace_past(const struct test_scene *ts, int i, const double o[3], const double d[3], double tmin)
{
	const scene_object *s = &ts->sc.objects[i];
	struct answer a = { INFINITY, -1, { 0, 0, 0 } };
	double lo[3], ld[3];
	scene_xform_point(&ts->inv[i], o, lo);
	scene_xform_vector(&ts->inv[i], d, ld);
	shape_hit h = { .t = INFINITY };
	shape_of(s)->trace(&ts->sc, s, lo, ld, tmin, &h);
	if (h.t == INFINITY)
		return a;
	const double (*m)[4] = ts->inv[i].m;
	double len = 0;
	for (int k = 0; k < 3; k++) {   /* normals go to world space by the inverse's transpose */
		a.n[k] = m[0][k] * h.n[0] + m[1][k] * h.n[1] + m[2][k] * h.n[2];
		len += a.n[k] * a.n[k];
	}
	for (int k = 0; k < 3; k++)
		a.n[k] /= sqrt(len);
	a.t = h.t;
	a.object = i;
	return a;
}

static struct answer trace_object(const struct test_scene *ts, int i, const double o[3], const double d[3])
{
	return trace_past(ts, i, o, d, 0);
}

static struct answer trace_scene(const struct test_scene *ts, const double o[3], const double d[3])
{
	struct answer best = { INFINITY, -1, { 0, 0, 0 } };
	for (int i = 0; i < ts->sc.n_objects; i++) {
		struct answer a = trace_object(ts, i, o, d);
		if (a.t < best.t)
			best = a;
	}
	return best;
}

static bool inside_object(const struct test_scene *ts, int i, const double p[3])
{
	const scene_object *s = &ts->sc.objects[i];
	double q[3];
	scene_xform_point(&ts->inv[i], p, q);
	return shape_of(s)->inside && shape_of(s)->inside(&ts->sc, s, q);
}

/* ---- the device's answers ---- */

struct device_scene {
	device_ctx *dev;
	cl_program prog;
	lower_result lr;
};

static cl_mem buffer(struct device_scene *ds, cl_mem_flags flags, size_t bytes, const void *data)
{
	cl_int err;   /* an empty one is 16 bytes of nothing: no copy from a 0-byte array */
	bool copy = data && bytes > 0;
	return clCreateBuffer(ds->dev->context, flags | (copy ? CL_MEM_COPY_HOST_PTR : 0), bytes ? bytes : 16,
	                      copy ? (void *)data : NULL, &err);
}

/* Casts n rays (8 floats each: origin, tmax, direction, 0) through
 * raycast_surface: hits (t, primitive, instance, any) and surfaces (normal,
 * object). */
static int cast(struct device_scene *ds, const float *rays, int n, float *hits, float *surfaces)
{
	lower_result *lr = &ds->lr;
	cl_int err;
	cl_kernel k = clCreateKernel(ds->prog, "raycast_surface", &err);
	if (err != CL_SUCCESS)
		return device_fail("clCreateKernel raycast_surface", err);
	cl_mem b[5] = {
		buffer(ds, CL_MEM_READ_ONLY, lr->dev_node_bytes, lr->dev_nodes),
		buffer(ds, CL_MEM_READ_ONLY, lr->n_all_prims * sizeof(dev_prim), lr->prims),
		buffer(ds, CL_MEM_READ_ONLY, lr->n_normals * sizeof(float4), lr->normals),
		buffer(ds, CL_MEM_READ_ONLY, (size_t)n * 8 * sizeof(float), rays),
		buffer(ds, CL_MEM_WRITE_ONLY, (size_t)n * 8 * sizeof(float), NULL),
	};
	cl_mem out_s = buffer(ds, CL_MEM_WRITE_ONLY, (size_t)n * 4 * sizeof(float), NULL);
	clSetKernelArg(k, 0, sizeof(cl_mem), &b[0]);
	clSetKernelArg(k, 1, sizeof(cl_mem), &b[1]);
	clSetKernelArg(k, 2, sizeof(cl_mem), &b[2]);
	clSetKernelArg(k, 3, sizeof(int), &lr->n_prims);
	clSetKernelArg(k, 4, sizeof(int), &lr->n_planes);
	clSetKernelArg(k, 5, sizeof(cl_mem), &b[3]);
	clSetKernelArg(k, 6, sizeof(cl_mem), &b[4]);
	clSetKernelArg(k, 7, sizeof(cl_mem), &out_s);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(ds->dev->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(ds->dev->queue, b[4], CL_TRUE, 0, (size_t)n * 4 * sizeof(float), hits, 0, NULL,
		                          NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(ds->dev->queue, out_s, CL_TRUE, 0, (size_t)n * 4 * sizeof(float), surfaces, 0,
		                          NULL, NULL);
	for (int i = 0; i < 5; i++)
		clReleaseMemObject(b[i]);
	clReleaseMemObject(out_s);
	clReleaseKernel(k);
	return err == CL_SUCCESS ? 0 : device_fail("raycast_surface", err);
}

/* points: 4 floats each, the point and the primitive (int bits); inside: 0 or 1. */
static int inside_points(struct device_scene *ds, const float *points, int n, int *inside)
{
	lower_result *lr = &ds->lr;
	cl_int err;
	cl_kernel k = clCreateKernel(ds->prog, "inside_points", &err);
	if (err != CL_SUCCESS)
		return device_fail("clCreateKernel inside_points", err);
	cl_mem b[3] = {
		buffer(ds, CL_MEM_READ_ONLY, lr->n_all_prims * sizeof(dev_prim), lr->prims),
		buffer(ds, CL_MEM_READ_ONLY, (size_t)n * 4 * sizeof(float), points),
		buffer(ds, CL_MEM_WRITE_ONLY, (size_t)n * sizeof(int), NULL),
	};
	for (int i = 0; i < 3; i++)
		clSetKernelArg(k, i, sizeof(cl_mem), &b[i]);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(ds->dev->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(ds->dev->queue, b[2], CL_TRUE, 0, (size_t)n * sizeof(int), inside, 0, NULL, NULL);
	for (int i = 0; i < 3; i++)
		clReleaseMemObject(b[i]);
	clReleaseKernel(k);
	return err == CL_SUCCESS ? 0 : device_fail("inside_points", err);
}

/* ---- comparing ---- */

/* How far rounding may move a ray or point: some float ulps of the largest
 * coordinate it meets (the shapes' maps hold floats of that size). */
static double rounding(const double p[3], double extra)
{
	return 4 * FLT_EPSILON * (fmax(fmax(fabs(p[0]), fabs(p[1])), fabs(p[2])) + extra);
}

static bool normals_agree(const struct test_scene *ts, int object, const double a[3], const double b[3]);

/* Whether the device's hit (t, object, normal n; object -1 for none) is the
 * host's for the ray (o, d): the same nearest distance, and the device's
 * object hit there with the same normal (for a shape with no inside, up to
 * its sign). */
static bool agrees(const struct test_scene *ts, const double o[3], const double d[3], double t, int object,
                   const double n[3])
{
	struct answer best = trace_scene(ts, o, d);
	if (object < 0 || best.object < 0)
		return object < 0 && best.object < 0;
	double tol = 1e-4 * fmax(1, best.t);
	if (fabs(t - best.t) > tol)
		return false;
	struct answer mine = trace_object(ts, object, o, d);   /* surfaces may meet there */
	if (!(fabs(t - mine.t) <= tol))
		return false;
	return normals_agree(ts, object, n, mine.n);
}

static bool normals_agree(const struct test_scene *ts, int object, const double a[3], const double b[3])
{
	double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
	return (shape_of(&ts->sc.objects[object])->inside ? c : fabs(c)) > 0.999;
}

/* p moved by delta along axis k / 2, down for even k and up for odd k; k < 0: p itself. */
static void nudge(const double p[3], int k, double delta, double out[3])
{
	memcpy(out, p, 3 * sizeof *out);
	if (k >= 0)
		out[k / 2] += k % 2 ? delta : -delta;
}

/* Whether x, with the normal n, is a point of the object's surface within
 * delta: a probe along -n from 2 delta above x, or above x moved by delta,
 * meets the surface within 4 delta with the normal n; or with a normal that
 * turns less from one the probes found than theirs turn among themselves
 * (near a cone's point, where delta spans many normals). */
static bool on_surface(const struct test_scene *ts, int object, const double x[3], const double n[3], double delta)
{
	double back[3] = { -n[0], -n[1], -n[2] }, found[7][3];
	int m = 0;
	bool sided = shape_of(&ts->sc.objects[object])->inside != NULL;
	for (int k = -1; k < 6; k++) {
		double p[3], s[3];
		nudge(x, k, delta, p);
		for (int i = 0; i < 3; i++)
			s[i] = p[i] + 2 * delta * n[i];
		struct answer a = trace_object(ts, object, s, back);
		if (!(a.t <= 4 * delta))
			continue;
		if (normals_agree(ts, object, a.n, n))
			return true;
		memcpy(found[m++], a.n, sizeof found[0]);
	}
	double spread = 0, best = INFINITY;
	for (int j = 0; j < m; j++) {
		double c = found[j][0] * n[0] + found[j][1] * n[1] + found[j][2] * n[2];
		best = fmin(best, 1 - (sided ? c : fabs(c)));
		for (int k = 0; k < j; k++) {
			c = found[j][0] * found[k][0] + found[j][1] * found[k][1] + found[j][2] * found[k][2];
			spread = fmax(spread, 1 - (sided ? c : fabs(c)));
		}
	}
	return m >= 2 && best <= spread + 0.001;
}

/* Whether a ray within delta of (o, d) meets the object where the device's
 * hit is: t between its first two hits on the object there, the normal that
 * of one of them. A ray that grazes a curved surface has its two roots close
 * together, and the device's, in single precision, anywhere between them. */
static bool on_chord(const struct test_scene *ts, int object, const double o[3], const double d[3], double t,
                     const double n[3], double delta)
{
	double slack = 4 * delta + 1e-5 * t;
	for (int k = -1; k < 6; k++) {
		double p[3];
		nudge(o, k, delta, p);
		struct answer a = trace_object(ts, object, p, d);
		if (a.object < 0 || t < a.t - slack)
			continue;
		struct answer b = trace_past(ts, object, p, d, a.t + 1e-9 * fmax(1, a.t));
		if (t <= (b.object >= 0 ? b.t : a.t) + slack &&
		    (normals_agree(ts, object, n, a.n) || (b.object >= 0 && normals_agree(ts, object, n, b.n))))
			return true;
	}
	return false;
}

/* Whether the device's answer is the host's within rounding: for a miss, the
 * host misses the ray once moved by delta along some axis or turned by some
 * float ulps; for a hit, its point lies on the object's surface with its
 * normal (within delta), and the host meets nothing nearer on the ray or on
 * one so moved or turned. */
static bool agrees_nearby(const struct test_scene *ts, const double o[3], const double d[3], double t, int object,
                          const double n[3], double delta)
{
	if (object >= 0) {
		double x[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
		if (!on_surface(ts, object, x, n, delta) && !on_chord(ts, object, o, d, t, n, delta))
			return false;
	}
	double slack = object >= 0 ? 4 * delta + 1e-5 * t : 0;
	for (int k = -1; k < 12; k++) {
		double p[3], q[3];
		nudge(o, k < 6 ? k : -1, delta, p);
		nudge(d, k < 6 ? -1 : k - 6, 16 * FLT_EPSILON, q);
		if (trace_scene(ts, p, q).t >= (object >= 0 ? t - slack : INFINITY))
			return true;
	}
	return false;
}

/* The objects a and b (-1: none) as --dump-scene writes them. */
static void dump_objects(const struct test_scene *ts, int a, int b)
{
	for (int i = 0; i < ts->sc.n_objects; i++)
		if (i == a || i == b) {
			fprintf(stderr, "    object %d: ", i);
			shape_of(&ts->sc.objects[i])->dump(stderr, &ts->sc.objects[i]);
			fputc('\n', stderr);
		}
}

struct tally {
	int rays, hits, edges, bad, any_bad, points, inside, point_edges, point_bad;
};

/* Casts the rays (doubles: origin and unit direction, 6 a ray) on the device,
 * as floats, and compares each with the host. */
static void compare_rays(const char *what, struct device_scene *ds, const struct test_scene *ts, const double *rd,
                         int n, struct tally *tl)
{
	float *rays = malloc((size_t)n * 8 * sizeof *rays), *hits = malloc((size_t)n * 4 * sizeof *hits);
	float *surf = malloc((size_t)n * 4 * sizeof *surf);
	for (int i = 0; i < n; i++) {
		for (int k = 0; k < 3; k++) {
			rays[8 * i + k] = (float)rd[6 * i + k];
			rays[8 * i + 4 + k] = (float)rd[6 * i + 3 + k];
		}
		rays[8 * i + 3] = INFINITY;
		rays[8 * i + 7] = 0;
	}
	if (cast(ds, rays, n, hits, surf)) {
		failures++;
		n = 0;
	}
	for (int i = 0; i < n; i++) {
		/* the host sees the ray as the device does */
		double o[3] = { rays[8 * i], rays[8 * i + 1], rays[8 * i + 2] };
		double d[3] = { rays[8 * i + 4], rays[8 * i + 5], rays[8 * i + 6] };
		const float *h = hits + 4 * i, *s = surf + 4 * i;
		int prim, object;
		memcpy(&prim, &h[1], sizeof prim);
		memcpy(&object, &s[3], sizeof object);
		if (prim < 0)
			object = -1;
		double t = h[0], nrm[3] = { s[0], s[1], s[2] };
		tl->rays++;
		tl->hits += prim >= 0;
		tl->any_bad += (h[3] > 0.5f) != (prim >= 0);
		if (agrees(ts, o, d, t, object, nrm))
			continue;
		struct answer ref = trace_scene(ts, o, d);
		double far = prim >= 0 ? t : ref.object >= 0 ? ref.t : 0;
		if (agrees_nearby(ts, o, d, t, object, nrm, rounding(o, far))) {
			tl->edges++;
			continue;
		}
		if (tl->bad++ < 5) {
			fprintf(stderr,
			        "  %s ray %d <%.9g, %.9g, %.9g> <%.9g, %.9g, %.9g>: device t %.9g object %d normal <%.4f, %.4f, "
			        "%.4f>, host t %.9g object %d normal <%.4f, %.4f, %.4f>\n",
			        what, i, o[0], o[1], o[2], d[0], d[1], d[2], t, object, nrm[0], nrm[1], nrm[2], ref.t,
			        ref.object, ref.n[0], ref.n[1], ref.n[2]);
			dump_objects(ts, object, ref.object);
		}
	}
	free(rays);
	free(hits);
	free(surf);
}

/* The device primitive of each object: the one with its number, when it has
 * exactly one (-1 otherwise: its inside is not tested). */
static void object_prims(const lower_result *lr, int *prim, int n_objects)
{
	for (int i = 0; i < n_objects; i++)
		prim[i] = -1;
	for (int i = 0; i < lr->n_prims + lr->n_planes; i++) {
		int o = lr->prims[i].object;
		if (o >= 0 && o < n_objects)
			prim[o] = prim[o] == -1 ? i : -2;
	}
}

static void compare_points(const char *what, struct device_scene *ds, const struct test_scene *ts, int n,
                           struct tally *tl)
{
	int prim[OBJECTS];
	object_prims(&ds->lr, prim, ts->sc.n_objects);
	float *points = malloc((size_t)n * 4 * sizeof *points);
	int *inside = malloc((size_t)n * sizeof *inside), *object = malloc((size_t)n * sizeof *object);
	int m = 0;
	for (int i = 0; i < n; i++) {
		int obj = (int)(uniform() * ts->sc.n_objects) % ts->sc.n_objects;
		if (prim[obj] < 0)
			continue;
		double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
		shape_of(&ts->sc.objects[obj])->bounds(&ts->sc, &ts->sc.objects[obj], lo, hi);
		for (int k = 0; k < 3; k++) {   /* the object's box and a margin about it */
			double a = fmax(lo[k], ts->lo[k]), b = fmin(hi[k], ts->hi[k]), e = 0.2 * (b - a);
			points[4 * m + k] = (float)between(a - e, b + e);
		}
		memcpy(&points[4 * m + 3], &prim[obj], sizeof(int));
		object[m++] = obj;
	}
	if (m && inside_points(ds, points, m, inside)) {
		failures++;
		m = 0;
	}
	for (int i = 0; i < m; i++) {
		double p[3] = { points[4 * i], points[4 * i + 1], points[4 * i + 2] };
		bool host = inside_object(ts, object[i], p);
		tl->points++;
		tl->inside += inside[i];
		if (host == (inside[i] != 0))
			continue;
		double delta = rounding(p, 0);
		bool near = false;
		for (int k = 0; k < 6 && !near; k++) {
			double q[3] = { p[0], p[1], p[2] };
			q[k / 2] += k % 2 ? delta : -delta;
			near = inside_object(ts, object[i], q) == (inside[i] != 0);
		}
		if (near) {
			tl->point_edges++;
			continue;
		}
		if (tl->point_bad++ < 5) {
			fprintf(stderr, "  %s point <%.9g, %.9g, %.9g> of object %d: device %s, host %s\n", what, p[0], p[1],
			        p[2], object[i], inside[i] ? "inside" : "outside", host ? "inside" : "outside");
			dump_objects(ts, object[i], -1);
		}
	}
	free(points);
	free(inside);
	free(object);
}

/* ---- rays ---- */

static void set_ray(double *r, const double o[3], const double target[3])
{
	double d[3], len = 0;
	for (int k = 0; k < 3; k++) {
		d[k] = target[k] - o[k];
		len += d[k] * d[k];
	}
	for (int k = 0; k < 3; k++) {
		r[k] = o[k];
		r[3 + k] = d[k] / sqrt(len);
	}
}

static void point_in(const struct test_scene *ts, double p[3], double margin)
{
	for (int k = 0; k < 3; k++) {
		double e = margin * (ts->hi[k] - ts->lo[k]);
		p[k] = between(ts->lo[k] - e, ts->hi[k] + e);
	}
}

/* An origin around the scene: on a sphere about its box, or (inner) inside it. */
static void origin(const struct test_scene *ts, double o[3], int inner)
{
	if (inner) {
		point_in(ts, o, 0);
		return;
	}
	double c[3], r = 0, dir[3];
	for (int k = 0; k < 3; k++) {
		c[k] = (ts->lo[k] + ts->hi[k]) / 2;
		r += (ts->hi[k] - ts->lo[k]) * (ts->hi[k] - ts->lo[k]);
	}
	random_direction(dir);
	for (int k = 0; k < 3; k++)
		o[k] = c[k] + (0.6 + uniform()) * sqrt(r) * dir[k];
}

/* Random rays: from around the scene toward points of its box, and from inside
 * it; half of them aimed at a point of a surface the host found. */
static int random_rays(const struct test_scene *ts, double *rd, int n)
{
	for (int i = 0; i < n; i++) {
		double o[3], target[3];
		origin(ts, o, i % 4 == 3);
		point_in(ts, target, 0.1);
		set_ray(rd + 6 * i, o, target);
		if (i % 2) {   /* through a surface point, from elsewhere */
			struct answer a = trace_scene(ts, rd + 6 * i, rd + 6 * i + 3);
			if (a.object >= 0) {
				for (int k = 0; k < 3; k++)
					target[k] = rd[6 * i + k] + a.t * rd[6 * i + 3 + k];
				origin(ts, o, i % 8 == 7);
				set_ray(rd + 6 * i, o, target);
			}
		}
	}
	return n;
}

/* Whether the host's answers for two rays differ: hit and miss, other objects,
 * a jump in distance or a turn of the normal (an edge between two faces). */
static bool differ(const struct answer *a, const struct answer *b)
{
	if (a->object != b->object)
		return true;
	if (a->object < 0)
		return false;
	double c = a->n[0] * b->n[0] + a->n[1] * b->n[1] + a->n[2] * b->n[2];
	return fabs(a->t - b->t) > 1e-3 * fmax(1, a->t) || c < 0.99;
}

/* Rays on the host's edges: from one origin toward two points whose answers
 * differ, the target bisected until the two are 1e-13 apart. Four rays an
 * edge: both last ones, which the device may answer either way, and one on
 * each side a little farther out than rounding reaches (2 delta, along the
 * line of the first two targets), which it must answer as the host: a shape
 * whose edge the device draws too far in or out fails there. */
static int edge_rays(const struct test_scene *ts, double *rd, int n)
{
	int m = 0, tries = 0;
	while (m + 4 <= n && tries++ < 50 * n) {
		double o[3], a[3], b[3], ra[6], rb[6], u[3], ul = 0;
		origin(ts, o, tries % 4 == 0);
		point_in(ts, a, 0.1);
		point_in(ts, b, 0.1);
		set_ray(ra, o, a);
		set_ray(rb, o, b);
		struct answer ha = trace_scene(ts, ra, ra + 3), hb = trace_scene(ts, rb, rb + 3);
		if (!differ(&ha, &hb))
			continue;
		for (int k = 0; k < 3; k++) {
			u[k] = b[k] - a[k];
			ul += u[k] * u[k];
		}
		for (int it = 0; it < 60; it++) {
			double mid[3], rm[6], gap = 0;
			for (int k = 0; k < 3; k++) {
				mid[k] = (a[k] + b[k]) / 2;
				gap = fmax(gap, fabs(a[k] - b[k]));
			}
			if (gap < 1e-13 * (1 + fabs(mid[0]) + fabs(mid[1]) + fabs(mid[2])))
				break;
			set_ray(rm, o, mid);
			struct answer hm = trace_scene(ts, rm, rm + 3);
			if (differ(&ha, &hm))
				memcpy(b, mid, sizeof b), hb = hm;
			else
				memcpy(a, mid, sizeof a), ha = hm;
		}
		double dist = sqrt((a[0] - o[0]) * (a[0] - o[0]) + (a[1] - o[1]) * (a[1] - o[1]) +
		                   (a[2] - o[2]) * (a[2] - o[2]));
		double out = 2 * rounding(o, dist) / sqrt(ul), a2[3], b2[3];
		for (int k = 0; k < 3; k++) {
			a2[k] = a[k] - out * u[k];
			b2[k] = b[k] + out * u[k];
		}
		set_ray(rd + 6 * m++, o, a);
		set_ray(rd + 6 * m++, o, b);
		set_ray(rd + 6 * m++, o, a2);
		set_ray(rd + 6 * m++, o, b2);
	}
	return m;
}

/* ---- the test of one shape ---- */

static void test_shape(device_ctx *dev, cl_program prog, const struct maker *m, int scenes, int n_rays,
                       int n_points)
{
	scene_shape kind;
	if (!shape_named(m->name, &kind)) {
		printf("FAIL: %s is not a shape of the table\n", m->name);
		failures++;
		return;
	}
	/* each shape's own numbers, whatever the others are or whether they run */
	rng_state = seed;
	for (const char *c = m->name; *c; c++)
		rng_state = (rng_state ^ (unsigned char)*c) * 0x100000001b3ull;
	struct tally random = { 0 }, edges = { 0 };
	double *rd = malloc((size_t)n_rays * 6 * sizeof *rd);
	for (int s = 0; s < scenes; s++) {
		struct test_scene ts;
		make_scene(&ts, m, kind, s % 4 == 3);
		struct device_scene ds = { .dev = dev, .prog = prog };
		lower_options lo = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_DEFAULT, 0, 0, 0, NULL };
		if (lower_scene(&ts.sc, &lo, &ds.lr)) {
			printf("FAIL: %s: a scene does not lower\n", m->name);
			failures++;
			scene_free(&ts.sc);
			continue;
		}
		char what[64];
		snprintf(what, sizeof what, "%s, scene %d", m->name, s);
		compare_rays(what, &ds, &ts, rd, random_rays(&ts, rd, n_rays), &random);
		compare_rays(what, &ds, &ts, rd, edge_rays(&ts, rd, n_rays / 2), &edges);
		compare_points(what, &ds, &ts, n_points, &random);
		lower_free(&ds.lr);
		scene_free(&ts.sc);
	}
	free(rd);
	int ok = random.bad == 0 && random.any_bad == 0 && edges.bad == 0 && edges.any_bad == 0 && random.point_bad == 0;
	printf("%s: %s: %d random rays (%d hits, %d at an edge within rounding), %d rays on edges (%d hits, %d "
	       "either way), %d points (%d inside, %d at the surface within rounding); %d, %d and %d disagree, "
	       "%d any-hit errors\n",
	       ok ? "ok" : "FAIL", m->name, random.rays, random.hits, random.edges, edges.rays, edges.hits, edges.edges,
	       random.points, random.inside, random.point_edges, random.bad, edges.bad, random.point_bad,
	       random.any_bad + edges.any_bad);
	failures += !ok;
}

int main(int argc, char **argv)
{
	int n = sizeof makers / sizeof makers[0], scenes = 24, first = 1;
	for (; first + 1 < argc && argv[first][0] == '-'; first += 2) {
		if (strcmp(argv[first], "-n") == 0)
			scenes = atoi(argv[first + 1]);
		else if (strcmp(argv[first], "-s") == 0)
			seed = strtoull(argv[first + 1], NULL, 0);
		else
			break;
	}
	if (first < argc && argv[first][0] == '-') {
		fprintf(stderr, "usage: test_shapes [-n SCENES] [-s SEED] [SHAPE...]\n");
		return 2;
	}
	for (int i = first; i < argc; i++) {
		int found = 0;
		for (int k = 0; k < n; k++)
			found |= strcmp(argv[i], makers[k].name) == 0;
		if (!found) {
			fprintf(stderr, "test_shapes: no maker for '%s'\n", argv[i]);
			return 2;
		}
	}
	/* every shape of the table has a maker, but a mesh (test_traverse's), a
	 * smooth triangle (a triangle here), and the shapes whose arguments are
	 * lists, which property tests of their own cover with the same rules:
	 * tests/test_prism.c, test_revolve.c, test_torus.c and test_sweep.c (the
	 * sphere_sweep), and the isosurface,
	 * whose function is compiled into the kernels: tests/test_function.c; a
	 * height field, a bicubic patch and a parametric are meshes (test_traverse),
	 * their triangles POV-Ray's in tests/povray/height_field.scn,
	 * bicubic_patch.scn and parametric.scn;
	 * a julia_fractal's marching is chaotic where a ray grazes a thin part (a
	 * float ray's last bits decide which part a step lands in), so it is held
	 * to POV-Ray's images in tests/povray/julia_fractal.scn instead */
	static const char *const elsewhere[] = { "polygon", "prism", "text", "quadric", "sor", "lathe", "torus",
	                                         "superellipsoid", "isosurface", "height_field",
	                                         "bicubic_patch", "julia_fractal", "sphere_sweep", "parametric" };
	for (int s = 0; s < SHAPE_KINDS; s++) {
		scene_object o = { .shape = (scene_shape)s };
		const char *name = shape_of(&o)->name;
		int found = s == SHAPE_MESH || s == SHAPE_SMOOTH_TRIANGLE;
		for (size_t k = 0; k < sizeof elsewhere / sizeof *elsewhere; k++)
			found |= strcmp(name, elsewhere[k]) == 0;
		for (int k = 0; k < n; k++)
			found |= strcmp(name, makers[k].name) == 0;
		if (!found) {
			printf("FAIL: %s has no maker in tests/test_shapes.c\n", name);
			failures++;
		}
	}
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	printf("device: %s\n", dev.name);
	lower_result probe = { .layout = LOWER_LAYOUT_DEFAULT };
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&probe), NULL);
	if (!prog)
		return 1;
	for (int k = 0; k < n; k++) {
		int chosen = first == argc;
		for (int i = first; i < argc; i++)
			chosen |= strcmp(argv[i], makers[k].name) == 0;
		if (chosen)
			test_shape(&dev, prog, &makers[k], scenes, 4000, 4000);
	}
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all shape checks passed");
	return failures ? 1 : 0;
}
