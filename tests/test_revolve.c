/* test_revolve.c: quadric, sor and lathe on the device (kernels/shape_quadric.cl,
 * kernels/shape_sor.cl, through eclat's own lowering and kernels/raycast.cl)
 * against their host trace() in double precision (src/shape_quadric.c,
 * src/revolve.c), which is also POV-Ray's trace().
 *
 *   test_revolve [RAYS]
 *
 * As tests/test_prism.c: each shape is lowered alone and meets RAYS random
 * rays and RAYS rays aimed at its surface, its rims and caps. A ray must hit
 * where trace() says (within 1e-4 of the shape's size) or miss where it
 * misses; where they disagree, the ray must pass within 1e-4 of the size of a
 * boundary, and such rays must be rare. The host's own inside test is checked
 * against trace(): a point is inside when a ray from it crosses the surface an
 * odd number of times, and its normals point out. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cast.h"
#include "device.h"
#include "lower.h"
#include "revolve.h"

static int failures;
/* ---- the shapes ---- */

enum { QUADRIC_HYPER, QUADRIC_CONE, SOR_CLOSED, SOR_OPEN, LATHE_LINEAR, LATHE_CUP, LATHE_QUADRATIC, LATHE_CUBIC,
       LATHE_BEZIER, SHAPES };
static const char *const names[SHAPES] = {
	"quadric hyperboloid (turned)", "quadric cone (mixed terms, scaled)", "sor closed (turned)", "sor open",
	"lathe linear_spline", "lathe linear cup (turned)", "lathe quadratic_spline", "lathe cubic_spline",
	"lathe bezier_spline",
};

static scene_object make_shape(scene *s, int which)
{
	scene_object o = { .shape = SHAPE_LATHE, .xf = scene_xform_identity(), .material = scene_default_material(),
	                   .mesh = -1, .outline = -1, .loc = SRC_NOWHERE };
	static const double sor_pts[] = { 0, 0, 0.6, 0, 0.8, 0.5, 0.4, 1.2, 0.5, 1.6, 0.7, 2, 0.8, 2.2 };
	static const double goblet[] = { 0.3, -0.2, 0.3, 0, 0.1, 0.3, 0.1, 0.9, 0.6, 1.3, 0.8, 1.8, 0.9, 2, 1, 2.2 };
	static const double top[] = { 0, 0, 0.8, 0.7, 0.6, 1.1, 0.15, 1.3, 0, 1.8 };
	static const double cup[] = { 0, 0, 0.9, 0, 1, 1.4, 0.9, 1.4, 0.8, 0.15, 0, 0.15, 0, 0 };
	static const double quad[] = { 0, -0.2, 0, 0, 0.7, 0.3, 0.3, 1, 0.5, 1.6, 0, 2 };
	static const double cubic[] = { 0, -0.3, 0, 0, 0.8, 0.4, 0.4, 1, 0.7, 1.6, 0, 2, 0, 2.3 };
	static const double bez[] = { 0, 0, 1.2, 0, 0.2, 0.8, 0.5, 1, 0.5, 1, 0.9, 1.2, 0.6, 1.8, 0, 1.8 };
	const double *pts = NULL;
	int n = 0;
	switch (which) {
	case QUADRIC_HYPER:
		o.shape = SHAPE_QUADRIC;
		o.p[0][0] = 1, o.p[0][1] = -1, o.p[0][2] = 1, o.radius = -0.25;
		o.xf = scene_xform_rotate((double[3]){ 30, 20, -40 });
		return o;
	case QUADRIC_CONE:
		o.shape = SHAPE_QUADRIC;
		o.p[0][0] = 1, o.p[0][1] = -0.5, o.p[0][2] = 1, o.p[1][0] = 0.2, o.p[2][1] = 0.1;
		o.xf = scene_xform_scale((double[3]){ 1, 1.5, 0.7 });
		return o;
	case SOR_CLOSED: o.shape = SHAPE_SOR, pts = sor_pts, n = 7;
		o.xf = scene_xform_rotate((double[3]){ 10, -35, 25 });
		break;
	case SOR_OPEN: o.shape = SHAPE_SOR, pts = goblet, n = 8, o.shape_flags = SHAPE_OPEN; break;
	case LATHE_LINEAR: pts = top, n = 5; break;
	case LATHE_CUP: pts = cup, n = 7;
		o.xf = scene_xform_rotate((double[3]){ -25, 10, 0 });
		break;
	case LATHE_QUADRATIC: pts = quad, n = 6, o.param[0] = REVOLVE_QUADRATIC; break;
	case LATHE_CUBIC: pts = cubic, n = 7, o.param[0] = REVOLVE_CUBIC; break;
	case LATHE_BEZIER: pts = bez, n = 8, o.param[0] = REVOLVE_BEZIER; break;
	}
	scene_outline ol = { .edge = malloc(n * sizeof *ol.edge), .n_edges = n };
	for (int i = 0; i < n; i++) {
		ol.edge[i][0] = pts[2 * i], ol.edge[i][1] = pts[2 * i + 1];
		ol.edge[i][2] = ol.edge[i][3] = 0;
	}
	o.outline = scene_add_outline(s, &ol);
	return o;
}

/* ---- the host's answer in world space ---- */

/* ---- the device ---- */

/* ---- rays ---- */


/* A point of the surface to aim at, in object space: on a piece of a sor's
 * or lathe's profile (often at its ends, the rims), or where a random ray
 * from inside the box meets a quadric; true when it is on a rim. */
static bool surface_point(const scene *s, const scene_object *o, const revolve_profile *pr, double p[3])
{
	if (o->shape == SHAPE_QUADRIC) {
		double from[3], d[3], n[3];
		for (int k = 0; k < 3; k++)
			from[k] = 2 * cast_uniform() - 1;
		cast_random_unit(d);
		shape_hit h = { .t = INFINITY };
		shape_of(o)->trace(s, o, from, d, 0, &h);
		(void)n;
		for (int k = 0; k < 3; k++)
			p[k] = isfinite(h.t) && h.t < 3 ? from[k] + h.t * d[k] : from[k];
		return false;
	}
	const revolve_piece *q = &pr->piece[(int)(cast_uniform() * pr->n)];
	double a = 2 * M_PI * cast_uniform(), r, y;
	bool rim = cast_uniform() < 0.3;
	if (q->kind == REVOLVE_DISC) {
		double r2 = rim ? (cast_uniform() < 0.5 ? q->c[0] : q->c[1]) : q->c[0] + cast_uniform() * (q->c[1] - q->c[0]);
		r = sqrt(r2), y = q->h1;
	} else {
		y = rim ? (cast_uniform() < 0.5 ? q->h1 : q->h2) : q->h1 + cast_uniform() * (q->h2 - q->h1);
		double u = y - q->hc;
		r = sqrt(fmax(((q->c[0] * u + q->c[1]) * u + q->c[2]) * u + q->c[3], 0));
	}
	p[0] = r * cos(a), p[1] = y, p[2] = r * sin(a);
	return rim;
}

/* ---- one shape ---- */

static void test_shape(device_ctx *dev, cl_program prog, int which, int n_rays)
{
	scene s;
	scene_init(&s);
	scene_object o = make_shape(&s, which);
	scene_add_object(&s, &o);
	cast_shape sh = { .s = &s, .o = &s.objects[0] };
	lower_invert(&o.xf, &sh.inv);
	revolve_profile pr = { 0 };
	if (o.shape != SHAPE_QUADRIC)
		revolve_profile_of(&s, &o, &pr);
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, mid[3];
	if (o.shape == SHAPE_QUADRIC)   /* unbounded: the rays go through the cube around its centre */
		for (int k = 0; k < 3; k++)
			lo[k] = -1.2, hi[k] = 1.2;
	else
		shape_of(&o)->bounds(&s, &o, lo, hi);
	double size = 0;
	for (int k = 0; k < 3; k++) {
		mid[k] = (lo[k] + hi[k]) / 2;
		size = fmax(size, hi[k] - lo[k]);
	}
	lower_options opt = { LOWER_BVH_SAH, 24, LOWER_LAYOUT_BINARY, 0, 0, 0, NULL };
	lower_result lr;
	if (lower_scene(&s, &opt, &lr)) {
		printf("FAIL: %s: lowering failed\n", names[which]);
		failures++;
		scene_free(&s);
		return;
	}
	int n = 2 * n_rays;
	float *rays = malloc((size_t)n * 8 * sizeof *rays), *hits = malloc((size_t)n * 4 * sizeof *hits);
	bool *on_edge = calloc(n, sizeof *on_edge);
	xform to_world = o.xf;
	for (int i = 0; i < n; i++) {
		double from[3], to[3], d[3];
		cast_random_unit(d);
		for (int k = 0; k < 3; k++)
			from[k] = mid[k] + 2 * size * d[k];
		if (i < n_rays) {   /* random: toward a point of the box */
			for (int k = 0; k < 3; k++)
				to[k] = lo[k] + cast_uniform() * (hi[k] - lo[k]);
		} else {            /* aimed at the surface, its edges and corners */
			double p[3];
			on_edge[i] = surface_point(&s, &o, &pr, p);
			scene_xform_point(&to_world, p, to);
		}
		float *r = rays + 8 * i;
		for (int k = 0; k < 3; k++) {
			r[k] = (float)from[k];
			r[4 + k] = (float)(to[k] - from[k]);
		}
		r[3] = 1e30f;
		r[7] = 0;
	}
	if (cast_rays(dev, prog, "raycast", &lr, rays, n, hits, 1, -1)) {
		failures++;
		goto done;
	}
	int wrong = 0, near[2] = { 0, 0 }, hit_count = 0;
	double tol = 1e-4 * size;
	for (int i = 0; i < n; i++) {
		const float *r = rays + 8 * i;
		double wo[3] = { r[0], r[1], r[2] }, wd[3] = { r[4], r[5], r[6] };
		double len = sqrt(wd[0] * wd[0] + wd[1] * wd[1] + wd[2] * wd[2]);
		int prim;
		memcpy(&prim, &hits[4 * i + 1], sizeof prim);
		double hn[3], od[3];
		double td = prim >= 0 ? hits[4 * i] : INFINITY, th = cast_trace(&sh, wo, wd, hn);
		if (o.shape == SHAPE_QUADRIC) {   /* unbounded: only the hits in the cube the rays cross */
			td = td < 2 ? td : INFINITY;
			th = th < 2 ? th : INFINITY;
		}
		hit_count += isfinite(th);
		/* a grazing hit's distance moves by the float error over the angle's cosine */
		scene_xform_vector(&sh.inv, wd, od);
		double c = fabs(hn[0] * od[0] + hn[1] * od[1] + hn[2] * od[2]) /
		           sqrt((hn[0] * hn[0] + hn[1] * hn[1] + hn[2] * hn[2]) * (od[0] * od[0] + od[1] * od[1] + od[2] * od[2]));
		if ((isinf(td) && isinf(th)) || fabs(td - th) * len <= tol / fmax(isfinite(th) ? c : 1, 1e-3))
			continue;
		/* a ray passing within tol of a boundary: a jittered ray gives the
		 * device's answer, or misses the host's nearer hit while the device's
		 * is the host's next one */
		double u[3], w[3], dn[3] = { wd[0] / len, wd[1] / len, wd[2] / len }, eps = 4 * tol / len;
		shape_frame(dn, u, w);
		double next = th < td ? cast_trace_from(&sh, wo, wd, th + 2 * eps, NULL) : INFINITY;
		bool next_ok = th < td && ((isinf(td) && isinf(next)) || fabs(td - next) <= eps);
		bool agrees = false, some_hit = false, some_miss = false;
		for (int j = 0; j < 8 && !agrees; j++) {
			double a = 2 * M_PI * j / 8, jo[3];
			for (int k = 0; k < 3; k++)
				jo[k] = wo[k] + tol * (cos(a) * u[k] + sin(a) * w[k]);
			double tj = cast_trace(&sh, jo, wd, NULL);
			agrees = (isinf(td) && isinf(tj)) || fabs(td - tj) <= eps || (next_ok && tj > th + eps);
			some_hit |= isfinite(tj);
			some_miss |= isinf(tj);
		}
		/* a curved surface's silhouette: within tol of it some rays hit and some
		 * miss, and a grazing hit's distance is uncertain by about sqrt(tol) */
		agrees = agrees || (some_hit && some_miss);
		/* a ray aimed at an edge may stop there (t = 1) or pass it: one of the
		 * two stops near it (grazing turns a tiny offset into a larger one in t) */
		agrees = agrees || (on_edge[i] && (fabs(td - 1) <= 3e-3 || fabs(th - 1) <= 3e-3));
		if (agrees) {
			near[i >= n_rays]++;
		} else if (wrong++ < 5) {
			printf("  ray %d <%.9g,%.9g,%.9g> <%.9g,%.9g,%.9g>: device t %.9g, host %.9g\n", i, wo[0], wo[1], wo[2],
			       wd[0], wd[1], wd[2], td, th);
		}
	}
	/* grazing rays: at most 0.5% of the random ones; the aimed ones are aimed at
	 * edges about half the time (at a polygon's always) */
	bool ok = wrong == 0 && near[0] <= n_rays / 200 + 1;
	printf("%s: %s: %d rays (%d hit), %d disagree, %d + %d graze a boundary\n", ok ? "ok" : "FAIL", names[which], n,
	       hit_count, wrong, near[0], near[1]);
	failures += !ok;

	/* the host's inside against trace(): crossings of a ray out of the point,
	 * and the normals at the crossings point out (a quadric is unbounded) */
	if (shape_of(&o)->inside && !(o.shape_flags & SHAPE_OPEN) && o.shape != SHAPE_QUADRIC)
		failures += cast_check_inside(&sh, names[which], lo, hi, size, 2000) != 0;
done:
	free(rays);
	free(hits);
	free(on_edge);
	lower_free(&lr);
	revolve_free(&pr);
	scene_free(&s);
}

int main(int argc, char **argv)
{
	int n = argc > 1 ? atoi(argv[1]) : 20000;
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	printf("device: %s\n", dev.name);
	lower_result probe = { .layout = LOWER_LAYOUT_BINARY };
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&probe), NULL);
	if (!prog)
		return 1;
	for (int which = 0; which < SHAPES; which++)
		test_shape(&dev, prog, which, n);
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all quadric, sor and lathe checks passed");
	return failures ? 1 : 0;
}
