/* embree_bench.c: make bench's comparison with Embree (issue 18), eclat and
 * Embree in one process, round by round, so that their ratio holds on a busy
 * machine. Built only by make bench, and only when configure found Embree;
 * eclat itself never links it.
 *
 *   embree_bench rays SCENE MESH ROUNDS       rays per second through the BVH
 *   embree_bench build ROUNDS MESH...         BVH build times
 *   embree_bench paths SCENE MESH W H SPP D   Embree's paths per second
 *
 * rays: the scene (tests/bench/cornell_bunny.scn, its Mesh declared as MESH) is
 * evaluated and lowered by eclat's own code; Embree gets the same triangles
 * flattened into world space. Three ray sets, the same for both: camera rays
 * (one a pixel, 1080 x 1080), diffuse bounce rays (cosine-distributed from
 * each camera hit) and shadow rays (from each camera hit to a point of the
 * lamp). eclat traces them with kernels/raycast.cl's trace_rays, which only
 * traverses (closest hit, or any hit for shadow rays); Embree with
 * rtcIntersect1 and rtcOccluded1 on 2 threads. Each round runs every set
 * through both; the summary gives each side's best and median and the ratio
 * of the medians.
 * build: each mesh's BVH built by eclat's lowering (the time --stats prints)
 * and by rtcCommitScene on 2 threads, alternately. */

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "device.h"
#include "diag.h"
#include "eval.h"
#include "lower.h"
#include "parse.h"
#include "embree_bench.h"

#define THREADS 2
#define SIZE 1080

double bench_now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

/* The process's processor time in milliseconds: what the two sides' threads
 * spent, which the other programs on a shared machine change less than the
 * wall time (only one side runs at a time). */
static double cpu_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static uint64_t rng_state = 0x2545f4914f6cdd1dull;

static float uniform(void)   /* splitmix64 */
{
	uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return (float)((z ^ (z >> 31)) >> 40) * (1.0f / 16777216.0f);
}

/* ---- the scene, through eclat's front end and lowering ---- */

static int load(const char *path, const char *mesh, scene *s, lower_result *lr)
{
	static char decl[4096], dir[4096];
	snprintf(decl, sizeof decl, "Mesh=\"%s\"", mesh);
	snprintf(dir, sizeof dir, "%s", mesh);
	char *slash = strrchr(dir, '/');
	if (slash)
		*slash = 0;
	else
		strcpy(dir, ".");
	const char *decls[] = { decl }, *dirs[] = { dir };
	eval_options eo = eval_options_default();
	eo.declares = decls;
	eo.n_declares = 1;
	eo.io_read_dirs = dirs;
	eo.n_io_read_dirs = 1;
	eo.io_current_folder = true;
	scene_init(s);
	ast_node *tree = parse_file(path, SRC_NOWHERE);
	int ok = tree && eval_scene(tree, s, &eo) == 0 && diag_error_count() == 0 && lower_scene(s, NULL, lr) == 0;
	ast_free(tree);
	if (!ok)
		fprintf(stderr, "embree_bench: %s did not evaluate and lower\n", path);
	return ok ? 0 : -1;
}

static int is_triangle(const dev_prim *p)
{
	return p->type == PRIM_TRIANGLE || p->type == PRIM_SMOOTH_TRIANGLE;
}

/* The world-to-mesh rows of an instance, inverted: the mesh-to-world map. */
static void invert_rows(const dev_prim *q, double m[3][4])
{
	double a[3][3] = { { q->a.x, q->a.y, q->a.z }, { q->b.x, q->b.y, q->b.z },
	                   { q->c.x, q->c.y, q->c.z } };
	double t[3] = { q->a.w, q->b.w, q->c.w };
	double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
	             a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
	             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {   /* the cofactor of a[j][i], over det */
			int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
			m[i][j] = (a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]) / det;
		}
	for (int i = 0; i < 3; i++)
		m[i][3] = -(m[i][0] * t[0] + m[i][1] * t[1] + m[i][2] * t[2]);
}

static void put(bench_soup *s, const float4 *c, const double (*m)[4], int emits)
{
	for (int k = 0; k < 3; k++)
		for (int a = 0; a < 3; a++)
			s->v[s->n][k][a] = m ? (float)(m[a][0] * c[k].x + m[a][1] * c[k].y + m[a][2] * c[k].z + m[a][3])
			                     : ((const float *)&c[k])[a];
	s->emits[s->n++] = emits;
}

/* The lowered scene as one soup. The bench scene places one mesh, whose
 * triangles are all those after the top level's primitives and planes. */
static int flatten(const lower_result *lr, bench_soup *s)
{
	int n_inst = 0;
	s->v = malloc((size_t)lr->n_all_prims * sizeof *s->v);
	s->emits = malloc((size_t)lr->n_all_prims * sizeof *s->emits);
	s->n = 0;
	for (int i = 0; i < lr->n_prims; i++) {
		const dev_prim *p = &lr->prims[i];
		if (is_triangle(p)) {
			float4 c[3] = { p->a, p->b, p->c };
			put(s, c, NULL, p->link >= 0);
		} else if (p->type == PRIM_INSTANCE && n_inst++ == 0) {
			double m[3][4];
			invert_rows(p, m);
			for (int j = lr->n_prims + lr->n_planes; j < lr->n_all_prims; j++)
				if (is_triangle(&lr->prims[j])) {
					float4 c[3] = { lr->prims[j].a, lr->prims[j].b, lr->prims[j].c };
					put(s, c, (const double (*)[4])m, 0);
				}
		} else {
			fprintf(stderr, "embree_bench: the scene must hold triangles and one placed mesh\n");
			return -1;
		}
	}
	const float4 *cam[4] = { &lr->params.cam_location, &lr->params.cam_direction, &lr->params.cam_right,
	                         &lr->params.cam_up };
	for (int k = 0; k < 4; k++)
		for (int a = 0; a < 3; a++)
			s->camera[k][a] = ((const float *)cam[k])[a];
	return lr->n_planes > 0 ? -1 : 0;
}

RTCScene bench_embree_scene(RTCDevice dev, const bench_soup *s, double *ms)
{
	RTCScene sc = rtcNewScene(dev);
	RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
	float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
	                                   3 * (size_t)s->n);
	unsigned *idx = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
	                                        (size_t)s->n);
	memcpy(v, s->v, (size_t)s->n * sizeof *s->v);
	for (unsigned i = 0; i < 3 * (unsigned)s->n; i++)
		idx[i] = i;
	double t0 = bench_now_ms();
	rtcCommitGeometry(g);
	rtcAttachGeometry(sc, g);
	rtcReleaseGeometry(g);
	rtcCommitScene(sc);
	*ms = bench_now_ms() - t0;
	return sc;
}

/* ---- ray sets ---- */

typedef struct {
	float *rays;   /* eclat's layout: (origin, tmax), (direction, 0) */
	int n;
	int shadow;
	const char *name;
} ray_set;

static void add_ray(ray_set *r, const float o[3], const float d[3], float tmax)
{
	float *q = &r->rays[8 * (size_t)r->n++];
	q[0] = o[0], q[1] = o[1], q[2] = o[2], q[3] = tmax;
	q[4] = d[0], q[5] = d[1], q[6] = d[2], q[7] = 0;
}

static void camera_rays(const bench_soup *s, ray_set *r)
{
	r->rays = malloc((size_t)SIZE * SIZE * 8 * sizeof(float));
	for (int y = 0; y < SIZE; y++)
		for (int x = 0; x < SIZE; x++) {
			float sx = (x + 0.5f) / SIZE - 0.5f, sy = 0.5f - (y + 0.5f) / SIZE, d[3];
			for (int a = 0; a < 3; a++)
				d[a] = s->camera[1][a] + sx * s->camera[2][a] + sy * s->camera[3][a];
			add_ray(r, s->camera[0], d, INFINITY);
		}
}

/* Diffuse bounce rays and shadow rays toward the lamp from the camera rays'
 * hits (Embree's: the sets must not depend on the side being measured). */
static void secondary_rays(RTCScene sc, const bench_soup *s, const ray_set *cam, ray_set *diffuse, ray_set *shadow)
{
	int lamps[64], n_lamps = 0;
	for (int i = 0; i < s->n && n_lamps < 64; i++)
		if (s->emits[i])
			lamps[n_lamps++] = i;
	diffuse->rays = malloc((size_t)cam->n * 8 * sizeof(float));
	shadow->rays = malloc((size_t)cam->n * 8 * sizeof(float));
	struct RTCIntersectContext ctx;
	rtcInitIntersectContext(&ctx);
	for (int i = 0; i < cam->n; i++) {
		const float *q = &cam->rays[8 * (size_t)i];
		struct RTCRayHit rh = { .ray = { q[0], q[1], q[2], 0, q[4], q[5], q[6], 0, INFINITY, -1u, 0, 0 },
		                 .hit = { .geomID = RTC_INVALID_GEOMETRY_ID } };
		rtcIntersect1(sc, &ctx, &rh);
		if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || s->emits[rh.hit.primID])
			continue;
		float n[3] = { rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z }, len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		float facing = n[0] * q[4] + n[1] * q[5] + n[2] * q[6] > 0 ? -1.0f : 1.0f, p[3], d[3];
		for (int a = 0; a < 3; a++) {
			n[a] *= facing / len;
			p[a] = q[a] + rh.ray.tfar * q[4 + a] + 1e-4f * n[a];
		}
		/* cosine-distributed about n: a point of the unit sphere, plus n */
		float z = 2 * uniform() - 1, phi = 6.2831853f * uniform(), rr = sqrtf(1 - z * z);
		d[0] = n[0] + rr * cosf(phi), d[1] = n[1] + rr * sinf(phi), d[2] = n[2] + z;
		add_ray(diffuse, p, d, INFINITY);
		if (n_lamps) {
			const float (*l)[3] = s->v[lamps[(int)(uniform() * n_lamps) % n_lamps]];
			float u = uniform(), v = uniform();
			if (u + v > 1)
				u = 1 - u, v = 1 - v;
			for (int a = 0; a < 3; a++)
				d[a] = l[0][a] + u * (l[1][a] - l[0][a]) + v * (l[2][a] - l[0][a]) - p[a];
			add_ray(shadow, p, d, 0.999f);
		}
	}
}

/* ---- Embree's side: 2 threads taking chunks of rays ---- */

typedef struct {
	RTCScene sc;
	const ray_set *r;
	atomic_int next;
	float *t;   /* each ray's hit distance (INFINITY: none), or 1/0 for shadow rays */
} embree_job;

static void *embree_worker(void *arg)
{
	embree_job *j = arg;
	struct RTCIntersectContext ctx;
	rtcInitIntersectContext(&ctx);
	for (;;) {
		int first = atomic_fetch_add(&j->next, 1024);
		if (first >= j->r->n)
			return NULL;
		int end = first + 1024 < j->r->n ? first + 1024 : j->r->n;
		for (int i = first; i < end; i++) {
			const float *q = &j->r->rays[8 * (size_t)i];
			if (j->r->shadow) {
				struct RTCRay ray = { q[0], q[1], q[2], 0, q[4], q[5], q[6], 0, q[3], -1u, 0, 0 };
				rtcOccluded1(j->sc, &ctx, &ray);
				j->t[i] = ray.tfar < 0;
			} else {
				struct RTCRayHit rh = { .ray = { q[0], q[1], q[2], 0, q[4], q[5], q[6], 0, q[3], -1u, 0, 0 },
				                 .hit = { .geomID = RTC_INVALID_GEOMETRY_ID } };
				rtcIntersect1(j->sc, &ctx, &rh);
				j->t[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? INFINITY : rh.ray.tfar;
			}
		}
	}
}

static double embree_trace(RTCScene sc, const ray_set *r, float *t, double *per_cpu)
{
	embree_job j = { sc, r, 0, t };
	pthread_t th[THREADS];
	double c0 = cpu_ms(), t0 = bench_now_ms();
	for (int i = 0; i < THREADS; i++)
		pthread_create(&th[i], NULL, embree_worker, &j);
	for (int i = 0; i < THREADS; i++)
		pthread_join(th[i], NULL);
	double ms = bench_now_ms() - t0;
	*per_cpu = r->n / ((cpu_ms() - c0) * 1e3);
	return r->n / (ms * 1e3);   /* M rays/s */
}

/* ---- eclat's side: trace_rays on the device ---- */

typedef struct {
	device_ctx *dev;
	cl_kernel k;
	cl_mem nodes, prims, rays, hits;
	int n;
} eclat_set;

static int eclat_prepare(device_ctx *dev, cl_program prog, const lower_result *lr, const ray_set *r, eclat_set *e)
{
	cl_int err;
	e->dev = dev;
	e->n = r->n;
	e->k = clCreateKernel(prog, "trace_rays", &err);
	if (!e->k)
		return device_fail("trace_rays", err);
	e->nodes = clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, lr->dev_node_bytes,
	                          (void *)lr->dev_nodes, &err);
	e->prims = clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
	                          lr->n_all_prims * sizeof(dev_prim), lr->prims, &err);
	e->rays = clCreateBuffer(dev->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
	                         (size_t)r->n * 8 * sizeof(float), r->rays, &err);
	e->hits = clCreateBuffer(dev->context, CL_MEM_WRITE_ONLY, (size_t)r->n * sizeof(cl_float4), NULL, &err);
	if (err != CL_SUCCESS)
		return device_fail("clCreateBuffer", err);
	clSetKernelArg(e->k, 0, sizeof(cl_mem), &e->nodes);
	clSetKernelArg(e->k, 1, sizeof(cl_mem), &e->prims);
	clSetKernelArg(e->k, 2, sizeof(int), &lr->n_prims);
	clSetKernelArg(e->k, 3, sizeof(int), &lr->n_planes);
	clSetKernelArg(e->k, 4, sizeof(cl_mem), &e->rays);
	clSetKernelArg(e->k, 5, sizeof(cl_mem), &e->hits);
	clSetKernelArg(e->k, 6, sizeof(int), &r->shadow);
	return 0;
}

/* M rays/s, or -1; t gets each ray's answer as embree_trace gives it, and
 * *per_cpu the M rays per second of processor time. */
static double eclat_trace(eclat_set *e, float *t, double *per_cpu)
{
	size_t global = (size_t)e->n;
	double c0 = cpu_ms(), t0 = bench_now_ms();
	cl_int err = clEnqueueNDRangeKernel(e->dev->queue, e->k, 1, NULL, &global, NULL, 0, NULL, NULL);
	if (err == CL_SUCCESS)
		err = clFinish(e->dev->queue);
	double ms = bench_now_ms() - t0;
	*per_cpu = e->n / ((cpu_ms() - c0) * 1e3);
	cl_float4 *h = malloc((size_t)e->n * sizeof *h);
	if (err == CL_SUCCESS)
		err = clEnqueueReadBuffer(e->dev->queue, e->hits, CL_TRUE, 0, (size_t)e->n * sizeof *h, h, 0, NULL, NULL);
	for (int i = 0; err == CL_SUCCESS && i < e->n; i++)
		t[i] = h[i].s[0];
	free(h);
	return err == CL_SUCCESS ? e->n / (ms * 1e3) : device_fail("trace_rays", err);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Best (the highest, or with lowest the lowest) and median of n figures. */
static void best_median(double *v, int n, int lowest, double *best, double *median)
{
	qsort(v, (size_t)n, sizeof *v, cmp_double);
	*best = lowest ? v[0] : v[n - 1];
	*median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* How many rays the two sides answer differently (a hit distance off by more
 * than 1e-3 relative, or another shadow answer): a check that they did the same work. */
static int disagreements(const ray_set *r, const float *a, const float *b)
{
	int bad = 0;
	for (int i = 0; i < r->n; i++)
		if (r->shadow ? a[i] != b[i] : !(fabsf(a[i] - b[i]) <= 1e-3f * fabsf(a[i]) || a[i] == b[i]))
			bad++;
	return bad;
}

static int cmd_rays(const char *path, const char *mesh, int rounds)
{
	scene s;
	lower_result lr;
	bench_soup soup;
	device_ctx dev;
	if (load(path, mesh, &s, &lr) || flatten(&lr, &soup) || device_open(&dev, -1))
		return 1;
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&lr), lr.functions);
	if (!prog)
		return 1;
	RTCDevice edev = rtcNewDevice("threads=2");
	double build_ms;
	RTCScene sc = bench_embree_scene(edev, &soup, &build_ms);
	ray_set sets[3] = { { .name = "camera" }, { .name = "diffuse" }, { .name = "shadow", .shadow = 1 } };
	camera_rays(&soup, &sets[0]);
	secondary_rays(sc, &soup, &sets[0], &sets[1], &sets[2]);
	eclat_set es[3];
	double *fig[3][4], cpu;   /* wall: eclat, Embree; processor time: eclat, Embree */
	float *ta = malloc((size_t)sets[0].n * sizeof *ta), *tb = malloc((size_t)sets[0].n * sizeof *tb);
	for (int k = 0; k < 3; k++) {
		if (eclat_prepare(&dev, prog, &lr, &sets[k], &es[k]))
			return 1;
		for (int f = 0; f < 4; f++)
			fig[k][f] = malloc((size_t)rounds * sizeof(double));
		eclat_trace(&es[k], ta, &cpu);   /* warm-up: the first launch compiles for the work-group size */
	}
	printf("rays: %d triangles; %d camera, %d diffuse, %d shadow rays; %d rounds, eclat then Embree\n", soup.n,
	       sets[0].n, sets[1].n, sets[2].n, rounds);
	for (int r = 0; r < rounds; r++)
		for (int k = 0; k < 3; k++) {
			fig[k][0][r] = eclat_trace(&es[k], ta, &fig[k][2][r]);
			fig[k][1][r] = embree_trace(sc, &sets[k], tb, &fig[k][3][r]);
			if (fig[k][0][r] < 0)
				return 1;
			printf("round %d: %-7s eclat %6.2f M rays/s, Embree %6.2f (%.2fx); per processor second %.2f and %.2f "
			       "(%.2fx); %d rays answered differently\n", r + 1, sets[k].name, fig[k][0][r], fig[k][1][r],
			       fig[k][0][r] / fig[k][1][r], fig[k][2][r], fig[k][3][r], fig[k][2][r] / fig[k][3][r],
			       disagreements(&sets[k], ta, tb));
			fflush(stdout);
		}
	for (int k = 0; k < 3; k++) {
		double eb, em, bb, bm, ecb, ecm, bcb, bcm;
		best_median(fig[k][0], rounds, 0, &eb, &em);
		best_median(fig[k][1], rounds, 0, &bb, &bm);
		best_median(fig[k][2], rounds, 0, &ecb, &ecm);
		best_median(fig[k][3], rounds, 0, &bcb, &bcm);
		printf("summary: %s rays, M rays/s best and median: eclat %.2f %.2f, Embree rtc%s1 %.2f %.2f: "
		       "eclat/Embree %.2fx; per processor second, medians: eclat %.2f, Embree %.2f: %.2fx\n", sets[k].name,
		       eb, em, sets[k].shadow ? "Occluded" : "Intersect", bb, bm, em / bm, ecm, bcm, ecm / bcm);
	}
	rtcReleaseScene(sc);
	rtcReleaseDevice(edev);
	return 0;
}

/* ---- BVH builds ---- */

static int cmd_build(int rounds, char **meshes, int n_meshes)
{
	RTCDevice edev = rtcNewDevice("threads=2");
	for (int m = 0; m < n_meshes; m++) {
		char scn[] = "/tmp/eclat-embree-bench-XXXXXX";
		int fd = mkstemp(scn);
		FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
		if (!f)
			return 1;
		fprintf(f, "object { mesh { file Mesh } }\n");
		fclose(f);
		double *fe = malloc((size_t)rounds * sizeof *fe), *fb = malloc((size_t)rounds * sizeof *fb);
		int n_tris = 0;
		for (int r = 0; r < rounds; r++) {
			scene s;
			lower_result lr;
			bench_soup soup;
			if (load(scn, meshes[m], &s, &lr) || flatten(&lr, &soup))
				return 1;
			fe[r] = lr.n_stats > 1 ? lr.stats[1].build_ms : lr.stats[0].build_ms;
			RTCScene sc = bench_embree_scene(edev, &soup, &fb[r]);
			n_tris = soup.n;
			rtcReleaseScene(sc);
			free(soup.v);
			free(soup.emits);
			lower_free(&lr);
			scene_free(&s);
		}
		remove(scn);
		double eb, em, bb, bm;
		best_median(fe, rounds, 1, &eb, &em);
		best_median(fb, rounds, 1, &bb, &bm);
		const char *name = strrchr(meshes[m], '/');
		printf("summary: BVH build of %s (%d triangles), ms best and median of %d: eclat %.1f %.1f, "
		       "Embree %.1f %.1f: eclat/Embree %.2fx\n", name ? name + 1 : meshes[m], n_tris, rounds, eb, em, bb,
		       bm, em / bm);
	}
	rtcReleaseDevice(edev);
	return 0;
}

static int cmd_paths(const char *path, const char *mesh, int w, int h, int spp, int depth)
{
	scene s;
	lower_result lr;
	bench_soup soup;
	if (load(path, mesh, &s, &lr) || flatten(&lr, &soup))
		return 1;
	RTCDevice edev = rtcNewDevice("threads=2");
	double ms;
	RTCScene sc = bench_embree_scene(edev, &soup, &ms);
	printf("embree paths: %.3f M paths/s\n", bench_embree_paths(sc, &soup, w, h, spp, depth, THREADS));
	rtcReleaseScene(sc);
	rtcReleaseDevice(edev);
	return 0;
}

int main(int argc, char **argv)
{
	if (argc == 5 && !strcmp(argv[1], "rays"))
		return cmd_rays(argv[2], argv[3], atoi(argv[4]));
	if (argc >= 4 && !strcmp(argv[1], "build"))
		return cmd_build(atoi(argv[2]), &argv[3], argc - 3);
	if (argc == 8 && !strcmp(argv[1], "paths"))
		return cmd_paths(argv[2], argv[3], atoi(argv[4]), atoi(argv[5]), atoi(argv[6]), atoi(argv[7]));
	fprintf(stderr, "usage: embree_bench rays SCENE MESH ROUNDS | build ROUNDS MESH... | "
	                "paths SCENE MESH W H SPP DEPTH\n");
	return 2;
}
