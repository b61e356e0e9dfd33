/* test_torus.c: the torus and the superellipsoid on the device (through
 * eclat's lowering and kernels/raycast.cl's shapecast) against their host
 * classes (src/shape_torus.c, src/shape_superellipsoid.c: trace() and the
 * inside test, in double), and the host's trace() against brute force.
 *
 *   test_torus [RAYS]
 *
 * Each case is one shape, thin and fat, transformed, far from the origin; its
 * rays come from around it toward its box, from inside its box in any
 * direction, along its surface (grazing it, just inside or outside), and
 * through its centre (a torus's hole, a spindle torus's tips). A ray's
 * closest hit must agree with the host's (hit or miss, the distance to 1e-4,
 * the normal to 0.999), any-hit with closest-hit, and the inside test at its
 * origin with the host's; a disagreement passes only where the host itself
 * answers otherwise for a ray within rounding of it (2 float epsilons of its
 * coordinates away, 16 on a device without double), which only grazing rays
 * and origins on the surface are.
 * The host's nearest hit is held to brute force: the inside test sampled
 * densely along the ray (no hit may come after a crossing it sees, and a hit
 * it does not see must be a grazing one or a spindle's inner surface, whose
 * sides are both inside). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cast.h"
#include "device.h"
#include "lower.h"
#include "shape.h"

static int failures;
static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void unit_vector(double v[3])
{
	double z = 2 * cast_uniform() - 1, phi = 2 * M_PI * cast_uniform(), s = sqrt(1 - z * z);
	v[0] = s * cos(phi), v[1] = s * sin(phi), v[2] = z;
}

static void normalize3(double v[3])
{
	double l = sqrt(dot3(v, v));
	for (int k = 0; k < 3; k++)
		v[k] = l > 0 ? v[k] / l : 0;
}

/* xform inverse (eval_xform_inverse's, without the evaluator) */
static xform inverse(const xform *t)
{
	xform inv;
	if (lower_invert(t, &inv))
		abort();
	return inv;
}

/* ---- the host ---- */

struct host_hit {
	double t;        /* INFINITY: none */
	double n[3];     /* unit, world space */
};

/* trace() as eval_trace.c calls it: in object space, the ray keeping its parameter. */
static struct host_hit host_trace(const scene_object *o, const xform *inv, const double ro[3], const double rd[3])
{
	double lo[3], ld[3];
	scene_xform_point(inv, ro, lo);
	scene_xform_vector(inv, rd, ld);
	shape_hit h = { .t = INFINITY };
	shape_of(o)->trace(NULL, o, lo, ld, 0, &h);
	struct host_hit r = { h.t, { 0, 0, 0 } };
	if (h.t < INFINITY) {
		for (int k = 0; k < 3; k++)
			r.n[k] = inv->m[0][k] * h.n[0] + inv->m[1][k] * h.n[1] + inv->m[2][k] * h.n[2];
		normalize3(r.n);
	}
	return r;
}

static bool host_inside(const scene_object *o, const xform *inv, const double p[3])
{
	double lp[3];
	scene_xform_point(inv, p, lp);
	return shape_of(o)->inside(NULL, o, lp);
}

/* ---- the device ---- */

struct dev_hit {
	float t, n[3];
	int hit, any, inside;
};

static int cast(device_ctx *dev, cl_program prog, const lower_result *lr, int shape, const float *rays, int n,
                struct dev_hit *out)
{
	float *res = malloc((size_t)n * 8 * sizeof *res);
	if (!res || cast_rays(dev, prog, "shapecast", lr, rays, n, res, 2, shape)) {
		free(res);
		return -1;
	}
	for (int i = 0; i < n; i++) {
		const float *r = res + 8 * i;
		int prim;
		memcpy(&prim, &r[1], sizeof prim);
		out[i] = (struct dev_hit){ prim >= 0 ? r[0] : INFINITY, { r[4], r[5], r[6] }, prim >= 0, r[2] > 0.5f,
		                           r[3] > 0.5f };
	}
	free(res);
	return 0;
}

/* ---- rays ---- */

enum { RAYS_AROUND, RAYS_INSIDE, RAYS_GRAZING, RAYS_CENTRE, N_RAY_KINDS };
static const char *const kind_names[N_RAY_KINDS] = {
	"from around toward its box", "from inside its box", "grazing its surface", "through its centre",
};

struct box {
	double lo[3], hi[3], c[3], r;   /* r: half the diagonal */
};

/* n rays of a kind (origin, w: tmax; direction), in world space, as floats. */
static float *make_rays(const scene_object *o, const xform *inv, const struct box *b, int kind, int n)
{
	float *rays = malloc((size_t)n * 8 * sizeof *rays);
	double centre[3], zero[3] = { 0, 0, 0 };
	scene_xform_point(&o->xf, zero, centre);
	for (int i = 0; i < n; i++) {
		double org[3], d[3], u[3], target[3];
		unit_vector(u);
		for (int tries = 0;; tries++) {
			if (kind == RAYS_INSIDE) {
				for (int k = 0; k < 3; k++)
					org[k] = b->lo[k] + cast_uniform() * (b->hi[k] - b->lo[k]);
				unit_vector(d);
				break;
			}
			for (int k = 0; k < 3; k++) {
				org[k] = b->c[k] + 2 * b->r * u[k];
				target[k] = kind == RAYS_CENTRE ? centre[k] + 0.05 * b->r * (2 * cast_uniform() - 1)
				                                : b->lo[k] + cast_uniform() * (b->hi[k] - b->lo[k]);
				d[k] = target[k] - org[k];
			}
			normalize3(d);
			if (kind != RAYS_GRAZING)
				break;
			/* a point of the surface, then along it, a little inside or outside */
			struct host_hit h = host_trace(o, inv, org, d);
			if (h.t == INFINITY) {
				unit_vector(u);
				continue;
			}
			double x[3], tan[3], a[3];
			for (int k = 0; k < 3; k++)
				x[k] = org[k] + h.t * d[k];
			unit_vector(a);
			tan[0] = a[1] * h.n[2] - a[2] * h.n[1];
			tan[1] = a[2] * h.n[0] - a[0] * h.n[2];
			tan[2] = a[0] * h.n[1] - a[1] * h.n[0];
			normalize3(tan);
			double off = b->r * 1e-3 * (2 * cast_uniform() - 1) * (i % 3 == 0 ? 1e-3 : 1);
			for (int k = 0; k < 3; k++) {
				d[k] = tan[k];
				org[k] = x[k] + off * h.n[k] - 2 * b->r * tan[k];
			}
			break;
		}
		for (int k = 0; k < 3; k++) {
			rays[8 * i + k] = (float)org[k];
			rays[8 * i + 4 + k] = (float)d[k];
		}
		rays[8 * i + 3] = INFINITY;
		rays[8 * i + 7] = 0;
	}
	return rays;
}

/* ---- comparisons ---- */

static bool same_hit(const struct host_hit *h, const struct dev_hit *d)
{
	if ((h->t < INFINITY) != (d->hit != 0))
		return false;
	if (!d->hit)
		return true;
	double dn[3] = { d->n[0], d->n[1], d->n[2] };
	return fabs(d->t - h->t) <= 1e-4 * fmax(1.0, h->t) && dot3(dn, h->n) > 0.999;
}

/* The perturbations of a ray within rounding: its origin moved by delta
 * across it, four ways. */
static void nudge(const double o[3], const double d[3], double delta, int which, double out[3])
{
	double a[3], b[3];
	shape_frame(d, a, b);
	const double *v = which < 2 ? a : b;
	double s = which % 2 ? -delta : delta;
	for (int k = 0; k < 3; k++)
		out[k] = o[k] + s * v[k];
}

/* How far the device may move a ray by rounding, in float epsilons of its
 * coordinates: 2 where it solves in double (the rays and the maps to the
 * shapes' spaces are floats), which roots found in float overstep; 16
 * without double. */
static double rounding_eps = 2 * FLT_EPSILON;

static double rounding(const double o[3], double t)
{
	double m = fmax(fmax(fabs(o[0]), fabs(o[1])), fabs(o[2]));
	return rounding_eps * (m + (isfinite(t) ? t : 0));
}

struct tally {
	int n, hits, bad, excused, any_bad, inside_bad, inside_excused;
};

static void compare(const scene_object *o, const xform *inv, const float *rays, const struct dev_hit *dh, int n,
                    struct tally *ty, const char *what)
{
	for (int i = 0; i < n; i++) {
		double org[3] = { rays[8 * i], rays[8 * i + 1], rays[8 * i + 2] };
		double d[3] = { rays[8 * i + 4], rays[8 * i + 5], rays[8 * i + 6] };
		struct host_hit h = host_trace(o, inv, org, d);
		ty->n++;
		ty->hits += h.t < INFINITY;
		ty->any_bad += dh[i].any != dh[i].hit;
		if (!same_hit(&h, &dh[i])) {
			double delta = rounding(org, h.t < INFINITY ? h.t : dh[i].t), p[3];
			bool ok = false;
			for (int w = 0; w < 4 && !ok; w++) {
				nudge(org, d, delta, w, p);
				struct host_hit hn = host_trace(o, inv, p, d);
				ok = same_hit(&hn, &dh[i]) || (hn.t < INFINITY) != (h.t < INFINITY) ||
				     fabs(hn.t - h.t) > 1e-4 * fmax(1.0, h.t);
			}
			if (ok) {
				ty->excused++;
			} else if (ty->bad++ < 5) {
				fprintf(stderr, "  %s: ray <%.9g, %.9g, %.9g> + t <%.9g, %.9g, %.9g>: device t %.9g n <%.4f, %.4f, "
				        "%.4f>, host t %.9g n <%.4f, %.4f, %.4f>\n", what, org[0], org[1], org[2], d[0], d[1],
				        d[2], dh[i].t, dh[i].n[0], dh[i].n[1], dh[i].n[2], h.t, h.n[0], h.n[1], h.n[2]);
			}
		}
		bool in = host_inside(o, inv, org);
		if (in != (dh[i].inside != 0)) {
			double delta = rounding(org, 0), p[3];
			bool ok = false;
			for (int k = 0; k < 6 && !ok; k++) {
				memcpy(p, org, sizeof p);
				p[k / 2] += k % 2 ? -delta : delta;
				ok = host_inside(o, inv, p) != in;
			}
			if (ok)
				ty->inside_excused++;
			else if (ty->inside_bad++ < 5)
				fprintf(stderr, "  %s: point <%.9g, %.9g, %.9g>: device inside %d, host %d\n", what, org[0],
				        org[1], org[2], dh[i].inside, in);
		}
	}
}

/* The host's trace() against the inside test sampled along the ray: returns
 * the number of rays where they disagree. */
static int brute_force(const scene_object *o, const xform *inv, const struct box *b, const float *rays, int n,
                       bool spindle, const char *what)
{
	int bad = 0;
	const int samples = 4000;
	for (int i = 0; i < n; i++) {
		double org[3] = { rays[8 * i], rays[8 * i + 1], rays[8 * i + 2] };
		double d[3] = { rays[8 * i + 4], rays[8 * i + 5], rays[8 * i + 6] }, p[3];
		struct host_hit h = host_trace(o, inv, org, d);
		/* the ray across the box: from its origin to 4 r beyond */
		double t_end = 4 * b->r + sqrt(dot3((double[3]){ org[0] - b->c[0], org[1] - b->c[1], org[2] - b->c[2] },
		                                    (double[3]){ org[0] - b->c[0], org[1] - b->c[1], org[2] - b->c[2] }));
		double step = t_end / samples, cross = INFINITY;
		bool prev = host_inside(o, inv, org);
		for (int s = 1; s <= samples && cross == INFINITY; s++) {
			for (int k = 0; k < 3; k++)
				p[k] = org[k] + s * step * d[k];
			bool in = host_inside(o, inv, p);
			if (in != prev) {
				double lo = (s - 1) * step, hi = s * step;
				for (int it = 0; it < 60; it++) {
					double m = 0.5 * (lo + hi);
					for (int k = 0; k < 3; k++)
						p[k] = org[k] + m * d[k];
					if (host_inside(o, inv, p) == prev)
						lo = m;
					else
						hi = m;
				}
				cross = 0.5 * (lo + hi);
			}
		}
		bool ok;
		if (cross < INFINITY) {
			/* a crossing it sees: the host's hit is that one, or nearer */
			ok = h.t <= cross + 1e-6 * fmax(1.0, cross) || (h.t < INFINITY && fabs(dot3(h.n, d)) < 0.2);
			if (ok && h.t < cross - 1e-6 * fmax(1.0, cross))
				goto nearer;
		} else if (h.t < INFINITY) {
nearer:
			/* a hit the samples step over: grazing (two crossings within a
			 * step, or a touch), or a spindle's inner surface */
			ok = spindle || fabs(dot3(h.n, d)) < 0.2;
			if (!ok) {   /* or the inside changes across it after all */
				double q[3], eps = 1e-7 * fmax(1.0, h.t);
				for (int k = 0; k < 3; k++) {
					p[k] = org[k] + (h.t - eps) * d[k];
					q[k] = org[k] + (h.t + eps) * d[k];
				}
				ok = host_inside(o, inv, p) != host_inside(o, inv, q);
			}
		} else {
			ok = true;
		}
		if (!ok && bad++ < 5)
			fprintf(stderr, "  %s: ray <%.9g, %.9g, %.9g> + t <%.9g, %.9g, %.9g>: trace() t %.9g, brute force %.9g\n",
			        what, org[0], org[1], org[2], d[0], d[1], d[2], h.t, cross);
	}
	return bad;
}

/* ---- cases ---- */

struct shape_case {
	const char *name;
	scene_object o;
};

static scene_object make(scene_shape shape, double a, double b, const double rot[3], const double sc[3],
                         const double mv[3])
{
	scene_object o = { .shape = shape, .xf = scene_xform_identity(), .material = scene_default_material(),
	                   .mesh = -1, .loc = SRC_NOWHERE };
	if (shape == SHAPE_TORUS) {
		o.radius = a;
		o.param[0] = b;
	} else {
		o.p[0][0] = a;
		o.p[0][1] = b;
	}
	xform r = scene_xform_rotate(rot), s = scene_xform_scale(sc), t = scene_xform_translate(mv);
	o.xf = scene_xform_then(&s, &r);
	o.xf = scene_xform_then(&o.xf, &t);
	return o;
}

static void test_case(device_ctx *dev, cl_program prog, const struct shape_case *c, int n_rays)
{
	scene sc;
	scene_init(&sc);
	scene_add_object(&sc, &c->o);
	lower_result lr;
	lower_options opt = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_DEFAULT, 0, 0, 0, NULL };
	if (lower_scene(&sc, &opt, &lr) || lr.n_prims != 1) {
		printf("FAIL: %s: lowering made %d primitives\n", c->name, lr.n_prims);
		failures++;
		scene_free(&sc);
		return;
	}
	const scene_object *o = &sc.objects[0];
	xform inv = inverse(&o->xf);
	struct box b;
	for (int k = 0; k < 3; k++)
		b.lo[k] = INFINITY, b.hi[k] = -INFINITY;
	shape_of(o)->bounds(&sc, o, b.lo, b.hi);
	b.r = 0;
	for (int k = 0; k < 3; k++) {
		b.c[k] = (b.lo[k] + b.hi[k]) / 2;
		b.r += (b.hi[k] - b.lo[k]) * (b.hi[k] - b.lo[k]) / 4;
	}
	b.r = sqrt(b.r);
	bool spindle = o->shape == SHAPE_TORUS && o->param[0] > o->radius;
	for (int kind = 0; kind < N_RAY_KINDS; kind++) {
		int n = kind == RAYS_GRAZING || kind == RAYS_CENTRE ? n_rays / 2 : n_rays;
		float *rays = make_rays(o, &inv, &b, kind, n);
		struct dev_hit *dh = malloc((size_t)n * sizeof *dh);
		struct tally ty = { 0 };
		char what[160];
		snprintf(what, sizeof what, "%s, %s", c->name, kind_names[kind]);
		if (cast(dev, prog, &lr, 0, rays, n, dh)) {
			failures++;
		} else {
			compare(o, &inv, rays, dh, n, &ty, what);
			bool ok = ty.bad == 0 && ty.any_bad == 0 && ty.inside_bad == 0;
			printf("%s: %s: %d rays, %d hits; %d disagreements (%d within rounding), %d any-hit errors, "
			       "%d inside disagreements (%d within rounding)\n", ok ? "ok" : "FAIL", what, ty.n, ty.hits,
			       ty.bad + ty.excused, ty.excused, ty.any_bad, ty.inside_bad + ty.inside_excused, ty.inside_excused);
			failures += !ok;
			int nb = n < 400 ? n : 400;
			int bf = brute_force(o, &inv, &b, rays, nb, spindle, what);
			printf("%s: %s: trace() against the sampled inside test on %d rays: %d disagreements\n",
			       bf ? "FAIL" : "ok", what, nb, bf);
			failures += bf != 0;
		}
		free(rays);
		free(dh);
	}
	lower_free(&lr);
	scene_free(&sc);
}

int main(int argc, char **argv)
{
	int n_rays = argc > 1 ? atoi(argv[1]) : 4000;
	if (n_rays <= 0) {
		fprintf(stderr, "usage: test_torus [RAYS]\n");
		return 2;
	}
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	char ext[4096] = "";
	clGetDeviceInfo(dev.device, CL_DEVICE_EXTENSIONS, sizeof ext - 1, ext, NULL);
	bool fp64 = strstr(ext, "cl_khr_fp64") != NULL;
	if (!fp64)
		rounding_eps = 16 * FLT_EPSILON;
	printf("device: %s, %s\n", dev.name, fp64 ? "roots in double" : "no double: roots in float");
	lower_result probe = { .layout = LOWER_LAYOUT_DEFAULT };
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&probe), NULL);
	if (!prog)
		return 1;
	const double none[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 };
	const double tilt[3] = { 30, 40, 50 }, uneven[3] = { 1.5, 0.6, 1 }, far[3] = { 3000.3, -1700.7, 2900.1 };
	const double big[3] = { 40, 40, 40 }, near[3] = { 0.3, -0.2, 0.5 };
	struct shape_case cases[] = {
		{ "torus 1, 0.25", make(SHAPE_TORUS, 1, 0.25, none, one, none) },
		{ "thin torus 2, 0.02, turned", make(SHAPE_TORUS, 2, 0.02, tilt, one, near) },
		{ "torus 1, 0.4 scaled unevenly", make(SHAPE_TORUS, 1, 0.4, tilt, uneven, near) },
		{ "horn torus 0.5, 0.5", make(SHAPE_TORUS, 0.5, 0.5, tilt, one, none) },
		{ "spindle torus 0.6, 1", make(SHAPE_TORUS, 0.6, 1, tilt, one, near) },
		{ "torus 1, 0.3, scaled 40 and 4000 units away", make(SHAPE_TORUS, 1, 0.3, tilt, big, far) },
		{ "superellipsoid <1, 1> (a sphere)", make(SHAPE_SUPERELLIPSOID, 1, 1, none, one, none) },
		{ "superellipsoid <0.2, 0.3>, turned", make(SHAPE_SUPERELLIPSOID, 0.2, 0.3, tilt, one, near) },
		{ "superellipsoid <2.5, 0.5> scaled unevenly", make(SHAPE_SUPERELLIPSOID, 2.5, 0.5, tilt, uneven, near) },
		{ "superellipsoid <3, 3> (pinched)", make(SHAPE_SUPERELLIPSOID, 3, 3, tilt, one, none) },
		{ "superellipsoid <0.5, 2>, scaled 40 and 4000 units away",
		  make(SHAPE_SUPERELLIPSOID, 0.5, 2, tilt, big, far) },
		{ "superellipsoid <0, 0.7> (square sections)", make(SHAPE_SUPERELLIPSOID, 0, 0.7, tilt, one, near) },
		{ "superellipsoid <0.3, 0.7>", make(SHAPE_SUPERELLIPSOID, 0.3, 0.7, tilt, uneven, none) },
		{ "superellipsoid <2.5, 4> (pinched)", make(SHAPE_SUPERELLIPSOID, 2.5, 4, tilt, one, near) },
		{ "superellipsoid <0.5, 3>", make(SHAPE_SUPERELLIPSOID, 0.5, 3, tilt, one, none) },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		test_case(&dev, prog, &cases[i], n_rays);
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all torus and superellipsoid checks passed");
	return failures ? 1 : 0;
}
