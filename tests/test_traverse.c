/* test_traverse.c: the kernels' BVH traversal (kernels/raycast.cl, through
 * eclat's own lowering and device code) against brute force in double precision.
 *
 *   test_traverse [FILE=RAYS]...
 *
 * Closest hits and any-hits of RAYS random and RAYS aimed rays on each mesh FILE
 * (tests/traverse.test names them: the generated blob and assimp's Wuson, and
 * the bunny and the dragon when the optional meshes are there) and on a soup
 * with degenerate triangles, and of recorded rays grazing the silhouette of
 * dragon.obj when it is one of the files; rays aimed exactly at the shared
 * corners and edges of a closed mesh, which must never slip through; and a mesh
 * placed as a transformed instance against the same triangles flattened into
 * world space. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "lower.h"
#include "mesh_io.h"
#include "mesh_arg.h"

static int failures;
static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static double uniform(void)   /* splitmix64 */
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

static void check(int ok, const char *fmt, const char *what, double a, double b)
{
	printf("%s: ", ok ? "ok" : "FAIL");
	printf(fmt, what, a, b);
	putchar('\n');
	failures += !ok;
}

/* ---- geometry: world-space triangles, as the brute force sees them ---- */

struct soup {
	double (*v)[3][3];
	int n;
};

struct hit {
	double t;
	int face;        /* -1: none */
	double margin;   /* the smallest barycentric coordinate: near 0 on an edge */
};

/* Where the ray (o, d) crosses the plane of face f, in double: returns the
 * smallest barycentric coordinate (negative outside the face, near 0 on an edge)
 * and sets *t; -1 for a face with no area or a ray along its plane. */
static double face_crossing(const struct soup *s, int f, const float o[3], const float d[3], double *t)
{
	const double (*v)[3] = s->v[f];
	double e1[3], e2[3], p[3], q[3], tv[3];
	for (int k = 0; k < 3; k++) {
		e1[k] = v[1][k] - v[0][k];
		e2[k] = v[2][k] - v[0][k];
		tv[k] = o[k] - v[0][k];
	}
	p[0] = d[1] * e2[2] - d[2] * e2[1], p[1] = d[2] * e2[0] - d[0] * e2[2], p[2] = d[0] * e2[1] - d[1] * e2[0];
	double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
	if (det == 0)
		return -1;
	double u = (tv[0] * p[0] + tv[1] * p[1] + tv[2] * p[2]) / det;
	q[0] = tv[1] * e1[2] - tv[2] * e1[1], q[1] = tv[2] * e1[0] - tv[0] * e1[2], q[2] = tv[0] * e1[1] - tv[1] * e1[0];
	double w = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
	*t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
	return fmin(fmin(u, w), 1 - u - w);
}

static double face_margin(const struct soup *s, int f, const float o[3], const float d[3])
{
	double t;
	return face_crossing(s, f, o, d, &t);
}

/* How far, in the scene's units, the ray crosses face f's plane from the nearest
 * of its edge lines (negative outside the face): each barycentric coordinate
 * times the height over its edge. */
static double edge_distance(const struct soup *s, int f, const float o[3], const float d[3])
{
	const double (*v)[3] = s->v[f];
	double t = NAN, e[3][3], n[3];
	face_crossing(s, f, o, d, &t);
	if (isnan(t))   /* no area, or a ray along its plane */
		return -INFINITY;
	for (int k = 0; k < 3; k++) {
		e[0][k] = v[2][k] - v[1][k];   /* opposite corner 0 */
		e[1][k] = v[2][k] - v[0][k];   /* opposite corner 1 */
		e[2][k] = v[1][k] - v[0][k];   /* opposite corner 2 */
	}
	n[0] = e[2][1] * e[1][2] - e[2][2] * e[1][1];
	n[1] = e[2][2] * e[1][0] - e[2][0] * e[1][2];
	n[2] = e[2][0] * e[1][1] - e[2][1] * e[1][0];
	double area2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	/* the crossing point, and its barycentric coordinates by sub-areas */
	double p[3];
	for (int k = 0; k < 3; k++)
		p[k] = o[k] + t * d[k];
	double best = INFINITY;
	for (int c = 0; c < 3; c++) {
		const double *a = v[(c + 1) % 3], *q = v[(c + 2) % 3];
		double x[3], y[3], m[3];
		for (int k = 0; k < 3; k++)
			x[k] = a[k] - p[k], y[k] = q[k] - p[k];
		m[0] = x[1] * y[2] - x[2] * y[1], m[1] = x[2] * y[0] - x[0] * y[2], m[2] = x[0] * y[1] - x[1] * y[0];
		double b = (m[0] * n[0] + m[1] * n[1] + m[2] * n[2]) / (area2 * area2);
		best = fmin(best, b * area2 / sqrt(e[c][0] * e[c][0] + e[c][1] * e[c][1] + e[c][2] * e[c][2]));
	}
	return best;
}

/* Whether the device may place the ray on the other side of face f's edge by
 * rounding: it works in float on coordinates as large as |o| + t, so it can move
 * a crossing by some ulps of that (up to about 10 FLT_EPSILON (|o| + t) measured
 * on the dragon's silhouettes at t = 25). A bound on the barycentric coordinate
 * instead would be blind to scale: 1e-5 of a 0.03-high triangle 25 units away is
 * already within rounding. */
static int near_edge(const struct soup *s, int f, const float o[3], const float d[3], double t)
{
	double scale = fmax(fmax(fabs(o[0]), fabs(o[1])), fabs(o[2])) +
	               t * fmax(fmax(fabs(d[0]), fabs(d[1])), fabs(d[2]));
	return fabs(edge_distance(s, f, o, d)) < 16 * FLT_EPSILON * scale;
}

/* The reference: the nearest face the ray crosses, edges included, in double. */
static struct hit brute_force(const struct soup *s, const float o[3], const float d[3], double tmax)
{
	struct hit best = { tmax, -1, 0 };
	for (int f = 0; f < s->n; f++) {
		double t, m = face_crossing(s, f, o, d, &t);
		if (m >= -1e-7 && t > 0 && t < best.t)
			best = (struct hit){ t, f, m };
	}
	return best;
}

/* ---- the device ---- */

struct device_scene {
	device_ctx *dev;
	cl_program prog;
	lower_result lr;
};

/* Casts n rays (origin, direction, tmax) through the kernels; hits: t, face, any. */
static int cast(struct device_scene *ds, const float *rays, int n, float *hits)
{
	lower_result *lr = &ds->lr;
	cl_int err;
	cl_kernel k = clCreateKernel(ds->prog, "raycast", &err);
	cl_mem b[4] = {
		clCreateBuffer(ds->dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
		               lr->dev_node_bytes, (void *)lr->dev_nodes, &err),
		clCreateBuffer(ds->dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
		               lr->n_all_prims * sizeof(dev_prim), lr->prims, &err),
		clCreateBuffer(ds->dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
		               (size_t)n * 8 * sizeof(float), (void *)rays, &err),
		clCreateBuffer(ds->dev->context, CL_MEM_WRITE_ONLY, (size_t)n * 4 * sizeof(float), NULL, &err),
	};
	clSetKernelArg(k, 0, sizeof(cl_mem), &b[0]);
	clSetKernelArg(k, 1, sizeof(cl_mem), &b[1]);
	clSetKernelArg(k, 2, sizeof(int), &lr->n_prims);
	clSetKernelArg(k, 3, sizeof(int), &lr->n_planes);
	clSetKernelArg(k, 4, sizeof(cl_mem), &b[2]);
	clSetKernelArg(k, 5, sizeof(cl_mem), &b[3]);
	size_t global = (size_t)n;
	err = clEnqueueNDRangeKernel(ds->dev->queue, k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(ds->dev->queue, b[3], CL_TRUE, 0, (size_t)n * 4 * sizeof(float), hits, 0,
		                          NULL, NULL);
	for (int i = 0; i < 4; i++)
		clReleaseMemObject(b[i]);
	clReleaseKernel(k);
	if (err != CL_SUCCESS)
		return device_fail("raycast", err);
	/* the face: the object number of a top-level triangle, or of a mesh's triangle */
	for (int i = 0; i < n; i++) {
		int prim;
		memcpy(&prim, &hits[4 * i + 1], sizeof prim);
		hits[4 * i + 1] = prim < 0 ? -1.0f : (float)lr->prims[prim].object;
	}
	return 0;
}

/* ---- scenes ---- */

static scene_object triangle_object(const double v[3][3], int id)
{
	scene_object o = { .shape = SHAPE_TRIANGLE, .xf = scene_xform_identity(),
	                   .material = scene_default_material(), .loc = SRC_NOWHERE };
	memcpy(o.p, v, sizeof o.p);
	(void)id;
	return o;
}

/* The mesh's faces in world space through xf, for the brute force. */
static struct soup mesh_soup(const scene_mesh *m, const xform *xf)
{
	struct soup s = { malloc(m->n_faces * sizeof *s.v), m->n_faces };
	for (int f = 0; f < m->n_faces; f++)
		for (int k = 0; k < 3; k++)
			scene_xform_point(xf, m->v[m->face[f][k]], s.v[f][k]);
	return s;
}

/* The node layout under test (main runs every check in both). */
static int layout;

static int open_scene(struct device_scene *ds, const scene *s)
{
	lower_options lo = { LOWER_BVH_SAH, 24, layout, 0, 0, 0, NULL };
	if (lower_scene(s, &lo, &ds->lr)) {
		fprintf(stderr, "lowering failed\n");
		return -1;
	}
	return 0;
}

/* A scene holding mesh m once, placed by xf: as an instance, or flattened. */
static void mesh_scene(scene *s, const scene_mesh *m, const xform *xf, int flatten)
{
	scene_init(s);
	if (flatten) {
		for (int f = 0; f < m->n_faces; f++) {
			double v[3][3];
			for (int k = 0; k < 3; k++)
				memcpy(v[k], m->v[m->face[f][k]], sizeof v[k]);
			scene_object o = triangle_object(v, f);
			o.xf = *xf;
			scene_add_object(s, &o);
		}
		return;
	}
	scene_mesh copy = *m;
	copy.v = malloc(m->n_v * sizeof *m->v);
	copy.face = malloc(m->n_faces * sizeof *m->face);
	memcpy(copy.v, m->v, m->n_v * sizeof *m->v);
	memcpy(copy.face, m->face, m->n_faces * sizeof *m->face);
	copy.nrm = NULL, copy.face_nrm = NULL, copy.n_nrm = 0;
	scene_object o = { .shape = SHAPE_MESH, .mesh = scene_add_mesh(s, &copy), .xf = *xf,
	                   .material = scene_default_material(), .loc = SRC_NOWHERE };
	scene_add_object(s, &o);
}

/* ---- rays ---- */

static void bounds(const struct soup *s, double lo[3], double hi[3])
{
	for (int k = 0; k < 3; k++)
		lo[k] = 1e300, hi[k] = -1e300;
	for (int f = 0; f < s->n; f++)
		for (int c = 0; c < 3; c++)
			for (int k = 0; k < 3; k++) {
				lo[k] = fmin(lo[k], s->v[f][c][k]);
				hi[k] = fmax(hi[k], s->v[f][c][k]);
			}
}

/* Half the rays from a sphere around the geometry toward random points of its box,
 * half from inside the box in any direction; aimed: toward points inside random faces. */
static float *make_rays(const struct soup *s, int n, int aimed)
{
	double lo[3], hi[3], c[3], r = 0;
	bounds(s, lo, hi);
	for (int k = 0; k < 3; k++) {
		c[k] = (lo[k] + hi[k]) / 2;
		r += (hi[k] - lo[k]) * (hi[k] - lo[k]);
	}
	r = sqrt(r);
	float *rays = malloc((size_t)n * 8 * sizeof *rays);
	for (int i = 0; i < n; i++) {
		double o[3], target[3], d[3], len = 0;
		double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform(), sz = sqrt(1 - z * z);
		double dir[3] = { sz * cos(phi), sz * sin(phi), z };
		int inside = !aimed && (i & 1);
		for (int k = 0; k < 3; k++)
			o[k] = inside ? lo[k] + uniform() * (hi[k] - lo[k]) : c[k] + 1.5 * r * dir[k];
		if (aimed) {
			const double (*v)[3] = s->v[(int)(uniform() * s->n) % s->n];
			double b1 = 0.05 + 0.9 * uniform(), b2 = (1 - b1 - 0.05) * uniform() + 0.025;
			b1 = fmin(b1, 0.95 - b2);
			for (int k = 0; k < 3; k++)
				target[k] = (1 - b1 - b2) * v[0][k] + b1 * v[1][k] + b2 * v[2][k];
		} else {
			for (int k = 0; k < 3; k++)
				target[k] = lo[k] + uniform() * (hi[k] - lo[k]);
		}
		for (int k = 0; k < 3; k++) {
			d[k] = inside ? dir[k] : target[k] - o[k];
			len += d[k] * d[k];
		}
		for (int k = 0; k < 3; k++) {
			rays[8 * i + k] = (float)o[k];
			rays[8 * i + 4 + k] = (float)(d[k] / sqrt(len));
		}
		rays[8 * i + 3] = INFINITY;
		rays[8 * i + 7] = 0;
	}
	return rays;
}

/* Device against brute force: equal hit or miss, equal distance (1e-4 relative),
 * the same face unless two faces meet there; a disagreement only where the ray
 * passes within rounding of an edge. any-hit must agree with closest-hit. */
static void compare(const char *what, struct device_scene *ds, const struct soup *s, const float *rays, int n)
{
	float *hits = malloc((size_t)n * 4 * sizeof *hits);
	if (cast(ds, rays, n, hits)) {
		failures++;
		free(hits);
		return;
	}
	int bad = 0, edge = 0, n_hits = 0, any_bad = 0;
	for (int i = 0; i < n; i++) {
		const float *o = rays + 8 * i, *d = rays + 8 * i + 4, *h = hits + 4 * i;
		struct hit ref = brute_force(s, o, d, INFINITY);
		int dev_hit = h[1] >= 0;
		n_hits += ref.face >= 0;
		any_bad += (h[3] > 0.5f) != dev_hit;
		int same = dev_hit == (ref.face >= 0) &&
		           (!dev_hit || fabs(h[0] - ref.t) <= 1e-4 * fmax(1.0, ref.t));
		if (same)
			continue;
		/* within rounding of an edge: the reference's face, or the device's */
		if ((ref.face >= 0 && near_edge(s, ref.face, o, d, ref.t)) ||
		    (dev_hit && near_edge(s, (int)h[1], o, d, h[0]))) {
			edge++;
			continue;
		}
		if (bad++ < 5)
			fprintf(stderr, "  %s ray %d: device t %.9g face %d (margin %g), brute force t %.9g face %d "
			        "(margin %g)\n", what, i, h[0], (int)h[1], dev_hit ? face_margin(s, (int)h[1], o, d) : 0,
			        ref.t, ref.face, ref.margin);
	}
	char line[256];
	snprintf(line, sizeof line, "%s: %d rays, %d hits, %d at an edge within rounding", what, n, n_hits, edge);
	check(bad == 0 && any_bad == 0, "%s; %g disagreements, %g any-hit errors", line, bad, any_bad);
	free(hits);
}

/* Rays recorded on the dragon that graze its silhouette: the brute force crosses
 * a front face 1e-5 to 3e-5 of its height inside an edge whose other face turns
 * away, 25 units off, and both layouts miss that face (float rounding moves the
 * crossing by about 1e-6 there), so the ray goes on to a farther face or out. A
 * barycentric bound of 1e-5 counted them as traversal errors. A reported dragon
 * ray missed at t = 23.92, 1.36e-5 from an edge (not reproduced: no binary/wide
 * difference in 20 million rays) fits this pattern. */
static const float dragon_grazes[][8] = {
	{ 0x1.08cc4ep-2, -0x1.2d63f4p+3, 0x1.2c003ap+4, INFINITY, -0x1.ffeddcp-6, 0x1.48a60cp-1, -0x1.8845e8p-1, 0 },
	{ 0x1.946a44p+4, -0x1.2052cp-3, -0x1.d5594p+3, INFINITY, -0x1.8c77a4p-1, 0x1.37cd24p-3, 0x1.3a7442p-1, 0 },
	{ 0x1.388994p+4, 0x1.6017c4p+4, -0x1.4437c4p+1, INFINITY, -0x1.4c0204p-1, -0x1.7e7cf6p-1, 0x1.2bcd7ep-3, 0 },
};

static int test_mesh(device_ctx *dev, cl_program prog, const char *file, int n)
{
	char label[320], err[512];
	const char *name = strrchr(file, '/') ? strrchr(file, '/') + 1 : file;
	scene_mesh m;
	if (mesh_io_load(file, MESH_IO_DEFAULT_TIME_LIMIT, 0, &m, err, sizeof err)) {
		printf("FAIL: %s does not load: %s\n", file, err);
		failures++;
		return -1;
	}
	xform id = scene_xform_identity();
	struct soup s = mesh_soup(&m, &id);
	scene sc;
	mesh_scene(&sc, &m, &id, 0);
	struct device_scene ds = { .dev = dev, .prog = prog };
	if (open_scene(&ds, &sc) == 0) {
		float *rays = make_rays(&s, n, 0), *aimed = make_rays(&s, n, 1);
		snprintf(label, sizeof label, "%.256s, random rays", name);
		compare(label, &ds, &s, rays, n);
		snprintf(label, sizeof label, "%.256s, rays aimed inside faces", name);
		compare(label, &ds, &s, aimed, n);
		free(rays);
		free(aimed);
		if (!strcmp(name, "dragon.obj")) {
			snprintf(label, sizeof label, "%.256s, recorded rays grazing its silhouette", name);
			compare(label, &ds, &s, &dragon_grazes[0][0], sizeof dragon_grazes / sizeof dragon_grazes[0]);
		}
	}
	lower_free(&ds.lr);
	scene_free(&sc);
	free(s.v);
	free(m.v), free(m.face), free(m.nrm), free(m.face_nrm);
	return 0;
}

/* A soup in the unit cube: random triangles, and degenerate ones (a repeated
 * corner, three corners on a line, all three the same), which must never be hit. */
static void test_soup(device_ctx *dev, cl_program prog, int n_tris, int n_rays)
{
	scene sc;
	scene_init(&sc);
	struct soup s = { malloc(n_tris * sizeof *s.v), 0 };
	for (int f = 0; f < n_tris; f++) {
		double v[3][3], size = f % 50 == 0 ? 0.5 : 0.05;
		for (int k = 0; k < 3; k++)
			v[0][k] = uniform();
		for (int c = 1; c < 3; c++)
			for (int k = 0; k < 3; k++)
				v[c][k] = v[0][k] + size * (uniform() - 0.5);
		if (f % 40 == 1)
			memcpy(v[2], v[1], sizeof v[1]);
		if (f % 40 == 2)
			for (int k = 0; k < 3; k++)
				v[2][k] = 2 * v[1][k] - v[0][k];
		if (f % 40 == 3)
			memcpy(v[1], v[0], sizeof v[0]), memcpy(v[2], v[0], sizeof v[0]);
		scene_object o = triangle_object(v, f);
		scene_add_object(&sc, &o);
		memcpy(s.v[s.n++], v, sizeof v);
	}
	struct device_scene ds = { .dev = dev, .prog = prog };
	if (open_scene(&ds, &sc) == 0) {
		float *rays = make_rays(&s, n_rays, 0);
		compare("soup with degenerate triangles, random rays", &ds, &s, rays, n_rays);
		free(rays);
	}
	lower_free(&ds.lr);
	scene_free(&sc);
	free(s.v);
}

/* An icosphere: closed, every corner and edge shared, corners bit-identical. */
static scene_mesh icosphere(int levels)
{
	const double t = (1 + sqrt(5)) / 2;
	double base[12][3] = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
	                       { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
	int faces[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
	                     { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
	                     { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
	                     { 8, 6, 7 }, { 9, 8, 1 } };
	int nf = 20 << (2 * levels), nv = 12 + 30 * ((1 << (2 * levels)) - 1) * 2;
	scene_mesh m = { .v = malloc(nv * sizeof *m.v), .face = malloc(nf * sizeof *m.face) };
	for (int i = 0; i < 12; i++) {
		double l = sqrt(base[i][0] * base[i][0] + base[i][1] * base[i][1] + base[i][2] * base[i][2]);
		for (int k = 0; k < 3; k++)
			m.v[i][k] = base[i][k] / l;
	}
	m.n_v = 12;
	memcpy(m.face, faces, sizeof faces);
	m.n_faces = 20;
	for (int l = 0; l < levels; l++) {   /* split each face in four; midpoints shared by lookup */
		int n = m.n_faces;
		int (*old)[3] = malloc(n * sizeof *old);
		memcpy(old, m.face, n * sizeof *old);
		m.n_faces = 0;
		for (int f = 0; f < n; f++) {
			int mid[3];
			for (int e = 0; e < 3; e++) {
				double p[3], len = 0;
				for (int k = 0; k < 3; k++) {
					p[k] = (m.v[old[f][e]][k] + m.v[old[f][(e + 1) % 3]][k]) / 2;
					len += p[k] * p[k];
				}
				for (int k = 0; k < 3; k++)
					p[k] /= sqrt(len);
				mid[e] = -1;
				for (int v = 12; v < m.n_v && mid[e] < 0; v++)
					if (!memcmp(m.v[v], p, sizeof p))
						mid[e] = v;
				if (mid[e] < 0) {
					memcpy(m.v[m.n_v], p, sizeof p);
					mid[e] = m.n_v++;
				}
			}
			int q[4][3] = { { old[f][0], mid[0], mid[2] }, { old[f][1], mid[1], mid[0] },
			                { old[f][2], mid[2], mid[1] }, { mid[0], mid[1], mid[2] } };
			memcpy(m.face[m.n_faces], q, sizeof q);
			m.n_faces += 4;
		}
		free(old);
	}
	return m;
}

/* Rays from outside aimed exactly at corners and edge midpoints of a closed mesh:
 * watertight intersection lets none through. Placed as a transformed instance
 * and flattened, so both paths through the kernels are held to it. */
/* far: the mesh scaled by 40 and moved some 3,000 units away, where a float's
 * rounding is coarse next to the triangles: rays aimed at a vertex shared by a
 * fan of five or six triangles then slip between them unless every neighbour
 * evaluates the shared edges identically. Moller-Trumbore, which measures each
 * triangle from its own first corner, misses rays here (checked by swapping
 * it in); the watertight test misses none. */
static void test_watertight(device_ctx *dev, cl_program prog, int n_rays, int n_brute, int far)
{
	scene_mesh m = icosphere(3);
	double k = far ? 40 : 1;
	double rot[3] = { 20, 35, 50 }, sc3[3] = { 1.5 * k, 0.7 * k, 1.1 * k };
	double mv[3] = { 0.3 + far * 3000.37, -0.2 - far * 1700.71, 0.5 + far * 2900.13 };
	xform a = scene_xform_rotate(rot), b = scene_xform_scale(sc3), c = scene_xform_translate(mv);
	xform xf = scene_xform_then(&a, &b);
	xf = scene_xform_then(&xf, &c);
	for (int flatten = 0; flatten < 2; flatten++) {
		scene sc;
		mesh_scene(&sc, &m, &xf, flatten);
		struct device_scene ds = { .dev = dev, .prog = prog };
		if (open_scene(&ds, &sc) == 0) {
			float *rays = malloc((size_t)n_rays * 8 * sizeof *rays), *hits = malloc((size_t)n_rays * 4 * sizeof *hits);
			/* flattened, each face's corners as the device has them (object: the face) */
			const dev_prim **face_prim = calloc(m.n_faces, sizeof *face_prim);
			for (int i = 0; i < ds.lr.n_prims; i++)
				if (ds.lr.prims[i].type == PRIM_TRIANGLE && ds.lr.prims[i].object < m.n_faces)
					face_prim[ds.lr.prims[i].object] = &ds.lr.prims[i];
			for (int i = 0; i < n_rays; i++) {
				int fi = (int)(uniform() * m.n_faces) % m.n_faces;
				const int *f = m.face[fi];
				double p[3], w[3], o[3], len = 0;
				int e = i % 6;   /* three corners, three points along the edges */
				double at = uniform();
				for (int k = 0; k < 3; k++)
					p[k] = e < 3 ? m.v[f[e]][k] : (1 - at) * m.v[f[e - 3]][k] + at * m.v[f[(e - 2) % 3]][k];
				scene_xform_point(&xf, p, w);
				/* from outside, well off the surface: a ray that grazes the silhouette may
				 * miss within rounding, and watertightness says nothing there */
				double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform(), s = sqrt(1 - z * z), q[3];
				double pl = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
				for (int k = 0; k < 3; k++)
					q[k] = 2 * p[k] / pl + 0.7 * (k == 0 ? s * cos(phi) : k == 1 ? s * sin(phi) : z);
				scene_xform_point(&xf, q, o);
				for (int k = 0; k < 3; k++) {
					rays[8 * i + k] = (float)o[k];
					len += (w[k] - o[k]) * (w[k] - o[k]);
				}
				for (int k = 0; k < 3; k++)
					rays[8 * i + 4 + k] = (float)((w[k] - o[k]) / sqrt(len));
				rays[8 * i + 3] = INFINITY;
				if (far && flatten && e < 3 && face_prim[fi]) {
					/* exactly through the float corner: o = corner + delta and d = -delta,
					 * with delta on a grid of 1/4, which the corner's ulp (1/4096 near
					 * 3,000) divides, so both are exact (d need not be unit length here) */
					const float4 *c = e == 0 ? &face_prim[fi]->a : e == 1 ? &face_prim[fi]->b : &face_prim[fi]->c;
					const float cv[3] = { c->x, c->y, c->z };
					for (int k = 0; k < 3; k++) {
						float delta = 0.25f * roundf(4.0f * (float)(o[k] - w[k]));
						rays[8 * i + k] = cv[k] + delta;
						rays[8 * i + 4 + k] = -delta;
					}
				}
			}
			free(face_prim);
			int missed = cast(&ds, rays, n_rays, hits) ? n_rays : 0;
			for (int i = 0; i < n_rays && !missed; i++)
				missed += hits[4 * i + 1] < 0;
			char what[128];
			snprintf(what, sizeof what, "closed mesh (%s%s), %d rays aimed exactly at shared corners and edges",
			         flatten ? "flattened" : "transformed instance", far ? ", far from the origin" : "", n_rays);
			check(missed == 0, "%s: %g missed (of %g)", what, missed, n_rays);
			free(rays);
			free(hits);
		}
		lower_free(&ds.lr);
		scene_free(&sc);
	}
	/* and against brute force, both ways */
	struct soup s = mesh_soup(&m, &xf);
	for (int flatten = 0; flatten < 2 && !far; flatten++) {
		scene sc;
		mesh_scene(&sc, &m, &xf, flatten);
		struct device_scene ds = { .dev = dev, .prog = prog };
		if (open_scene(&ds, &sc) == 0) {
			float *rays = make_rays(&s, n_brute, 0);
			compare(flatten ? "closed mesh flattened, random rays" : "closed mesh as a transformed instance, random rays",
			        &ds, &s, rays, n_brute);
			free(rays);
		}
		lower_free(&ds.lr);
		scene_free(&sc);
	}
	free(s.v);
	free(m.v);
	free(m.face);
}

int main(int argc, char **argv)
{
	char path[4096];
	int rays = 0;
	for (int i = 1; i < argc; i++)   /* all of them well formed before the first test */
		if (mesh_arg(argv[i], path, sizeof path, &rays))
			return 2;
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	printf("device: %s\n", dev.name);
	for (layout = LOWER_LAYOUT_BINARY; layout <= LOWER_LAYOUT_WIDE; layout++) {
		/* the options come from a lowered scene; any scene of the layout gives them */
		lower_result probe = { .layout = layout };
		cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&probe), NULL);
		if (!prog)
			return 1;
		printf("layout: %s\n", layout == LOWER_LAYOUT_WIDE ? "wide" : "binary");
		/* brute force costs rays times triangles on the host: the counts keep the
		 * test under a minute; the device-only checks take a million rays */
		test_soup(&dev, prog, 1000, 200000);
		test_watertight(&dev, prog, 1000000, 40000, 0);
		test_watertight(&dev, prog, 1000000, 0, 1);   /* its brute force would repeat the first's */
		for (int i = 1; i < argc; i++) {
			mesh_arg(argv[i], path, sizeof path, &rays);
			test_mesh(&dev, prog, path, rays);
		}
		clReleaseProgram(prog);
	}
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all traversal checks passed");
	return failures ? 1 : 0;
}
