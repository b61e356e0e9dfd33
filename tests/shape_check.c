/* shape_check.c: one shape on the device against its host class, and its
 * host class against brute force (shape_check.h). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shape_check.h"

static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize3(double v[3])
{
	double l = sqrt(dot3(v, v));
	for (int k = 0; k < 3; k++)
		v[k] = l > 0 ? v[k] / l : 0;
}

void check_case_init(check_case *c, const scene *s, const scene_object *o)
{
	c->sh = (cast_shape){ .s = s, .o = o };
	if (lower_invert(&o->xf, &c->sh.inv))
		abort();
	for (int k = 0; k < 3; k++)
		c->lo[k] = INFINITY, c->hi[k] = -INFINITY;
	shape_of(o)->bounds(s, o, c->lo, c->hi);
	c->r = 0;
	for (int k = 0; k < 3; k++) {
		c->c[k] = (c->lo[k] + c->hi[k]) / 2;
		c->r += (c->hi[k] - c->lo[k]) * (c->hi[k] - c->lo[k]) / 4;
	}
	c->r = sqrt(c->r);
}

/* ---- the host ---- */

struct host_hit {
	double t;        /* INFINITY: none */
	double n[3];     /* unit, world space */
};

/* trace() as eval_trace.c calls it: in object space, the ray keeping its parameter. */
static struct host_hit host_trace(const check_case *c, const double ro[3], const double rd[3])
{
	double n[3];
	struct host_hit r = { cast_trace(&c->sh, ro, rd, n), { 0, 0, 0 } };
	if (r.t < INFINITY) {
		const xform *inv = &c->sh.inv;
		for (int k = 0; k < 3; k++)
			r.n[k] = inv->m[0][k] * n[0] + inv->m[1][k] * n[1] + inv->m[2][k] * n[2];
		normalize3(r.n);
	}
	return r;
}

static bool host_inside(const check_case *c, const double p[3])
{
	double lp[3];
	scene_xform_point(&c->sh.inv, p, lp);
	return shape_of(c->sh.o)->inside(c->sh.s, c->sh.o, lp);
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

enum { RAYS_AROUND, RAYS_INSIDE, RAYS_GRAZING, RAYS_OWN, N_RAY_KINDS };
static const char *const kind_names[RAYS_OWN] = {
	"from around toward its box", "from inside its box", "grazing its surface",
};

/* n rays of a kind (origin, w: tmax; direction), in world space, as floats. */
static float *make_rays(const check_case *c, int kind, const check_kind *own, int n)
{
	float *rays = malloc((size_t)n * 8 * sizeof *rays);
	for (int i = 0; i < n; i++) {
		double org[3], d[3], u[3], target[3];
		cast_random_unit(u);
		for (int tries = 0;; tries++) {
			if (kind == RAYS_INSIDE) {
				for (int k = 0; k < 3; k++)
					org[k] = c->lo[k] + cast_uniform() * (c->hi[k] - c->lo[k]);
				cast_random_unit(d);
				break;
			}
			for (int k = 0; k < 3; k++)
				org[k] = c->c[k] + 2 * c->r * u[k];
			if (kind == RAYS_OWN) {
				own->aim(c, i, org, d, own->arg);
			} else {
				for (int k = 0; k < 3; k++) {
					target[k] = c->lo[k] + cast_uniform() * (c->hi[k] - c->lo[k]);
					d[k] = target[k] - org[k];
				}
			}
			normalize3(d);
			if (kind != RAYS_GRAZING)
				break;
			/* a point of the surface, then along it, a little inside or outside */
			struct host_hit h = host_trace(c, org, d);
			if (h.t == INFINITY) {
				cast_random_unit(u);
				continue;
			}
			double x[3], tan[3], a[3];
			for (int k = 0; k < 3; k++)
				x[k] = org[k] + h.t * d[k];
			cast_random_unit(a);
			tan[0] = a[1] * h.n[2] - a[2] * h.n[1];
			tan[1] = a[2] * h.n[0] - a[0] * h.n[2];
			tan[2] = a[0] * h.n[1] - a[1] * h.n[0];
			normalize3(tan);
			double off = c->r * 1e-3 * (2 * cast_uniform() - 1) * (i % 3 == 0 ? 1e-3 : 1);
			for (int k = 0; k < 3; k++) {
				d[k] = tan[k];
				org[k] = x[k] + off * h.n[k] - 2 * c->r * tan[k];
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

static void compare(const check_case *c, const float *rays, const struct dev_hit *dh, int n, struct tally *ty,
                    const char *what)
{
	for (int i = 0; i < n; i++) {
		double org[3] = { rays[8 * i], rays[8 * i + 1], rays[8 * i + 2] };
		double d[3] = { rays[8 * i + 4], rays[8 * i + 5], rays[8 * i + 6] };
		struct host_hit h = host_trace(c, org, d);
		ty->n++;
		ty->hits += h.t < INFINITY;
		ty->any_bad += dh[i].any != dh[i].hit;
		if (!same_hit(&h, &dh[i])) {
			double delta = rounding(org, h.t < INFINITY ? h.t : dh[i].t), p[3];
			bool ok = false;
			for (int w = 0; w < 4 && !ok; w++) {
				nudge(org, d, delta, w, p);
				struct host_hit hn = host_trace(c, p, d);
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
		bool in = host_inside(c, org);
		if (in != (dh[i].inside != 0)) {
			double delta = rounding(org, 0), p[3];
			bool ok = false;
			for (int k = 0; k < 6 && !ok; k++) {
				memcpy(p, org, sizeof p);
				p[k / 2] += k % 2 ? -delta : delta;
				ok = host_inside(c, p) != in;
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
static int brute_force(const check_case *c, const float *rays, int n, bool spindle, const char *what)
{
	int bad = 0;
	const int samples = 4000;
	for (int i = 0; i < n; i++) {
		double org[3] = { rays[8 * i], rays[8 * i + 1], rays[8 * i + 2] };
		double d[3] = { rays[8 * i + 4], rays[8 * i + 5], rays[8 * i + 6] }, p[3];
		struct host_hit h = host_trace(c, org, d);
		/* the ray across the box: from its origin to 4 r beyond */
		double t_end = 4 * c->r + sqrt(dot3((double[3]){ org[0] - c->c[0], org[1] - c->c[1], org[2] - c->c[2] },
		                                    (double[3]){ org[0] - c->c[0], org[1] - c->c[1], org[2] - c->c[2] }));
		double step = t_end / samples, cross = INFINITY;
		bool prev = host_inside(c, org);
		for (int s = 1; s <= samples && cross == INFINITY; s++) {
			for (int k = 0; k < 3; k++)
				p[k] = org[k] + s * step * d[k];
			bool in = host_inside(c, p);
			if (in != prev) {
				double lo = (s - 1) * step, hi = s * step;
				for (int it = 0; it < 60; it++) {
					double m = 0.5 * (lo + hi);
					for (int k = 0; k < 3; k++)
						p[k] = org[k] + m * d[k];
					if (host_inside(c, p) == prev)
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
				ok = host_inside(c, p) != host_inside(c, q);
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

/* ---- a shape ---- */

cl_program check_start(device_ctx *dev)
{
	if (device_open(dev, -1))
		return NULL;
	char ext[4096] = "";
	clGetDeviceInfo(dev->device, CL_DEVICE_EXTENSIONS, sizeof ext - 1, ext, NULL);
	bool fp64 = strstr(ext, "cl_khr_fp64") != NULL;
	if (!fp64)
		rounding_eps = 16 * FLT_EPSILON;
	printf("device: %s, %s\n", dev->name, fp64 ? "roots in double" : "no double: roots in float");
	lower_result probe = { .layout = LOWER_LAYOUT_DEFAULT };
	return device_build(dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&probe), NULL);
}

int check_shape(device_ctx *dev, cl_program prog, const lower_result *lr, const check_case *c, const char *name,
                const check_kind *own, bool spindle, int n_rays)
{
	int failures = 0;
	for (int kind = 0; kind < N_RAY_KINDS; kind++) {
		int n = kind == RAYS_GRAZING || kind == RAYS_OWN ? n_rays / 2 : n_rays;
		float *rays = make_rays(c, kind, own, n);
		struct dev_hit *dh = malloc((size_t)n * sizeof *dh);
		struct tally ty = { 0 };
		char what[160];
		snprintf(what, sizeof what, "%s, %s", name, kind == RAYS_OWN ? own->name : kind_names[kind]);
		if (cast(dev, prog, lr, 0, rays, n, dh)) {
			failures++;
		} else {
			compare(c, rays, dh, n, &ty, what);
			bool ok = ty.bad == 0 && ty.any_bad == 0 && ty.inside_bad == 0;
			printf("%s: %s: %d rays, %d hits; %d disagreements (%d within rounding), %d any-hit errors, "
			       "%d inside disagreements (%d within rounding)\n", ok ? "ok" : "FAIL", what, ty.n, ty.hits,
			       ty.bad + ty.excused, ty.excused, ty.any_bad, ty.inside_bad + ty.inside_excused, ty.inside_excused);
			failures += !ok;
			int nb = n < 400 ? n : 400;
			int bf = brute_force(c, rays, nb, spindle, what);
			printf("%s: %s: trace() against the sampled inside test on %d rays: %d disagreements\n",
			       bf ? "FAIL" : "ok", what, nb, bf);
			failures += bf != 0;
		}
		free(rays);
		free(dh);
	}
	return failures;
}
