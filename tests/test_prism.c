/* test_prism.c: polygon, prism and text on the device (kernels/shape_prism.cl,
 * through eclat's own lowering and kernels/raycast.cl) against their host
 * trace() in double precision (src/prism.c), which is also POV-Ray's trace().
 *
 *   test_prism [RAYS]
 *
 * Each shape is lowered alone and meets RAYS random rays and RAYS rays aimed at
 * its edges, corners and caps' silhouettes. A ray must hit where trace() says
 * (the same distance within 1e-4 of the shape's size) or miss where it misses;
 * where they disagree, the ray must pass within 1e-4 of the size of a boundary
 * (a jittered ray makes trace() agree), and such rays must be rare; a ray aimed
 * at an edge may stop at it or pass it, as long as one of the two stops there
 * (within 3e-3 of its distance, which grazing magnifies). The host's
 * own inside test is checked against trace(): a point is inside when a ray from
 * it crosses the surface an odd number of times, and its normals point out. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cast.h"
#include "device.h"
#include "lower.h"
#include "prism.h"

static int failures;
/* ---- the shapes ---- */

struct outline_build {
	scene_outline ol;
	int cap;
};

static void edge(struct outline_build *b, double x0, double z0, double x1, double z1)
{
	if (b->ol.n_edges == b->cap) {
		b->cap = b->cap ? 2 * b->cap : 64;
		b->ol.edge = realloc(b->ol.edge, b->cap * sizeof *b->ol.edge);
	}
	double *e = b->ol.edge[b->ol.n_edges++];
	e[0] = x0, e[1] = z0, e[2] = x1, e[3] = z1;
}

/* A closed loop of n points on an ellipse (wobbly when w), either way round. */
static void loop(struct outline_build *b, double cx, double cz, double rx, double rz, int n, double w, int reverse)
{
	for (int i = 0; i < n; i++) {
		double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n;
		double r0 = 1 + w * sin(5 * a0), r1 = 1 + w * sin(5 * a1);
		double p[4] = { cx + rx * r0 * cos(a0), cz + rz * r0 * sin(a0), cx + rx * r1 * cos(a1), cz + rz * r1 * sin(a1) };
		if (reverse)
			edge(b, p[2], p[3], p[0], p[1]);
		else
			edge(b, p[0], p[1], p[2], p[3]);
	}
}

static void glyph_mark(struct outline_build *b)
{
	b->ol.glyph = realloc(b->ol.glyph, (b->ol.n_glyphs + 2) * sizeof *b->ol.glyph);
	b->ol.glyph[b->ol.n_glyphs++] = b->ol.n_edges;
}

enum { RING, STAR, GLYPHS, CONIC, OPEN, POLYGON, SHAPES };
static const char *const names[SHAPES] = {
	"prism ring (100 edges, a hole)", "prism star (linear, turned)", "text (three glyphs)",
	"prism conic_sweep", "prism open", "polygon (rotated, a hole)",
};

static scene_object make_shape(scene *s, int which)
{
	struct outline_build b = { 0 };
	scene_object o = { .shape = SHAPE_PRISM, .xf = scene_xform_identity(), .material = scene_default_material(),
	                   .mesh = -1, .loc = SRC_NOWHERE };
	o.radius = -0.3;
	o.param[0] = 0.7;
	switch (which) {
	case RING:
		loop(&b, 0, 0, 1, 0.8, 60, 0.1, 0);
		loop(&b, 0.1, 0, 0.5, 0.4, 40, 0, 0);
		break;
	case STAR:
		for (int i = 0; i < 10; i++) {
			double a0 = M_PI * i / 5, a1 = M_PI * (i + 1) / 5, r0 = i % 2 ? 0.4 : 1, r1 = i % 2 ? 1 : 0.4;
			edge(&b, r0 * cos(a0), r0 * sin(a0), r1 * cos(a1), r1 * sin(a1));
		}
		o.xf = scene_xform_rotate((double[3]){ 30, 20, -40 });
		xform sc = scene_xform_scale((double[3]){ 1.5, 0.5, 1 });
		o.xf = scene_xform_then(&sc, &o.xf);
		break;
	case GLYPHS:   /* "text": glyphs in xy, thickness along z */
		o.shape = SHAPE_TEXT;
		o.radius = 0.25;
		glyph_mark(&b);
		loop(&b, 0.3, 0.4, 0.3, 0.4, 30, 0, 0);
		loop(&b, 0.3, 0.4, 0.15, 0.25, 20, 0, 1);
		glyph_mark(&b);
		loop(&b, 1, 0.35, 0.3, 0.35, 24, 0.2, 1);
		glyph_mark(&b);
		edge(&b, 1.5, 0, 1.9, 0), edge(&b, 1.9, 0, 1.7, 0.7), edge(&b, 1.7, 0.7, 1.5, 0);
		glyph_mark(&b);
		b.ol.n_glyphs--;
		o.xf = scene_xform_rotate((double[3]){ 10, -35, 0 });
		break;
	case CONIC:
		loop(&b, 0, 0, 1, 1, 4, 0, 0);
		edge(&b, 0.2, 0.2, -0.2, 0.3), edge(&b, -0.2, 0.3, 0, -0.3), edge(&b, 0, -0.3, 0.2, 0.2);
		o.radius = 0.2;
		o.param[0] = 1;
		o.param[1] = 1;
		break;
	case OPEN:
		loop(&b, 0, 0, 1, 0.6, 12, 0, 1);
		o.shape_flags = SHAPE_OPEN;
		break;
	case POLYGON: {
		o.shape = SHAPE_POLYGON;
		loop(&b, 0, 0, 1, 1, 5, 0, 0);
		loop(&b, 0, 0, 0.4, 0.4, 7, 0, 1);
		double u[3] = { 1, 0, 0 }, n[3] = { 0, 0.6, -0.8 }, v[3] = { 0, 0.8, 0.6 };
		memcpy(o.n[0], u, sizeof u);
		memcpy(o.n[1], n, sizeof n);
		memcpy(o.n[2], v, sizeof v);
		o.p[0][0] = 0.3;
		break;
	}
	}
	prism_orient(&b.ol);
	o.outline = scene_add_outline(s, &b.ol);
	return o;
}

/* ---- the host's answer in world space ---- */

/* ---- the device ---- */

/* ---- rays ---- */

/* A point of the solid's surface to aim at: on an edge's side (often at a
 * corner or at a cap's rim), or on a cap, in prism space. */
static bool surface_point(const prism_view *v, double p[3])
{
	const scene_outline *ol = v->ol;
	const double *e = ol->edge[(int)(cast_uniform() * ol->n_edges)];
	double s = cast_uniform() < 0.3 ? (cast_uniform() < 0.5 ? 0 : 1) : cast_uniform();
	double y = cast_uniform() < 0.5 ? (cast_uniform() < 0.5 ? v->h1 : v->h2) : v->h1 + cast_uniform() * (v->h2 - v->h1);
	double k = v->flags & PRISM_CONIC ? y : 1;
	p[0] = k * (e[0] + s * (e[2] - e[0]));
	p[1] = y;
	p[2] = k * (e[1] + s * (e[3] - e[1]));
	return s == 0 || s == 1 || y == v->h1 || y == v->h2;   /* on an edge of the solid */
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
	prism_view v = prism_view_of(&s, &o);
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY }, mid[3];
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
	xform to_world = scene_xform_then(&v.local, &o.xf);
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
			on_edge[i] = surface_point(&v, p);
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
		bool agrees = false;
		for (int j = 0; j < 8 && !agrees; j++) {
			double a = 2 * M_PI * j / 8, jo[3];
			for (int k = 0; k < 3; k++)
				jo[k] = wo[k] + tol * (cos(a) * u[k] + sin(a) * w[k]);
			double tj = cast_trace(&sh, jo, wd, NULL);
			agrees = (isinf(td) && isinf(tj)) || fabs(td - tj) <= eps || (next_ok && tj > th + eps);
		}
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
	 * and the normals at the crossings point out */
	if (shape_of(&o)->inside && !(o.shape_flags & SHAPE_OPEN))
		failures += cast_check_inside(&sh, names[which], lo, hi, size, 2000) != 0;
done:
	free(rays);
	free(hits);
	free(on_edge);
	lower_free(&lr);
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
	printf("%s\n", failures ? "FAIL" : "all prism checks passed");
	return failures ? 1 : 0;
}
