/* lower_csg_tree.c: the tree over a CSG object's leaf boxes (kernels/csg.cl),
 * so that a ray tests only the leaves whose boxes it meets and an inside
 * test only those whose boxes hold the point, however many leaves there are.
 *
 *   dev_prim *nodes; int *list, n_nodes, root;
 *   int depth = lower_csg_tree(boxes, n, &nodes, &n_nodes, &list, &root);
 *   if (depth > CSG_TREE_STACK) ...   too deep for the kernels
 *   root == CSG_NO_TREE: no tree (nodes and list NULL)
 *
 * A CSG has tens of leaves, rarely thousands: the tree is split at the median
 * of the longest side of its boxes' centres, which keeps it balanced (its
 * depth is log2 of the leaves, so the kernels' stack is small and fixed). A
 * split is kept only when the surface area heuristic says that a ray pays
 * less for the two children's boxes than for testing each leaf's box in
 * turn: leaves whose boxes mostly overlap (an intersection of spheres about
 * one centre) stay a run, which the kernels test in a loop, as they did every
 * CSG before the tree. Leaves whose boxes are unbounded (lowering clamps a
 * plane's or an inverse quadric's to +-1e30) are a run of their own beside
 * the bounded ones' tree, where they would not swell every box above them:
 * every ray tests them all. A tree that would spare a ray too few box tests
 * to pay for its own (a CSG of a few leaves, or of leaves that all overlap)
 * is not made: the kernels then loop over the leaves. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lower.h"

static void *alloc(size_t n)
{
	void *p = malloc(n);
	if (!p) {
		fputs("eclat: out of memory\n", stderr);
		diag_exit(1);
	}
	return p;
}

struct build {
	const dev_prim *boxes;
	int *index;           /* the leaves, in the order the tree puts them: a run's are together */
	dev_prim *nodes;
	int n_nodes;
};

struct box {
	float lo[3], hi[3];
};

/* A box record's corners, in order: an empty box's (lo > hi, lowering's
 * box no ray meets) count as the box they span, as the kernels' slab test
 * sees them. */
static struct box corners(const dev_prim *b)
{
	const float a[3] = { b->a.x, b->a.y, b->a.z }, c[3] = { b->b.x, b->b.y, b->b.z };
	struct box r;
	for (int k = 0; k < 3; k++) {
		r.lo[k] = fminf(a[k], c[k]);
		r.hi[k] = fmaxf(a[k], c[k]);
	}
	return r;
}

static int bounded(const dev_prim *b)
{
	struct box r = corners(b);
	for (int k = 0; k < 3; k++)
		if (!(r.lo[k] > -1e9f && r.hi[k] < 1e9f))
			return 0;
	return 1;
}

static struct box range_box(const struct build *b, int first, int count)
{
	struct box r = { { INFINITY, INFINITY, INFINITY }, { -INFINITY, -INFINITY, -INFINITY } };
	for (int i = first; i < first + count; i++) {
		struct box l = corners(&b->boxes[b->index[i]]);
		for (int k = 0; k < 3; k++) {
			r.lo[k] = fminf(r.lo[k], l.lo[k]);
			r.hi[k] = fmaxf(r.hi[k], l.hi[k]);
		}
	}
	return r;
}

static double half_area(const struct box *r)
{
	double d[3] = { (double)r->hi[0] - r->lo[0], (double)r->hi[1] - r->lo[1], (double)r->hi[2] - r->lo[2] };
	return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

static int by_axis;   /* qsort's comparison reads it: the tree is built on one thread */
static const dev_prim *by_boxes;

static int centre_order(const void *pa, const void *pb)
{
	struct box a = corners(&by_boxes[*(const int *)pa]), b = corners(&by_boxes[*(const int *)pb]);
	float ca = a.lo[by_axis] + a.hi[by_axis], cb = b.lo[by_axis] + b.hi[by_axis];
	if (ca != cb)
		return ca < cb ? -1 : 1;
	return *(const int *)pa - *(const int *)pb;   /* the same tree on every host */
}

static int leaf_order(const void *pa, const void *pb)
{
	return *(const int *)pa - *(const int *)pb;
}

static int new_node(struct build *b, const struct box *r)
{
	dev_prim *n = &b->nodes[b->n_nodes];
	*n = (dev_prim){ .type = PRIM_DATA, .material = -1, .object = -1, .link = -1 };
	n->a = (float4){ r->lo[0], r->lo[1], r->lo[2], 0 };
	n->b = (float4){ r->hi[0], r->hi[1], r->hi[2], 0 };
	return b->n_nodes++;
}

static void set_ints(float4 *v, int x, int y, int z, int w)
{
	int i[4] = { x, y, z, w };
	memcpy(v, i, sizeof i);
}

/* A run of index[first .. first + count - 1], in the leaves' order (the
 * order a loop over all of them had), or the leaf alone. */
static int run(struct build *b, int first, int count, const struct box *r)
{
	if (count == 1)
		return ~b->index[first];
	qsort(b->index + first, count, sizeof *b->index, leaf_order);
	int me = new_node(b, r);
	set_ints(&b->nodes[me].c, -1, -1, first, count);
	return me;
}

/* The reference of the subtree over index[first .. first + count - 1], whose
 * box is r (a node's number, or ~k for leaf k alone); its depth in *depth.
 * split: whether it may be split (the unbounded leaves are one run). */
static int build(struct build *b, int first, int count, const struct box *r, int split, int *depth)
{
	*depth = 1;
	if (count == 1 || !split)
		return run(b, first, count, r);
	float clo[3] = { INFINITY, INFINITY, INFINITY }, chi[3] = { -INFINITY, -INFINITY, -INFINITY };
	for (int i = first; i < first + count; i++) {
		struct box l = corners(&b->boxes[b->index[i]]);
		for (int k = 0; k < 3; k++) {
			clo[k] = fminf(clo[k], l.lo[k] + l.hi[k]);
			chi[k] = fmaxf(chi[k], l.lo[k] + l.hi[k]);
		}
	}
	by_axis = chi[1] - clo[1] > chi[0] - clo[0] ? 1 : 0;
	by_axis = chi[2] - clo[2] > chi[by_axis] - clo[by_axis] ? 2 : by_axis;
	by_boxes = b->boxes;
	qsort(b->index + first, count, sizeof *b->index, centre_order);
	int half = count / 2;
	struct box r0 = range_box(b, first, half), r1 = range_box(b, first + half, count - half);
	/* the box tests a ray through r makes: one each for the two children's
	 * boxes, then one each for the leaves of those it meets, against one
	 * for each leaf of the run */
	double area = half_area(r);
	if (area > 0 && 2 + (half_area(&r0) * half + half_area(&r1) * (count - half)) / area >= count)
		return run(b, first, count, r);
	int me = new_node(b, r), d0, d1;
	int left = build(b, first, half, &r0, 1, &d0), right = build(b, first + half, count - half, &r1, 1, &d1);
	set_ints(&b->nodes[me].c, left, right, 0, 0);
	*depth = 1 + (d0 > d1 ? d0 : d1);
	return me;
}

static struct box ref_box(const struct build *b, int ref)
{
	return ref < 0 ? corners(&b->boxes[~ref]) : corners(&b->nodes[ref]);
}

/* The box tests a ray that meets ref's box makes below it, by the surface
 * area heuristic: a run's leaves' boxes, or a node's children's and what
 * those it meets make (every ray meets an unbounded box). */
static double tests(const struct build *b, int ref)
{
	if (ref < 0)
		return 0;
	const dev_prim *n = &b->nodes[ref];
	int kid[2], count;
	memcpy(kid, &n->c, sizeof kid);
	memcpy(&count, &n->c.w, sizeof count);
	if (count > 0)
		return count;
	struct box r = ref_box(b, ref);
	double area = half_area(&r), sum = 2;
	for (int i = 0; i < 2; i++) {
		struct box c = ref_box(b, kid[i]);
		double p = isfinite(area) && area > 0 ? half_area(&c) / area : 1;
		sum += (p < 1 ? p : 1) * tests(b, kid[i]);
	}
	return sum;
}

int lower_csg_tree(const dev_prim *boxes, int n, dev_prim **nodes, int *n_nodes, int **list, int *root)
{
	if (n < 1) {
		*nodes = NULL;
		*n_nodes = 0;
		*list = NULL;
		*root = CSG_NO_TREE;
		return 0;
	}
	struct build b = { boxes, alloc((n + 1) * sizeof *b.index), alloc((2 * n + 1) * sizeof *b.nodes), 0 };
	int n_bounded = 0, at = 0, depth = 0;
	for (int k = 0; k < n; k++)
		n_bounded += bounded(&boxes[k]);
	for (int pass = 0; pass < 2; pass++)   /* the bounded first, the unbounded after them */
		for (int k = 0; k < n; k++)
			if (bounded(&boxes[k]) == !pass)
				b.index[at++] = k;
	struct box all = range_box(&b, 0, n);
	if (n_bounded == 0 || n_bounded == n) {
		*root = build(&b, 0, n, &all, n_bounded == n, &depth);
	} else {   /* the bounded leaves' tree and the unbounded ones' run under one node */
		int me = new_node(&b, &all), d0, d1;
		struct box r0 = range_box(&b, 0, n_bounded), r1 = range_box(&b, n_bounded, n - n_bounded);
		int left = build(&b, 0, n_bounded, &r0, 1, &d0), right = build(&b, n_bounded, n - n_bounded, &r1, 0, &d1);
		set_ints(&b.nodes[me].c, left, right, 0, 0);
		depth = 1 + (d0 > d1 ? d0 : d1);
		*root = me;
	}
	if (2 * (1 + tests(&b, *root)) >= n) {   /* a visit costs about two of a loop's box tests */
		free(b.nodes);
		free(b.index);
		*nodes = NULL;
		*n_nodes = 0;
		*list = NULL;
		*root = CSG_NO_TREE;
		return 0;
	}
	*nodes = b.nodes;
	*n_nodes = b.n_nodes;
	*list = b.index;
	return depth;
}
