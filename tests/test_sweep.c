/* test_sweep.c: the sphere_sweep on the device (through eclat's lowering
 * and kernels/raycast.cl's shapecast) against its host class
 * (src/shape_sphere_sweep.c: trace() and the inside test, in double), and
 * the host's trace() against brute force.
 *
 *   test_sweep [RAYS]
 *
 * Each case is one sweep (linear, cubic_spline, b_spline; thin and fat, a
 * radius growing faster than its centre moves, a sphere inside the next, a
 * curve that doubles back through itself), transformed, one far from the
 * origin; its rays come from around it toward its box, from inside its box,
 * along its surface (grazing its silhouette, just inside or outside), and at
 * the joints between its segments (toward points near a modelling sphere's
 * surface where two segments meet). A ray's closest hit must agree with the
 * host's (hit or miss, the distance to 1e-4, the normal to 0.999), any-hit
 * with closest-hit, and the inside test at its origin with the host's; a
 * disagreement passes only where the host itself answers otherwise for a ray
 * within rounding of it (2 float epsilons of its coordinates away, 16 on a
 * device without double). The host's nearest hit is held to brute force: the
 * inside test sampled densely along the ray. */
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
#include "sweep.h"

static int failures;
static const scene *cur;   /* the case's scene, which the sweep's spheres are in */
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
	shape_of(o)->trace(cur, o, lo, ld, 0, &h);
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
	return shape_of(o)->inside(cur, o, lp);
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

enum { RAYS_AROUND, RAYS_INSIDE, RAYS_GRAZING, RAYS_JOINT, N_RAY_KINDS };
static const char *const kind_names[N_RAY_KINDS] = {
	"from around toward its box", "from inside its box", "grazing its surface", "at its joints",
};

/* The modelling spheres the joints' rays aim at, in world space. */
static double (*joints)[4];
static int n_joints;

struct box {
	double lo[3], hi[3], c[3], r;   /* r: half the diagonal */
};

/* n rays of a kind (origin, w: tmax; direction), in world space, as floats. */
static float *make_rays(const scene_object *o, const xform *inv, const struct box *b, int kind, int n)
{
	float *rays = malloc((size_t)n * 8 * sizeof *rays);
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
				target[k] = b->lo[k] + cast_uniform() * (b->hi[k] - b->lo[k]);
				d[k] = target[k] - org[k];
			}
			if (kind == RAYS_JOINT) {   /* near a joint sphere's surface */
				const double *j = joints[i % n_joints];
				double v[3], s = j[3] * (1 + 0.02 * (2 * cast_uniform() - 1));
				unit_vector(v);
				for (int k = 0; k < 3; k++)
					d[k] = j[k] + s * v[k] - org[k];
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
                       const char *what)
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
			 * step, or a touch) */
			ok = fabs(dot3(h.n, d)) < 0.2;
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
	int kind, n;
	const double (*sp)[4];
	double rot[3], sc[3], mv[3];
};

static scene_object make(scene *sc, const struct shape_case *c)
{
	scene_object o = { .shape = SHAPE_SPHERE_SWEEP, .xf = scene_xform_identity(),
	                   .material = scene_default_material(), .mesh = -1, .loc = SRC_NOWHERE };
	scene_outline ol = { .edge = malloc((size_t)c->n * sizeof *ol.edge), .n_edges = c->n };
	memcpy(ol.edge, c->sp, (size_t)c->n * sizeof *ol.edge);
	o.outline = scene_add_outline(sc, &ol);
	o.param[0] = c->kind;
	o.param[1] = 1e-6;
	xform r = scene_xform_rotate(c->rot), s = scene_xform_scale(c->sc), t = scene_xform_translate(c->mv);
	o.xf = scene_xform_then(&s, &r);
	o.xf = scene_xform_then(&o.xf, &t);
	return o;
}

static void test_case(device_ctx *dev, cl_program prog, const struct shape_case *c, int n_rays)
{
	scene sc;
	scene_init(&sc);
	scene_object made = make(&sc, c);
	scene_add_object(&sc, &made);
	cur = &sc;
	lower_result lr;
	lower_options opt = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_DEFAULT, 0, 0, 0, NULL };
	if (lower_scene(&sc, &opt, &lr) || lr.n_prims < 1) {
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
	/* the joints: the ends of the segments (the spheres at u = 0 and 1) */
	int nseg = sweep_segments(&sc, o);
	n_joints = nseg + 1;
	joints = malloc((size_t)n_joints * sizeof *joints);
	for (int j = 0; j < n_joints; j++) {
		sweep_seg g;
		sweep_segment(&sc, o, j < nseg ? j : nseg - 1, &g);
		double p[4];
		for (int q = 0; q < 4; q++)
			p[q] = j < nseg ? g.c[0][q] : g.c[0][q] + g.c[1][q] + g.c[2][q] + g.c[3][q];
		scene_xform_point(&o->xf, p, joints[j]);
		double ax[3] = { p[3], 0, 0 }, w[3];   /* the radius, roughly, in world space */
		scene_xform_vector(&o->xf, ax, w);
		joints[j][3] = sqrt(dot3(w, w));
	}
	for (int kind = 0; kind < N_RAY_KINDS; kind++) {
		int n = kind == RAYS_GRAZING || kind == RAYS_JOINT ? n_rays / 2 : n_rays;
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
			int bf = brute_force(o, &inv, &b, rays, nb, what);
			printf("%s: %s: trace() against the sampled inside test on %d rays: %d disagreements\n",
			       bf ? "FAIL" : "ok", what, nb, bf);
			failures += bf != 0;
		}
		free(rays);
		free(dh);
	}
	free(joints);
	lower_free(&lr);
	scene_free(&sc);
}

int main(int argc, char **argv)
{
	int n_rays = argc > 1 ? atoi(argv[1]) : 2000;
	if (n_rays <= 0) {
		fprintf(stderr, "usage: test_sweep [RAYS]\n");
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
	static const double zigzag[][4] = {
		{ -2, 0, 0, 0.3 }, { -0.5, 1, 0.5, 0.6 }, { 0.8, 0, -0.3, 0.2 }, { 2, 0.8, 0.4, 0.5 },
	};
	static const double wave[][4] = {
		{ -3, -0.5, 0, 0.3 }, { -2, 0, 0, 0.3 }, { -0.5, 1, 0.5, 0.6 }, { 0.8, 0, -0.3, 0.2 },
		{ 2, 0.8, 0.4, 0.5 }, { 3, 0, 0, 0.2 },
	};
	static const double thin[][4] = {
		{ 0, 0, 0, 0.02 }, { 1, 0, 0, 0.05 }, { 1, 1, 0, 0.01 }, { 0, 1, 1, 0.04 }, { 0, 0, 1, 0.03 },
	};
	/* a sphere that swallows the next, and a radius growing faster than the centre moves */
	static const double swallow[][4] = { { 0, 0, 0, 1 }, { 0.3, 0, 0, 0.2 }, { 1.5, 0.2, 0, 0.9 }, { 1.6, 0, 0, 0.1 } };
	/* a loop through itself, fat (the envelope folds) */
	static const double loop[][4] = {
		{ -1, -1, 0, 0.3 }, { 0, 0, 0, 0.5 }, { 1, 1, 0.2, 0.4 }, { 1, -0.5, 0.1, 0.6 }, { 0, 0.8, -0.1, 0.5 },
		{ -1, 1, 0, 0.3 }, { -1.2, -1, 0.3, 0.4 },
	};
	/* a helix of many segments, which lowering splits among several primitives */
	static double helix[40][4];
	for (int i = 0; i < 40; i++) {
		helix[i][0] = cos(i * 0.5), helix[i][1] = -1 + i * 0.05, helix[i][2] = sin(i * 0.5);
		helix[i][3] = 0.12 + 0.05 * sin(i * 0.7);
	}
	const double none[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 }, tilt[3] = { 30, 40, 50 };
	const double uneven[3] = { 1.5, 0.6, 1 }, far[3] = { 3000.3, -1700.7, 2900.1 }, big[3] = { 40, 40, 40 };
	const double near[3] = { 0.3, -0.2, 0.5 };
#define CASE(name, kind, sp, rot, sc, mv) \
	{ name, kind, (int)(sizeof sp / sizeof sp[0]), sp, { rot[0], rot[1], rot[2] }, { sc[0], sc[1], sc[2] }, \
	  { mv[0], mv[1], mv[2] } }
	struct shape_case cases[] = {
		CASE("linear zigzag", SWEEP_LINEAR, zigzag, none, one, none),
		CASE("linear zigzag, turned, scaled unevenly", SWEEP_LINEAR, zigzag, tilt, uneven, near),
		CASE("linear, a sphere inside the next", SWEEP_LINEAR, swallow, tilt, one, near),
		CASE("linear thin", SWEEP_LINEAR, thin, tilt, one, none),
		CASE("cubic_spline wave", SWEEP_CUBIC, wave, none, one, none),
		CASE("cubic_spline wave, turned, scaled unevenly", SWEEP_CUBIC, wave, tilt, uneven, near),
		CASE("cubic_spline thin", SWEEP_CUBIC, thin, tilt, one, near),
		CASE("cubic_spline fat loop", SWEEP_CUBIC, loop, tilt, one, none),
		CASE("cubic_spline, radius outgrowing the centre", SWEEP_CUBIC, swallow, none, one, near),
		CASE("b_spline wave", SWEEP_B_SPLINE, wave, tilt, one, none),
		CASE("b_spline fat loop, scaled unevenly", SWEEP_B_SPLINE, loop, tilt, uneven, near),
		CASE("b_spline thin", SWEEP_B_SPLINE, thin, none, one, none),
		CASE("b_spline wave, scaled 40 and 4000 units away", SWEEP_B_SPLINE, wave, tilt, big, far),
		CASE("linear helix of 39 segments", SWEEP_LINEAR, helix, tilt, one, near),
		CASE("cubic_spline helix of 37 segments, scaled unevenly", SWEEP_CUBIC, helix, tilt, uneven, none),
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		test_case(&dev, prog, &cases[i], n_rays);
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all sphere_sweep checks passed");
	return failures ? 1 : 0;
}
