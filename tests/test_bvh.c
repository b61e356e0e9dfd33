/* test_bvh.c: checks bvh_build's trees structurally and by ray casting.
 *
 *   test_bvh              random triangle soups (with degenerate triangles)
 *   test_bvh mesh.obj     also a Wavefront OBJ mesh (v and f lines)
 *   test_bvh --property [FILE.obj=BRUTE]...   a million random rays each on
 *                         every OBJ mesh FILE (brute force on the first BRUTE)
 *                         and a soup (tests/bvh_property.test names the meshes)
 *
 * The core check: for every ray, the closest hit found by traversing the BVH
 * equals the closest hit found by testing every triangle, using the same
 * ray/triangle function, so the distances must agree bit for bit (a different
 * triangle is accepted only at exactly the same distance). The traversal here
 * is the reference the OpenCL kernel mirrors (see slab and traverse).
 * Exit status 0 = pass. Build with -I$(top_srcdir)/src -I$(top_srcdir)/kernels. */
#include "bvh.h"
#include "mesh_arg.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef SEED                   /* -DSEED=... to try other soups */
#define SEED 0x2545F4914F6CDD1DULL
#endif
#define N_SOUP 20000
#define N_RAYS 100000
#define MAX_REPORTED 8

/* Slab test slack, pbrt's 1 + 2 * gamma(3) rounded up: the far distance is
 * stretched so that rounding in the six plane distances cannot make a ray miss
 * a box that it touches. Without it, rays through a box's edge or corner
 * (t_near == t_far exactly) miss by rounding; the plane rays below, aimed at
 * vertices, make the property check fail if BOX_PAD is set to 1. */
#define BOX_PAD (1.0f + 4.0f * FLT_EPSILON)

/* ---- random numbers: splitmix64, fixed seed ---- */

typedef struct {
	uint64_t s;
} rng;

static uint64_t rng_u64(rng *r)
{
	uint64_t z = (r->s += 0x9E3779B97F4A7C15ULL);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	return z ^ (z >> 31);
}

/* Uniform in [0, 1), 24 random bits so every value is exact in float. */
static float rng_f(rng *r)
{
	return (float)(rng_u64(r) >> 40) * (1.0f / 16777216.0f);
}

static float rng_range(rng *r, float lo, float hi)
{
	return lo + (hi - lo) * rng_f(r);
}

static int rng_int(rng *r, int n)
{
	return (int)(rng_u64(r) % (uint64_t)n);
}

/* ---- small vector helpers ---- */

static void sub3(float r[3], const float a[3], const float b[3])
{
	for (int i = 0; i < 3; i++)
		r[i] = a[i] - b[i];
}

static void cross3(float r[3], const float a[3], const float b[3])
{
	r[0] = a[1] * b[2] - a[2] * b[1];
	r[1] = a[2] * b[0] - a[0] * b[2];
	r[2] = a[0] * b[1] - a[1] * b[0];
}

static float dot3(const float a[3], const float b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double now_ms(void)
{
	struct timespec ts;
	timespec_get(&ts, TIME_UTC);
	return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

/* ---- triangles, rays and the intersection function ---- */

/* v: the vertices; e1, e2, det2_min, lo, hi: precomputed for the
 * intersection, so that brute force over a whole mesh stays affordable. */
typedef struct {
	float v[3][3];
	float e1[3], e2[3];
	float det2_min;
	float lo[3], hi[3];     /* the box, as given to bvh_build */
} tri;

typedef struct {
	float o[3], d[3], inv[3];
	int neg[3];         /* signbit of d: which plane of each slab is entered first */
} ray;

typedef struct {
	float t;
	int prim;           /* -1: miss */
	int visits;         /* nodes visited */
	int tests;          /* ray/triangle tests */
} hit;

/* A determinant below 1e-6 of |e1| |e2| (|d| = 1) means a degenerate triangle
 * (identical or collinear vertices) or a ray within 1e-6 of its plane. */
static void tri_finish(tri *t)
{
	sub3(t->e1, t->v[1], t->v[0]);
	sub3(t->e2, t->v[2], t->v[0]);
	t->det2_min = 1e-12f * dot3(t->e1, t->e1) * dot3(t->e2, t->e2);
	for (int a = 0; a < 3; a++) {
		t->lo[a] = fminf(t->v[0][a], fminf(t->v[1][a], t->v[2][a]));
		t->hi[a] = fmaxf(t->v[0][a], fmaxf(t->v[1][a], t->v[2][a]));
	}
}

static bvh_box tri_box(const tri *t)
{
	bvh_box b;
	memcpy(b.min, t->lo, sizeof b.min);
	memcpy(b.max, t->hi, sizeof b.max);
	return b;
}

/* Whether the hit point at t lies in the triangle's box, give or take 1e-5 of
 * the coordinates involved (which covers the rounding of o + t d). On slivers
 * (vertices collinear up to rounding) and at grazing angles, Moller-Trumbore's
 * rounding can report a "hit" far outside the triangle and its box, where no
 * correct BVH looks; brute force would then disagree with every BVH. */
static int hit_in_box(const ray *r, const tri *tr, float t)
{
	for (int a = 0; a < 3; a++) {
		float p = r->o[a] + t * r->d[a];
		float slack = 1e-5f * (fabsf(r->o[a]) + fabsf(t * r->d[a]));
		if (p < tr->lo[a] - slack || p > tr->hi[a] + slack)
			return 0;
	}
	return 1;
}

/* Moller-Trumbore: a hit with t in (1e-6, tmax) stores t and returns 1.
 * Everything is computed before one combined test (1/det may be inf or NaN
 * then, and fails the test): without the usual early exits there are no
 * mispredicted branches, which makes brute force over a 70,000-triangle mesh
 * about twice as fast. The accepted hits are those of the textbook form,
 * less the rounding artefacts that hit_in_box rejects. */
static int intersect(const ray *r, const tri *tr, float tmax, float *t_out)
{
	float p[3], s[3], q[3];
	cross3(p, r->d, tr->e2);
	sub3(s, r->o, tr->v[0]);
	cross3(q, s, tr->e1);
	float det = dot3(tr->e1, p);
	float inv_det = 1.0f / det;
	float u = dot3(s, p) * inv_det;
	float v = dot3(r->d, q) * inv_det;
	float t = dot3(tr->e2, q) * inv_det;
	int ok = (det * det > tr->det2_min) & (u >= 0.0f) & (u <= 1.0f) & (v >= 0.0f) & (u + v <= 1.0f) &
		 (t > 1e-6f) & (t < tmax);
	if (!ok || !hit_in_box(r, tr, t))
		return 0;
	*t_out = t;
	return 1;
}

/* d need not be normalised; zero components stay exactly zero (with their
 * sign), so 1/d gives the infinities the slab test is built for. */
static ray make_ray(const float o[3], const float d[3])
{
	ray r;
	float len = sqrtf(dot3(d, d));
	for (int a = 0; a < 3; a++) {
		r.o[a] = o[a];
		r.d[a] = d[a] / len;
		r.inv[a] = 1.0f / r.d[a];
		r.neg[a] = signbit(r.d[a]) != 0;
	}
	return r;
}

/* ---- the slab test and the traversal (the kernel mirrors these) ---- */

/* Ray against box, clipped to [0, closest]. Per axis the entry plane is
 * chosen by the direction's sign bit, not by fmin(t1, t2): when d = +-0 and
 * the origin lies exactly in a plane, (plane - o) * inv = 0 * inf = NaN, and
 * fmaxf/fminf ignore a NaN operand, so that plane simply imposes no limit
 * (the ray runs inside the closed slab). The fmin(t1, t2) form would instead
 * return the other plane's +inf and make the ray miss. Off the planes, d = 0
 * gives +-inf of the right signs: no limit inside the slab, a miss outside.
 * Returns 1 on a hit and the entry distance (>= 0, never NaN) in *t_entry. */
static int slab(const bvh_node *b, const ray *r, float closest, float *t_entry)
{
	const float lo[3] = { b->min_x, b->min_y, b->min_z };
	const float hi[3] = { b->max_x, b->max_y, b->max_z };
	float t_near = 0.0f, t_far = closest;
	for (int a = 0; a < 3; a++) {
		float enter = r->neg[a] ? hi[a] : lo[a];
		float leave = r->neg[a] ? lo[a] : hi[a];
		t_near = fmaxf(t_near, (enter - r->o[a]) * r->inv[a]);
		t_far = fminf(t_far, (leave - r->o[a]) * r->inv[a]);
	}
	*t_entry = t_near;
	return t_near <= t_far * BOX_PAD;
}

/* Pops the next node whose entry distance is not beyond the closest hit;
 * -1 when the stack runs out. */
static int pop(const int *stack_node, const float *stack_t, int *sp, float closest)
{
	while (*sp > 0) {
		--*sp;
		if (stack_t[*sp] <= closest * BOX_PAD)
			return stack_node[*sp];
	}
	return -1;
}

/* Closest hit by stack traversal. At an interior node both children are
 * slab-tested against [0, closest]; if both are hit, the one with the smaller
 * entry distance is visited next (the left one on a tie) and the other is
 * pushed with its entry distance; if one is hit it is visited; if none, or at a
 * leaf after testing its triangles, the stack is popped, skipping entries whose
 * entry distance exceeds the (possibly shrunk) closest hit. The stack needs
 * depth - 1 entries: stacked nodes have strictly increasing depths. */
static hit traverse(const bvh_tree *t, const tri *tris, const ray *r, int *stack_node, float *stack_t)
{
	hit h = { INFINITY, -1, 0, 0 };
	float t_entry;
	if (t->n_prims == 0 || !slab(&t->nodes[0], r, h.t, &t_entry))
		return h;
	int sp = 0, node = 0;
	while (node >= 0) {
		const bvh_node *n = &t->nodes[node];
		h.visits++;
		if (n->count > 0) {
			for (int i = 0; i < n->count; i++) {
				int p = t->prim_index[n->left_first + i];
				float tt;
				h.tests++;
				if (intersect(r, &tris[p], h.t, &tt)) {
					h.t = tt;
					h.prim = p;
				}
			}
			node = pop(stack_node, stack_t, &sp, h.t);
			continue;
		}
		int l = n->left_first, rr = l + 1;
		float tl, tr;
		int hl = slab(&t->nodes[l], r, h.t, &tl);
		int hr = slab(&t->nodes[rr], r, h.t, &tr);
		if (hl && hr) {
			int near = tr < tl ? rr : l;
			stack_node[sp] = near == l ? rr : l;
			stack_t[sp++] = near == l ? tr : tl;
			node = near;
		} else if (hl || hr) {
			node = hl ? l : rr;
		} else {
			node = pop(stack_node, stack_t, &sp, h.t);
		}
	}
	return h;
}

/* The wide layout's traversal (kernels/traverse.cl mirrors it): child boxes
 * dequantized exactly as the kernel does, hit children sorted by entry
 * distance, the nearest visited first, the others stacked. */
static void qbound(const bvh_wnode *n, int k, int hi, float b[3])
{
	const float origin[3] = { n->origin_x, n->origin_y, n->origin_z };
	const uint q[3] = { hi ? n->qhi_x : n->qlo_x, hi ? n->qhi_y : n->qlo_y, hi ? n->qhi_z : n->qlo_z };
	for (int a = 0; a < 3; a++) {
		uint bits = ((n->meta >> (8 * a)) & 255u) << 23;
		float step;
		memcpy(&step, &bits, sizeof step);
		b[a] = origin[a] + (float)((q[a] >> (8 * k)) & 255u) * step;
	}
}

static hit traverse_wide(const bvh_wide *w, const bvh_tree *t, const tri *tris, const ray *r)
{
	hit h = { INFINITY, -1, 0, 0 };
	int stack[BVH_STACK_SIZE], sp = 0, ref = w->roots[0];
	float tstack[BVH_STACK_SIZE];
	if (t->n_prims == 0)
		return h;
	for (;;) {
		if (ref < 0) {
			int first = ref & ((1 << BVH_WIDE_FIRST_BITS) - 1);
			int end = first + ((ref >> BVH_WIDE_FIRST_BITS) & BVH_WIDE_LEAF_MAX);
			for (int i = first; i < end; i++) {
				int p = t->prim_index[i];
				float tt;
				h.tests++;
				if (intersect(r, &tris[p], h.t, &tt)) {
					h.t = tt;
					h.prim = p;
				}
			}
		} else {
			const bvh_wnode *n = &w->nodes[ref];
			int nc = (int)(n->meta >> 24), nh = 0, hc[4];
			float ht[4];
			h.visits++;
			for (int k = 0; k < nc; k++) {
				float lo[3], hi[3], te;
				qbound(n, k, 0, lo);
				qbound(n, k, 1, hi);
				bvh_node b = { lo[0], lo[1], lo[2], 0, hi[0], hi[1], hi[2], 0 };
				if (!slab(&b, r, h.t, &te))
					continue;
				int j = nh++;
				for (; j > 0 && ht[j - 1] < te; j--) {
					ht[j] = ht[j - 1];
					hc[j] = hc[j - 1];
				}
				ht[j] = te;
				hc[j] = n->child[k];
			}
			if (nh > 0) {
				if (sp + nh - 1 > BVH_STACK_SIZE) {
					h.prim = -2;   /* reported as a mismatch */
					return h;
				}
				for (int j = 0; j < nh - 1; j++) {
					stack[sp] = hc[j];
					tstack[sp++] = ht[j];
				}
				ref = hc[nh - 1];
				continue;
			}
		}
		for (;;) {
			if (sp == 0)
				return h;
			sp--;
			if (tstack[sp] <= h.t * BOX_PAD) {
				ref = stack[sp];
				break;
			}
		}
	}
}

static hit brute_force(const tri *tris, int n, const ray *r)
{
	hit h = { INFINITY, -1, 0, n };
	for (int i = 0; i < n; i++) {
		float tt;
		if (intersect(r, &tris[i], h.t, &tt)) {
			h.t = tt;
			h.prim = i;
		}
	}
	return h;
}

/* ---- reporting ---- */

static int n_errors;

/* Counts an error and prints the first few. */
static void fail(const char *fmt, ...)
{
	if (n_errors++ >= MAX_REPORTED) {
		if (n_errors == MAX_REPORTED + 1)
			printf("  (further errors not shown)\n");
		return;
	}
	va_list ap;
	va_start(ap, fmt);
	printf("  FAIL: ");
	vprintf(fmt, ap);
	printf("\n");
	va_end(ap);
}

/* ---- structural checks ---- */

static bvh_box node_box(const bvh_node *n)
{
	bvh_box b = { { n->min_x, n->min_y, n->min_z }, { n->max_x, n->max_y, n->max_z } };
	return b;
}

static int box_contains(const bvh_box *outer, const bvh_box *inner)
{
	for (int a = 0; a < 3; a++)
		if (!(outer->min[a] <= inner->min[a] && inner->max[a] <= outer->max[a]))
			return 0;
	return 1;
}

/* Rejects NaN, inverted boxes and infinities alike. */
static int box_sane(const bvh_box *b)
{
	for (int a = 0; a < 3; a++)
		if (!(b->min[a] <= b->max[a]) || !isfinite(b->min[a]) || !isfinite(b->max[a]))
			return 0;
	return 1;
}

static double area(const bvh_box *b)
{
	double d[3];
	for (int a = 0; a < 3; a++)
		d[a] = (double)b->max[a] - b->min[a];
	return 2.0 * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
}

static void check_leaf(const bvh_tree *t, int node, const bvh_box *boxes, int n, int *seen)
{
	const bvh_node *nd = &t->nodes[node];
	bvh_box b = node_box(nd);
	if (nd->count > BVH_MAX_LEAF || nd->left_first < 0 || nd->left_first + nd->count > t->n_prims) {
		fail("leaf %d: count %d, first %d out of range", node, nd->count, nd->left_first);
		return;
	}
	for (int i = 0; i < nd->count; i++) {
		int p = t->prim_index[nd->left_first + i];
		if (p < 0 || p >= n) {
			fail("leaf %d: primitive index %d out of range", node, p);
			continue;
		}
		seen[p]++;
		if (!box_contains(&b, &boxes[p]))
			fail("leaf %d does not contain the box of primitive %d", node, p);
	}
}

/* Returns the child index, or -1 after reporting why the node is broken.
 * Children must come after their parent, which also rules out cycles. */
static int check_interior(const bvh_tree *t, int node)
{
	const bvh_node *nd = &t->nodes[node];
	int l = nd->left_first;
	if (nd->count < 0 || l <= node || l + 1 >= t->n_nodes) {
		fail("node %d: count %d, children %d out of range", node, nd->count, l);
		return -1;
	}
	bvh_box b = node_box(nd);
	for (int c = l; c <= l + 1; c++) {
		bvh_box cb = node_box(&t->nodes[c]);
		if (!box_contains(&b, &cb))
			fail("node %d does not contain its child %d", node, c);
	}
	return l;
}

/* Walks the tree from the root: every node once, every primitive once, boxes
 * nested, depth and SAH cost as recomputed here. */
static void check_tree(const bvh_tree *t, const bvh_box *boxes, int n)
{
	if (n == 0) {
		if (t->n_nodes != 1 || t->n_prims != 0 || t->nodes[0].count != 0 || t->nodes[0].left_first != 0)
			fail("empty tree: %d nodes, %d prims", t->n_nodes, t->n_prims);
		return;
	}
	if (t->n_prims != n || t->n_nodes < 1 || t->n_nodes > 2 * n - 1) {
		fail("tree of %d prims has %d nodes and n_prims %d", n, t->n_nodes, t->n_prims);
		return;
	}
	int *seen = calloc((size_t)n, sizeof *seen);
	char *reached = calloc((size_t)t->n_nodes, 1);
	int *stack = malloc((size_t)t->n_nodes * 2 * sizeof *stack);
	if (!seen || !reached || !stack) {
		fail("out of memory in check_tree");
		goto done;
	}
	int sp = 0, max_depth = 0, n_reached = 0;
	bvh_box root = node_box(&t->nodes[0]);
	double sah = 0.0, root_area = area(&root);
	stack[sp++] = 0;
	stack[sp++] = 1;
	while (sp > 0) {
		int depth = stack[--sp], node = stack[--sp];
		if (reached[node]++) {
			fail("node %d reached twice", node);
			continue;
		}
		n_reached++;
		max_depth = depth > max_depth ? depth : max_depth;
		const bvh_node *nd = &t->nodes[node];
		bvh_box b = node_box(nd);
		if (!box_sane(&b))
			fail("node %d has a NaN, infinite or inverted box", node);
		double ratio = root_area > 0.0 ? area(&b) / root_area : 1.0;
		sah += nd->count > 0 ? ratio * nd->count : ratio;
		if (nd->count > 0) {
			check_leaf(t, node, boxes, n, seen);
			continue;
		}
		int l = check_interior(t, node);
		if (l < 0 || sp + 4 > 2 * t->n_nodes)
			continue;
		stack[sp++] = l;
		stack[sp++] = depth + 1;
		stack[sp++] = l + 1;
		stack[sp++] = depth + 1;
	}
	for (int p = 0; p < n; p++)
		if (seen[p] != 1)
			fail("primitive %d appears %d times in leaves", p, seen[p]);
	if (n_reached != t->n_nodes)
		fail("%d of %d nodes reachable from the root", n_reached, t->n_nodes);
	if (max_depth != t->depth)
		fail("depth %d, recomputed %d", t->depth, max_depth);
	if (!(fabs(sah - t->sah_cost) <= 1e-4 * sah))
		fail("sah_cost %.6f, recomputed %.6f", t->sah_cost, sah);
done:
	free(seen);
	free(reached);
	free(stack);
}

/* ---- the property check: BVH closest hit == brute-force closest hit ---- */

typedef struct {
	int rays, hits, flagged, flagged_hits;
	long long visits, tests;
	double ms_bvh;
} stats;

/* Equal when both miss, or both hit at bitwise the same distance; a different
 * primitive is accepted only if it really hits at that same distance (a tie). */
static int same_hit(const hit *a, const hit *b, const tri *tris, const ray *r)
{
	if (a->prim < 0 || b->prim < 0)
		return a->prim == b->prim;
	if (memcmp(&a->t, &b->t, sizeof a->t) != 0)
		return 0;
	if (a->prim == b->prim)
		return 1;
	float tt;
	return intersect(r, &tris[a->prim], INFINITY, &tt) && memcmp(&tt, &a->t, sizeof tt) == 0;
}

/* flags (may be NULL) marks rays whose hits are counted separately. */
static void check_rays(const bvh_tree *t, const tri *tris, int n, const ray *rays, int n_rays,
		       const char *flags, stats *st)
{
	int depth = t->depth > 0 ? t->depth : 1;
	int *stack_node = malloc((size_t)depth * sizeof *stack_node);
	float *stack_t = malloc((size_t)depth * sizeof *stack_t);
	hit *got = malloc((size_t)n_rays * sizeof *got);
	memset(st, 0, sizeof *st);
	if (!stack_node || !stack_t || !got) {
		fail("out of memory in check_rays");
		goto done;
	}
	double t0 = now_ms();
	for (int i = 0; i < n_rays; i++)
		got[i] = traverse(t, tris, &rays[i], stack_node, stack_t);
	st->ms_bvh = now_ms() - t0;
	int root = 0;
	bvh_wide w;
	if (bvh_widen(t->nodes, &root, 1, NULL, 0, &w) != 0) {
		fail("bvh_widen failed");
		goto done;
	}
	for (int i = 0; i < n_rays && t->n_prims > 0; i++) {
		hit wide = traverse_wide(&w, t, tris, &rays[i]);
		if (!same_hit(&wide, &got[i], tris, &rays[i]))
			fail("ray %d: wide layout t %.9g prim %d, binary t %.9g prim %d", i, wide.t, wide.prim,
			     got[i].t, got[i].prim);
	}
	bvh_wide_free(&w);
	for (int i = 0; i < n_rays; i++) {
		hit want = brute_force(tris, n, &rays[i]);
		const ray *r = &rays[i];
		st->rays++;
		st->hits += want.prim >= 0;
		st->visits += got[i].visits;
		st->tests += got[i].tests;
		if (flags && flags[i]) {
			st->flagged++;
			st->flagged_hits += want.prim >= 0;
		}
		if (!same_hit(&got[i], &want, tris, r))
			fail("ray %d o (%.9g %.9g %.9g) d (%a %a %a): bvh t %.9g prim %d, brute force t %.9g prim %d",
			     i, r->o[0], r->o[1], r->o[2], r->d[0], r->d[1], r->d[2],
			     got[i].t, got[i].prim, want.t, want.prim);
	}
done:
	free(stack_node);
	free(stack_t);
	free(got);
}

static void print_stats(const char *name, const stats *st)
{
	printf("  %s: %d rays, %d hits, %.2f node visits/ray, %.2f triangle tests/ray, traversal %.1f ms\n",
	       name, st->rays, st->hits, (double)st->visits / st->rays, (double)st->tests / st->rays, st->ms_bvh);
	if (st->flagged)
		printf("  %s: %d rays in an axis plane through a vertex or edge (0 * inf in the slab test), %d hit\n",
		       name, st->flagged, st->flagged_hits);
}

/* ---- building ---- */

static bvh_box *make_boxes(const tri *tris, int n)
{
	bvh_box *boxes = malloc((size_t)(n > 0 ? n : 1) * sizeof *boxes);
	for (int i = 0; boxes && i < n; i++)
		boxes[i] = tri_box(&tris[i]);
	return boxes;
}

static void box_from_boxes(const void *ctx, int i, bvh_box *out)
{
	*out = ((const bvh_box *)ctx)[i];
}

/* Builds (best time of a few builds when timing matters), checks the
 * structure and prints the tree's figures. Returns 0 with the tree in *t, or
 * -1 with nothing to free. */
static int build_checked(const char *name, const tri *tris, int n, int repeats, bvh_tree *t)
{
	bvh_box *boxes = make_boxes(tris, n);
	if (!boxes) {
		fail("%s: out of memory", name);
		return -1;
	}
	double best = INFINITY;
	int rc = 0;
	for (int k = 0; k < repeats && rc == 0; k++) {
		if (k > 0)
			bvh_free(t);
		double t0 = now_ms();
		rc = bvh_build(boxes, n, t);
		double ms = now_ms() - t0;
		best = ms < best ? ms : best;
	}
	if (rc != 0) {
		fail("%s: bvh_build returned %d", name, rc);
		free(boxes);
		return -1;
	}
	int before = n_errors;
	check_tree(t, boxes, n);
	printf("  %s: %d triangles, %d nodes, depth %d, SAH cost %.3f, build %.2f ms%s\n", name, n,
	       t->n_nodes, t->depth, t->sah_cost, best, n_errors == before ? ", structure ok" : "");
	free(boxes);
	if (n_errors == before)
		return 0;
	bvh_free(t);
	return -1;
}

/* ---- random soups ---- */

static void random_point(rng *r, float p[3])
{
	for (int a = 0; a < 3; a++)
		p[a] = rng_f(r);
}

static float clamp01(float x)
{
	return x < 0.0f ? 0.0f : (x > 1.0f ? 1.0f : x);
}

/* Vertex near c, up to size away on each axis, kept in the unit cube. */
static void near_point(rng *r, const float c[3], float size, float p[3])
{
	for (int a = 0; a < 3; a++)
		p[a] = clamp01(c[a] + rng_range(r, -size, size));
}

/* A triangle with an edge in the plane axis = c, where c is on a 1/64 grid,
 * and its third vertex off that plane: the plane is then a face of the
 * triangle's box, and rays lying in it can hit the edge. */
static void edge_on_plane(rng *r, tri *t, int axis)
{
	float c = (float)(1 + rng_int(r, 62)) / 64.0f, centre[3];
	random_point(r, centre);
	for (int k = 0; k < 3; k++)
		near_point(r, centre, 0.05f, t->v[k]);
	t->v[0][axis] = c;
	t->v[1][axis] = c;
	t->v[2][axis] = c + (rng_f(r) < 0.5f ? -1.0f : 1.0f) * rng_range(r, 0.002f, 0.05f);
}

/* Random soup in the unit cube: about 3% with two identical vertices, 3%
 * collinear (half exactly, along an axis), 3% with all vertices identical, 6%
 * flat in z, 3% flat in x or y, 4% edge_on_plane (axis noted in edge_axis[]),
 * the rest ordinary triangles of assorted sizes. */
static void make_soup(rng *r, tri *tris, int n, signed char *edge_axis)
{
	for (int i = 0; i < n; i++) {
		tri *t = &tris[i];
		float u = rng_f(r), centre[3], size = 0.002f + 0.06f * rng_f(r) * rng_f(r);
		if (rng_f(r) < 0.01f)
			size = 0.5f;
		random_point(r, centre);
		for (int k = 0; k < 3; k++)
			near_point(r, centre, size, t->v[k]);
		edge_axis[i] = -1;
		if (u < 0.03f) {
			memcpy(t->v[1], t->v[0], sizeof t->v[0]);
		} else if (u < 0.045f) {
			int a = rng_int(r, 3);
			memcpy(t->v[1], t->v[0], sizeof t->v[0]);
			memcpy(t->v[2], t->v[0], sizeof t->v[0]);
			t->v[1][a] = clamp01(t->v[0][a] + size);
			t->v[2][a] = clamp01(t->v[0][a] - size);
		} else if (u < 0.06f) {
			float s = rng_range(r, -0.5f, 1.5f);
			for (int a = 0; a < 3; a++)
				t->v[2][a] = t->v[0][a] + s * (t->v[1][a] - t->v[0][a]);
		} else if (u < 0.09f) {
			memcpy(t->v[1], t->v[0], sizeof t->v[0]);
			memcpy(t->v[2], t->v[0], sizeof t->v[0]);
		} else if (u < 0.15f) {
			t->v[1][2] = t->v[2][2] = t->v[0][2];
		} else if (u < 0.18f) {
			int a = rng_int(r, 2);
			t->v[1][a] = t->v[2][a] = t->v[0][a];
		} else if (u < 0.22f) {
			edge_axis[i] = (signed char)rng_int(r, 3);
			edge_on_plane(r, t, edge_axis[i]);
		}
		tri_finish(t);
	}
}

static void random_direction(rng *r, float d[3])
{
	float z = rng_range(r, -1.0f, 1.0f), phi = 6.2831853f * rng_f(r);
	float s = sqrtf(fmaxf(0.0f, 1.0f - z * z));
	d[0] = s * cosf(phi);
	d[1] = s * sinf(phi);
	d[2] = z;
}

/* Outside the unit cube, at most 3 away from it. */
static void outside_point(rng *r, float p[3])
{
	for (;;) {
		float d2 = 0.0f;
		for (int a = 0; a < 3; a++) {
			p[a] = rng_range(r, -3.0f, 4.0f);
			float e = p[a] < 0.0f ? -p[a] : (p[a] > 1.0f ? p[a] - 1.0f : 0.0f);
			d2 += e * e;
		}
		if (d2 > 0.0f && d2 <= 9.0f)
			return;
	}
}

/* A zero of random sign: -0 gives 1/d = -inf, the other half of the cases. */
static float signed_zero(rng *r)
{
	return rng_f(r) < 0.5f ? 0.0f : -0.0f;
}

/* A ray lying in a face plane of some triangle's box: either along the
 * edge_on_plane edge (so it can hit it through the NaN case of the slab test)
 * or through a vertex in one of its coordinate planes. */
static ray plane_ray(rng *r, const tri *tris, int n, const signed char *edge_axis)
{
	int i = rng_int(r, n), axis = rng_int(r, 3), v = rng_int(r, 3);
	float target[3], o[3], d[3];
	for (int k = 0; k < 50 && edge_axis[i] < 0; k++)
		i = rng_int(r, n);
	if (edge_axis[i] >= 0) {
		float s = rng_f(r);
		axis = edge_axis[i];
		for (int a = 0; a < 3; a++)
			target[a] = tris[i].v[0][a] + s * (tris[i].v[1][a] - tris[i].v[0][a]);
		target[axis] = tris[i].v[0][axis];
	} else {
		memcpy(target, tris[i].v[v], sizeof target);
	}
	for (int a = 0; a < 3; a++)
		o[a] = target[a] + rng_range(r, -2.0f, 2.0f);
	o[axis] = target[axis];
	sub3(d, target, o);
	d[axis] = signed_zero(r);
	return make_ray(o, d);
}

/* Directions exactly along an axis (two zero components) or in a coordinate
 * plane (one zero component). */
static ray axis_ray(rng *r, int zeros)
{
	float o[3], d[3], target[3];
	if (rng_f(r) < 0.5f)
		random_point(r, o);
	else
		outside_point(r, o);
	random_point(r, target);
	sub3(d, target, o);
	int keep = rng_int(r, 3);
	for (int a = 0; a < 3; a++) {
		int zero = zeros == 2 ? a != keep : a == keep;
		if (zero) {
			o[a] = target[a];
			d[a] = signed_zero(r);
		}
	}
	if (zeros == 2 && d[keep] == 0.0f)
		d[keep] = 1.0f;
	return make_ray(o, d);
}

/* A random point of the triangle (by barycentric coordinates). */
static void point_on_tri(rng *r, const tri *t, float p[3])
{
	float u = rng_f(r), v = rng_f(r);
	if (u + v > 1.0f) {
		u = 1.0f - u;
		v = 1.0f - v;
	}
	for (int a = 0; a < 3; a++)
		p[a] = t->v[0][a] + u * (t->v[1][a] - t->v[0][a]) + v * (t->v[2][a] - t->v[0][a]);
}

static ray soup_ray(rng *r, const tri *tris, int n, const signed char *edge_axis, char *flag)
{
	float u = rng_f(r), o[3], d[3];
	*flag = 0;
	if (u < 0.35f) {
		random_point(r, o);
		random_direction(r, d);
	} else if (u < 0.55f) {
		outside_point(r, o);
		random_direction(r, d);
	} else if (u < 0.62f) {
		float target[3];
		outside_point(r, o);
		random_point(r, target);
		sub3(d, target, o);
	} else if (u < 0.72f) {
		float target[3];
		if (rng_f(r) < 0.5f)
			random_point(r, o);
		else
			outside_point(r, o);
		point_on_tri(r, &tris[rng_int(r, n)], target);
		sub3(d, target, o);
	} else if (u < 0.82f) {
		return axis_ray(r, 2);
	} else if (u < 0.90f) {
		return axis_ray(r, 1);
	} else {
		*flag = 1;
		return plane_ray(r, tris, n, edge_axis);
	}
	return make_ray(o, d);
}

/* The textbook fmin(t1, t2) / fmax(t1, t2) slab test, only to show in
 * check_slab which boundary cases it gets wrong. */
static int naive_slab(const bvh_node *b, const ray *r, float closest)
{
	const float lo[3] = { b->min_x, b->min_y, b->min_z };
	const float hi[3] = { b->max_x, b->max_y, b->max_z };
	float t_near = 0.0f, t_far = closest;
	for (int a = 0; a < 3; a++) {
		float t1 = (lo[a] - r->o[a]) * r->inv[a], t2 = (hi[a] - r->o[a]) * r->inv[a];
		t_near = fmaxf(t_near, fminf(t1, t2));
		t_far = fminf(t_far, fmaxf(t1, t2));
	}
	return t_near <= t_far * BOX_PAD;
}

/* Unit cases for the slab test around the 0 * inf = NaN corner, against the
 * box [0,1]^3 and the flat box x = 0.5. */
static void check_slab(void)
{
	static const struct {
		float box[6], o[3], d[3];
		int expect;
	} cases[] = {
		{ { 0, 0, 0, 1, 1, 1 }, { 0, 0.5f, -1 }, { 0, 0, 1 }, 1 },     /* in the x = min face */
		{ { 0, 0, 0, 1, 1, 1 }, { 0, 0.5f, -1 }, { -0.0f, 0, 1 }, 1 },
		{ { 0, 0, 0, 1, 1, 1 }, { 1, 0.5f, -1 }, { 0, 0, 1 }, 1 },     /* in the x = max face */
		{ { 0, 0, 0, 1, 1, 1 }, { 1, 0.5f, -1 }, { -0.0f, 0, 1 }, 1 },
		{ { 0, 0, 0, 1, 1, 1 }, { 0, 0, -1 }, { 0, 0, 1 }, 1 },        /* along an edge */
		{ { 0, 0, 0, 1, 1, 1 }, { 1, 1, 2 }, { 0, -0.0f, -1 }, 1 },
		{ { 0.5f, 0, 0, 0.5f, 1, 1 }, { 0.5f, 0.5f, -1 }, { 0, 0, 1 }, 1 },   /* in a flat box */
		{ { 0.5f, 0, 0, 0.5f, 1, 1 }, { 0.5f, 0.5f, -1 }, { -0.0f, 0, 1 }, 1 },
		{ { 0.5f, 0, 0, 0.5f, 1, 1 }, { -1, 0.5f, 0.5f }, { 1, 0, 0 }, 1 },   /* through a flat box */
		{ { 0, 0, 0, 1, 1, 1 }, { 0.5f, 0.5f, 0.5f }, { 0, 0, 1 }, 1 },       /* from inside */
		{ { 0, 0, 0, 1, 1, 1 }, { -0.1f, 0.5f, -1 }, { 0, 0, 1 }, 0 },  /* beside the slab */
		{ { 0, 0, 0, 1, 1, 1 }, { 1.1f, 0.5f, -1 }, { -0.0f, 0, 1 }, 0 },
		{ { 0, 0, 0, 1, 1, 1 }, { 0.5f, 0.5f, 2 }, { 0, 0, 1 }, 0 },    /* box behind */
		{ { 0.5f, 0, 0, 0.5f, 1, 1 }, { 0.4f, 0.5f, -1 }, { 0, 0, 1 }, 0 },
	};
	int n = (int)(sizeof cases / sizeof cases[0]), ok = 0, naive_ok = 0;
	for (int i = 0; i < n; i++) {
		const float *b = cases[i].box;
		bvh_node node = { b[0], b[1], b[2], 0, b[3], b[4], b[5], 1 };
		ray r = make_ray(cases[i].o, cases[i].d);
		float t;
		int got = slab(&node, &r, INFINITY, &t);
		naive_ok += naive_slab(&node, &r, INFINITY) == cases[i].expect;
		if (got != cases[i].expect || isnan(t))
			fail("slab case %d: got %d, expected %d (t %g)", i, got, cases[i].expect, t);
		else
			ok++;
	}
	printf("slab test: %d of %d boundary cases ok (the fmin(t1, t2) form: %d of %d)\n", ok, n, naive_ok, n);
}

/* Builds over tris (in the unit cube), checks the structure and n_rays soup
 * rays. */
static void run_case(const char *name, rng *r, const tri *tris, int n, const signed char *edge_axis,
		     int n_rays, int repeats)
{
	ray *rays = malloc((size_t)n_rays * sizeof *rays);
	char *flags = malloc((size_t)n_rays);
	bvh_tree t;
	stats st;
	if (!rays || !flags) {
		fail("%s: out of memory", name);
		goto done;
	}
	if (build_checked(name, tris, n, repeats, &t) != 0)
		goto done;
	for (int i = 0; i < n_rays; i++)
		rays[i] = soup_ray(r, tris, n, edge_axis, &flags[i]);
	check_rays(&t, tris, n, rays, n_rays, flags, &st);
	print_stats(name, &st);
	bvh_free(&t);
done:
	free(rays);
	free(flags);
}

static void soup_test(const char *name, rng *r, int n, int n_rays, int repeats)
{
	tri *tris = malloc((size_t)n * sizeof *tris);
	signed char *edge_axis = malloc((size_t)n);
	if (!tris || !edge_axis)
		fail("%s: out of memory", name);
	else {
		make_soup(r, tris, n, edge_axis);
		run_case(name, r, tris, n, edge_axis, n_rays, repeats);
	}
	free(tris);
	free(edge_axis);
}

/* One triangle of an arrangement where binning cannot help: kind 0, the
 * same triangle every time (all centroids coincide, every hit is a tie);
 * kind 1, all in the plane z = 0.5 (a flat root); kind 2, all on the line
 * y = z = 0.5 (degenerate, a root of area 0). */
static void shape_tri(rng *r, int kind, tri *t)
{
	static const float same[3][3] = { { 0.2f, 0.3f, 0.4f }, { 0.8f, 0.35f, 0.5f }, { 0.5f, 0.9f, 0.6f } };
	float centre[3];
	random_point(r, centre);
	for (int k = 0; k < 3; k++) {
		near_point(r, centre, 0.05f, t->v[k]);
		if (kind == 0)
			memcpy(t->v[k], same[k], sizeof same[k]);
		else if (kind == 1)
			t->v[k][2] = 0.5f;
		else
			t->v[k][1] = t->v[k][2] = 0.5f;
	}
	tri_finish(t);
}

static void shape_tests(rng *r)
{
	static const char *names[3] = { "coincident", "coplanar", "collinear" };
	enum { N = 1000 };
	tri *tris = malloc(N * sizeof *tris);
	signed char edge_axis[N];
	memset(edge_axis, -1, sizeof edge_axis);
	if (!tris) {
		fail("shapes: out of memory");
		return;
	}
	for (int kind = 0; kind < 3; kind++) {
		for (int i = 0; i < N; i++)
			shape_tri(r, kind, &tris[i]);
		run_case(names[kind], r, tris, N, edge_axis, 20000, 1);
	}
	free(tris);
}

/* The build splits its work between threads (bvh.c): the tree must be the
 * same bit for bit with any number of threads and whatever their timing, so
 * the same soup is built on 1 to 4 threads, several times each. 100,000
 * triangles make dozens of tasks and bin the top nodes on two threads. */
static void determinism_test(rng *r)
{
	enum { N = 100000 };
	tri *tris = malloc(N * sizeof *tris);
	signed char *edge_axis = malloc(N);
	bvh_box *boxes = NULL;
	bvh_tree ref = { 0 }, t;
	if (!tris || !edge_axis) {
		fail("determinism: out of memory");
		goto done;
	}
	make_soup(r, tris, N, edge_axis);
	boxes = make_boxes(tris, N);
	if (!boxes || bvh_build_threads(boxes, N, 1, &ref) != 0) {
		fail("determinism: build failed");
		goto done;
	}
	int builds = 0;
	for (int threads = 1; threads <= 4; threads++)
		for (int k = 0; k < 3; k++, builds++) {
			if (bvh_build_threads(boxes, N, threads, &t) != 0) {
				fail("determinism: build on %d threads failed", threads);
				continue;
			}
			if (t.n_nodes != ref.n_nodes || t.depth != ref.depth ||
			    memcmp(t.nodes, ref.nodes, (size_t)t.n_nodes * sizeof *t.nodes) != 0 ||
			    memcmp(t.prim_index, ref.prim_index, (size_t)N * sizeof *t.prim_index) != 0)
				fail("determinism: the tree built on %d threads differs from the one-thread tree",
				     threads);
			bvh_free(&t);
		}
	printf("  %d builds of %d triangles on 1 to 4 threads: %d nodes each%s\n", builds, N, ref.n_nodes,
	       n_errors ? "" : ", all identical");
done:
	bvh_free(&ref);
	free(boxes);
	free(tris);
	free(edge_axis);
}

/* The primitives under node, at most max + 1 of them into out (enough to
 * tell a subtree of more than max). Returns how many were written. */
static int collect(const bvh_tree *t, int node, int *out, int n, int max)
{
	const bvh_node *nd = &t->nodes[node];
	if (nd->count > 0) {
		for (int i = 0; i < nd->count && n <= max; i++)
			out[n++] = t->prim_index[nd->left_first + i];
		return n;
	}
	n = collect(t, nd->left_first, out, n, max);
	return n > max ? n : collect(t, nd->left_first + 1, out, n, max);
}

static int by_int(const void *a, const void *b)
{
	return *(const int *)a - *(const int *)b;
}

/* Whether the subtree of cut's node b is full's node a with every subtree of
 * at most four primitives made one leaf over the same primitives. */
static int cut_matches(const bvh_tree *full, int a, const bvh_tree *cut, int b)
{
	const bvh_node *na = &full->nodes[a], *nb = &cut->nodes[b];
	int pa[BVH_MAX_LEAF + 1], pb[BVH_MAX_LEAF + 1];
	int ka = collect(full, a, pa, 0, BVH_MAX_LEAF), kb = collect(cut, b, pb, 0, BVH_MAX_LEAF);
	bvh_box ba = node_box(na), bb = node_box(nb);
	if (memcmp(&ba, &bb, sizeof ba) != 0)
		return 0;
	if (nb->count > 0) {
		qsort(pa, ka, sizeof *pa, by_int);
		qsort(pb, kb, sizeof *pb, by_int);
		return ka <= BVH_MAX_LEAF && ka == kb && memcmp(pa, pb, ka * sizeof *pa) == 0;
	}
	return na->count == 0 && ka > BVH_MAX_LEAF && kb > BVH_MAX_LEAF &&
	       cut_matches(full, na->left_first, cut, nb->left_first) &&
	       cut_matches(full, na->left_first + 1, cut, nb->left_first + 1);
}

/* bvh_build_leaves(..., 4, ...), the lowering's build of a mesh for the wide
 * layout: bvh_build's tree with each subtree of at most four primitives cut
 * to one leaf (the decisions above are the same on the same ranges), so the
 * wide layout's blocks hold the same triangles; then the structure and the
 * rays, as for any tree. A soup, and coincident triangles (every split a
 * fallback). */
static void leaves_test(rng *r)
{
	enum { N = 20000 };
	tri *tris = malloc(N * sizeof *tris);
	signed char *edge_axis = malloc(N);
	ray *rays = malloc(N * sizeof *rays);
	char *flags = malloc(N);
	bvh_box *boxes = NULL;
	if (!tris || !edge_axis || !rays || !flags) {
		fail("leaves: out of memory");
		goto done;
	}
	for (int kind = 0; kind < 2; kind++) {
		const char *name = kind ? "coincident, leaves of up to 4" : "soup, leaves of up to 4";
		if (kind == 0)
			make_soup(r, tris, N, edge_axis);
		for (int i = 0; kind == 1 && i < N; i++) {
			shape_tri(r, 0, &tris[i]);
			edge_axis[i] = -1;
		}
		free(boxes);
		boxes = make_boxes(tris, N);
		bvh_tree full, cut;
		if (!boxes || bvh_build(boxes, N, &full) != 0) {
			fail("%s: bvh_build failed", name);
			continue;
		}
		if (bvh_build_leaves(box_from_boxes, boxes, N, 4, &cut) != 0) {
			fail("%s: bvh_build_leaves failed", name);
			bvh_free(&full);
			continue;
		}
		int before = n_errors;
		check_tree(&cut, boxes, N);
		if (!cut_matches(&full, 0, &cut, 0))
			fail("%s: not bvh_build's tree with its subtrees of four or fewer cut to leaves", name);
		for (int i = 0; i < N; i++)
			rays[i] = soup_ray(r, tris, N, edge_axis, &flags[i]);
		stats st;
		check_rays(&cut, tris, N, rays, N, flags, &st);
		printf("  %s: %d nodes (bvh_build: %d)%s\n", name, cut.n_nodes, full.n_nodes,
		       n_errors == before ? ", bvh_build's tree cut, rays ok" : "");
		bvh_free(&full);
		bvh_free(&cut);
	}
	bvh_tree t;
	if (bvh_build_leaves(box_from_boxes, boxes, N, 0, &t) != -1 || t.nodes ||
	    bvh_build_leaves(box_from_boxes, boxes, N, BVH_MAX_LEAF + 1, &t) != -1 || t.nodes)
		fail("leaves: bvh_build_leaves accepts leaves of 0 or more than BVH_MAX_LEAF");
done:
	free(boxes);
	free(tris);
	free(edge_axis);
	free(rays);
	free(flags);
}

/* n == 0, and the arguments bvh_build must refuse (leaving t zeroed). */
static void empty_test(void)
{
	bvh_tree t;
	bvh_box box = { { 0, 0, 0 }, { 1, 1, 1 } };
	if (bvh_build(&box, -1, &t) != -1 || t.nodes || t.prim_index || t.n_nodes)
		fail("n = -1 was not refused with an empty tree");
	if (bvh_build(NULL, 3, &t) != -1 || t.nodes || t.prim_index || t.n_nodes)
		fail("boxes = NULL was not refused with an empty tree");
	if (bvh_build(NULL, 0, &t) != 0) {
		fail("n = 0: bvh_build failed");
		return;
	}
	check_tree(&t, NULL, 0);
	ray r = make_ray((const float[3]){ 0, 0, -1 }, (const float[3]){ 0, 0, 1 });
	hit h = traverse(&t, NULL, &r, NULL, NULL);
	if (h.prim != -1)
		fail("n = 0: a ray hit the empty tree");
	bvh_free(&t);
	if (t.nodes || t.prim_index || t.n_nodes || t.n_prims)
		fail("bvh_free did not zero the tree");
	printf("  n=0: %s\n", "one empty node, every ray misses");
}

/* ---- OBJ meshes ---- */

typedef struct {
	float (*v)[3];
	int n_v, cap_v;
	tri *t;
	int n_t, cap_t;
} mesh;

/* Room for index need: returns p, or a bigger block (*cap updated), or NULL
 * when out of memory (p is then still valid). */
static void *grow(void *p, int *cap, int need, size_t elem)
{
	if (need < *cap)
		return p;
	int c = *cap ? *cap : 1024;
	while (c <= need)
		c *= 2;
	void *q = realloc(p, (size_t)c * elem);
	if (q)
		*cap = c;
	return q;
}

static int obj_vertex(mesh *m, const char *s)
{
	char *end;
	float x[3];
	for (int a = 0; a < 3; a++) {
		x[a] = strtof(s, &end);
		if (end == s)
			return -1;
		s = end;
	}
	void *q = grow(m->v, &m->cap_v, m->n_v, sizeof *m->v);
	if (!q)
		return -1;
	m->v = q;
	memcpy(m->v[m->n_v++], x, sizeof x);
	return 0;
}

/* "f a b c ...", each corner "i", "i/j", "i//k" or "i/j/k"; polygons are
 * split into a fan. Negative indices count back from the last vertex. */
static int obj_face(mesh *m, const char *s)
{
	int idx[64], n = 0;
	for (;;) {
		while (*s == ' ' || *s == '\t')
			s++;
		if (*s == '\0' || *s == '\n' || *s == '\r')
			break;
		char *end;
		long i = strtol(s, &end, 10);
		if (end == s || n == 64)
			return -1;
		i = i < 0 ? m->n_v + i : i - 1;
		if (i < 0 || i >= m->n_v)
			return -1;
		idx[n++] = (int)i;
		s = end;
		while (*s && *s != ' ' && *s != '\t' && *s != '\n' && *s != '\r')
			s++;
	}
	if (n < 3)
		return -1;
	for (int k = 2; k < n; k++) {
		void *q = grow(m->t, &m->cap_t, m->n_t, sizeof *m->t);
		if (!q)
			return -1;
		m->t = q;
		tri *t = &m->t[m->n_t++];
		memcpy(t->v[0], m->v[idx[0]], sizeof t->v[0]);
		memcpy(t->v[1], m->v[idx[k - 1]], sizeof t->v[1]);
		memcpy(t->v[2], m->v[idx[k]], sizeof t->v[2]);
		tri_finish(t);
	}
	return 0;
}

static int load_obj(const char *path, mesh *m)
{
	char line[4096];
	int line_no = 0, rc = 0;
	FILE *f = fopen(path, "r");
	memset(m, 0, sizeof *m);
	if (!f) {
		printf("cannot open %s\n", path);
		return -1;
	}
	while (rc == 0 && fgets(line, sizeof line, f)) {
		line_no++;
		if (!strchr(line, '\n') && !feof(f))
			rc = -1;
		else if (line[0] == 'v' && (line[1] == ' ' || line[1] == '\t'))
			rc = obj_vertex(m, line + 2);
		else if (line[0] == 'f' && (line[1] == ' ' || line[1] == '\t'))
			rc = obj_face(m, line + 2);
	}
	fclose(f);
	if (rc != 0)
		printf("%s:%d: cannot parse (or out of memory)\n", path, line_no);
	return rc;
}

static void mesh_bounds(const mesh *m, float lo[3], float hi[3])
{
	for (int a = 0; a < 3; a++) {
		lo[a] = INFINITY;
		hi[a] = -INFINITY;
	}
	for (int i = 0; i < m->n_t; i++)
		for (int k = 0; k < 3; k++)
			for (int a = 0; a < 3; a++) {
				lo[a] = fminf(lo[a], m->t[i].v[k][a]);
				hi[a] = fmaxf(hi[a], m->t[i].v[k][a]);
			}
}

/* From a random point on a sphere around the mesh towards a random point in
 * its box; one ray in ten runs exactly along an axis instead. */
static ray mesh_ray(rng *r, const float lo[3], const float hi[3])
{
	float centre[3], target[3], o[3], d[3], radius = 0.0f;
	for (int a = 0; a < 3; a++) {
		centre[a] = 0.5f * (lo[a] + hi[a]);
		radius += (hi[a] - lo[a]) * (hi[a] - lo[a]);
		target[a] = rng_range(r, lo[a], hi[a]);
	}
	radius = 0.75f * sqrtf(radius);     /* 1.5 times the box's half diagonal */
	if (rng_f(r) < 0.1f) {
		int axis = rng_int(r, 3);
		float s = rng_f(r) < 0.5f ? -1.0f : 1.0f;
		memcpy(o, target, sizeof o);
		o[axis] = centre[axis] - s * radius;
		d[0] = d[1] = d[2] = 0.0f;
		d[axis] = s;
		return make_ray(o, d);
	}
	random_direction(r, d);
	for (int a = 0; a < 3; a++)
		o[a] = centre[a] + radius * d[a];
	sub3(d, target, o);
	return make_ray(o, d);
}

static void mesh_test(const char *path, rng *r)
{
	mesh m;
	bvh_tree t;
	stats st;
	ray *rays = NULL;
	float lo[3], hi[3];
	printf("mesh %s:\n", path);
	if (load_obj(path, &m) != 0 || m.n_t == 0) {
		fail("%s: no triangles loaded", path);
		goto done;
	}
	if (build_checked("mesh", m.t, m.n_t, 5, &t) != 0)
		goto done;
	rays = malloc((size_t)N_RAYS * sizeof *rays);
	if (!rays) {
		fail("out of memory");
		bvh_free(&t);
		goto done;
	}
	mesh_bounds(&m, lo, hi);
	for (int i = 0; i < N_RAYS; i++)
		rays[i] = mesh_ray(r, lo, hi);
	check_rays(&t, m.t, m.n_t, rays, N_RAYS, NULL, &st);
	print_stats("mesh", &st);
	bvh_free(&t);
done:
	free(rays);
	free(m.v);
	free(m.t);
}

/* ---- the property test: a million rays ----
 *
 * Brute force over 69,451 (bunny) or 871,306 (dragon) triangles for a million
 * rays would take hours, so the million rays are checked against a second,
 * independent structure instead, and brute force anchors both on a random
 * subset: every ray must give the same closest hit (distance bit for bit,
 * primitive up to exact ties) in
 *   - the SAH tree, binary traversal;
 *   - the same tree converted to the wide layout (bvh_widen), wide traversal;
 *   - the paper's median-split tree (bvh_build_median, depth 16): a different
 *     builder, so different partitions, boxes and leaf sizes;
 * and the subset must also agree with testing every triangle. A wrong box or
 * a wrong traversal step in one structure shows as a disagreement with the
 * others; for all of them to be wrong the same way on the same ray, two
 * unrelated trees would have to lose the same triangle. Origins: half inside
 * the mesh's box, half on a sphere around it; directions uniform. */
static ray property_ray(rng *r, const float lo[3], const float hi[3])
{
	float o[3], d[3], c[3], radius = 0.0f;
	for (int a = 0; a < 3; a++) {
		c[a] = 0.5f * (lo[a] + hi[a]);
		radius += (hi[a] - lo[a]) * (hi[a] - lo[a]);
	}
	radius = 0.75f * sqrtf(radius);
	if (rng_f(r) < 0.5f) {
		for (int a = 0; a < 3; a++)
			o[a] = rng_range(r, lo[a], hi[a]);
	} else {
		random_direction(r, d);
		for (int a = 0; a < 3; a++)
			o[a] = c[a] + radius * d[a];
	}
	random_direction(r, d);
	return make_ray(o, d);
}

static void property_case(const char *name, rng *r, const tri *tris, int n, int n_rays, int n_brute)
{
	bvh_box *boxes = make_boxes(tris, n);
	bvh_tree sah, med;
	bvh_wide wide;
	int root = 0, bad = 0, brute_bad = 0, hits = 0;
	float lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	if (!boxes || bvh_build(boxes, n, &sah) != 0 || bvh_build_median(boxes, n, 16, &med) != 0 ||
	    bvh_widen(sah.nodes, &root, 1, NULL, 0, &wide) != 0) {
		fail("%s: build failed", name);
		free(boxes);
		return;
	}
	for (int i = 0; i < n; i++)
		for (int a = 0; a < 3; a++) {
			lo[a] = fminf(lo[a], tris[i].lo[a]);
			hi[a] = fmaxf(hi[a], tris[i].hi[a]);
		}
	int depth = sah.depth > med.depth ? sah.depth : med.depth;
	int *stack_node = malloc((size_t)depth * sizeof *stack_node);
	float *stack_t = malloc((size_t)depth * sizeof *stack_t);
	double t0 = now_ms();
	for (int i = 0; i < n_rays && stack_node && stack_t; i++) {
		ray ry = property_ray(r, lo, hi);
		hit a = traverse(&sah, tris, &ry, stack_node, stack_t);
		hit b = traverse_wide(&wide, &sah, tris, &ry);
		hit c = traverse(&med, tris, &ry, stack_node, stack_t);
		hits += a.prim >= 0;
		if (!same_hit(&a, &b, tris, &ry) || !same_hit(&a, &c, tris, &ry)) {
			if (bad++ < 3)
				fail("%s ray %d: SAH t %.9g prim %d, wide t %.9g prim %d, median t %.9g prim %d", name, i,
				     a.t, a.prim, b.t, b.prim, c.t, c.prim);
		}
		if (i < n_brute) {
			hit want = brute_force(tris, n, &ry);
			if (!same_hit(&a, &want, tris, &ry) && brute_bad++ < 3)
				fail("%s ray %d: SAH t %.9g prim %d, brute force t %.9g prim %d", name, i, a.t, a.prim,
				     want.t, want.prim);
		}
	}
	printf("  %s: %d triangles, %d rays (%d hit): SAH, wide and median trees agree on %d; "
	       "brute force on the first %d: %d disagreements (%.0f ms)\n", name, n, n_rays, hits,
	       n_rays - bad, n_brute, brute_bad, now_ms() - t0);
	free(stack_node);
	free(stack_t);
	bvh_wide_free(&wide);
	bvh_free(&sah);
	bvh_free(&med);
	free(boxes);
}

static int property_test(int n_files, char **files, rng *r)
{
	enum { N_PROPERTY_RAYS = 1000000 };
	char path[4096];
	int n_brute;
	for (int i = 0; i < n_files; i++)   /* all of them well formed before the first case */
		if (mesh_arg(files[i], path, sizeof path, &n_brute))
			return 2;
	printf("property: %d random rays each\n", N_PROPERTY_RAYS);
	for (int i = 0; i < n_files; i++) {
		mesh m = { 0 };
		mesh_arg(files[i], path, sizeof path, &n_brute);
		const char *name = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
		if (load_obj(path, &m) != 0 || m.n_t == 0)
			fail("%s: no triangles loaded", path);
		else
			property_case(name, r, m.t, m.n_t, N_PROPERTY_RAYS, n_brute);
		free(m.v);
		free(m.t);
	}
	enum { N = 20000 };
	tri *tris = malloc(N * sizeof *tris);
	signed char *edge_axis = malloc(N);
	if (tris && edge_axis) {
		make_soup(r, tris, N, edge_axis);
		property_case("soup with degenerate triangles", r, tris, N, N_PROPERTY_RAYS, 2000);
	}
	free(tris);
	free(edge_axis);
	printf("%s: %d error%s\n", n_errors ? "FAIL" : "PASS", n_errors, n_errors == 1 ? "" : "s");
	return n_errors ? 1 : 0;
}

int main(int argc, char **argv)
{
	rng r = { SEED };
	if (argc >= 2 && strcmp(argv[1], "--property") == 0)
		return property_test(argc - 2, argv + 2, &r);
	printf("test_bvh: seed 0x%016llx, BVH_MAX_LEAF %d\n", (unsigned long long)SEED, BVH_MAX_LEAF);
	check_slab();
	printf("tiny trees:\n");
	empty_test();
	soup_test("n=1", &r, 1, 20000, 1);
	soup_test("n=2", &r, 2, 20000, 1);
	soup_test("n=5", &r, 5, 20000, 1);
	printf("special arrangements:\n");
	shape_tests(&r);
	printf("soup:\n");
	soup_test("soup", &r, N_SOUP, N_RAYS, 5);
	printf("threads:\n");
	determinism_test(&r);
	printf("leaves of up to four:\n");
	leaves_test(&r);
	if (argc > 1)
		mesh_test(argv[1], &r);
	printf("%s: %d error%s\n", n_errors ? "FAIL" : "PASS", n_errors, n_errors == 1 ? "" : "s");
	return n_errors ? 1 : 0;
}
