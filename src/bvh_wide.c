/* bvh_wide.c: the binary BVH converted to 4-wide nodes with quantized child
 * boxes (bvh_wnode, kernels/shared.h), tinybvh's approach: the builders make
 * one good binary tree, and this is only a change of layout.
 *
 *   int roots[] = { 0, mesh_root, ... };   binary node indices
 *   bvh_wide w;
 *   if (bvh_widen(nodes, roots, n_roots, prims, 1, &w) == 0)
 *       w.nodes[w.roots[k]] is the wide node of roots[k]; bvh_wide_free(&w);
 *
 * Each wide node takes the children of a binary interior node and, while it
 * has fewer than four, replaces its interior child of largest surface area by
 * that child's two children (the collapse most likely to save box tests).
 * Leaves keep their primitive ranges; a leaf of more than BVH_WIDE_LEAF_MAX
 * primitives (the median builder makes such) becomes a small subtree whose
 * children split its range and share its box.
 * In a mesh's tree the triangles are copied into blocks of four (bvh_tri4),
 * which the device tests together, and a subtree of at most four triangles
 * becomes one leaf: one block test in place of a node and two or more single
 * tests. */
#include "bvh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
	bvh_wide *w;
	int cap;
	int failed;
	const dev_prim *tris;   /* the tree's triangles, when its leaves are blocks; else NULL */
} widener;

static float node_area(const bvh_node *n)
{
	float dx = n->max_x - n->min_x, dy = n->max_y - n->min_y, dz = n->max_z - n->min_z;
	return dx * dy + dy * dz + dz * dx;
}

/* A new zeroed wide node, or -1. */
static int alloc_node(widener *x)
{
	bvh_wide *w = x->w;
	if (w->n_nodes == x->cap) {
		int cap = x->cap ? 2 * x->cap : 256;
		bvh_wnode *n = realloc(w->nodes, (size_t)cap * sizeof *n);
		if (!n) {
			x->failed = 1;
			return -1;
		}
		w->nodes = n;
		x->cap = cap;
	}
	memset(&w->nodes[w->n_nodes], 0, sizeof *w->nodes);
	return w->n_nodes++;
}

/* The step 2^e of one axis: the smallest that spans lo .. hi in 255 steps, as
 * the device computes lo + 255 * 2^e. Returns the biased exponent, or -1. */
static int axis_exponent(float lo, float hi)
{
	float extent = hi - lo;
	int e = -126;
	if (!isfinite(extent) || extent < 0.0f)
		return -1;
	if (extent > 0.0f) {
		frexpf(extent / 255.0f, &e);
		e = e < -126 ? -126 : e;
	}
	while (e < 128 && lo + 255.0f * ldexpf(1.0f, e) < hi)
		e++;
	return e > 127 ? -1 : e + 127;
}

/* Child k's bounds on one axis in steps from lo, rounded outwards and checked
 * in the device's arithmetic. */
static void quantize_axis(float lo, int biased, float clo, float chi, uint *qlo, uint *qhi, int k)
{
	float step = ldexpf(1.0f, biased - 127);
	float fl = floorf((clo - lo) / step), fh = ceilf((chi - lo) / step);
	int a = fl < 0.0f ? 0 : fl > 255.0f ? 255 : (int)fl;
	int b = fh < 0.0f ? 0 : fh > 255.0f ? 255 : (int)fh;
	while (a > 0 && lo + (float)a * step > clo)
		a--;
	while (b < 255 && lo + (float)b * step < chi)
		b++;
	*qlo |= (uint)a << (8 * k);
	*qhi |= (uint)b << (8 * k);
}

/* Fills wide node w with n children of the given boxes and references. */
static void fill_node(widener *x, int w, int n, const bvh_node *box, const int *ref)
{
	float lo[3] = { box[0].min_x, box[0].min_y, box[0].min_z };
	float hi[3] = { box[0].max_x, box[0].max_y, box[0].max_z };
	for (int k = 1; k < n; k++) {
		const float blo[3] = { box[k].min_x, box[k].min_y, box[k].min_z };
		const float bhi[3] = { box[k].max_x, box[k].max_y, box[k].max_z };
		for (int a = 0; a < 3; a++) {
			lo[a] = blo[a] < lo[a] ? blo[a] : lo[a];
			hi[a] = bhi[a] > hi[a] ? bhi[a] : hi[a];
		}
	}
	bvh_wnode *node = &x->w->nodes[w];
	int e[3];
	for (int a = 0; a < 3; a++)
		if (n > 0 && (e[a] = axis_exponent(lo[a], hi[a])) < 0)
			x->failed = 1;
	if (n == 0 || x->failed)
		return;
	node->origin_x = lo[0];
	node->origin_y = lo[1];
	node->origin_z = lo[2];
	node->meta = (uint)e[0] | (uint)e[1] << 8 | (uint)e[2] << 16 | (uint)n << 24;
	for (int k = 0; k < n; k++) {
		quantize_axis(lo[0], e[0], box[k].min_x, box[k].max_x, &node->qlo_x, &node->qhi_x, k);
		quantize_axis(lo[1], e[1], box[k].min_y, box[k].max_y, &node->qlo_y, &node->qhi_y, k);
		quantize_axis(lo[2], e[2], box[k].min_z, box[k].max_z, &node->qlo_z, &node->qhi_z, k);
		node->child[k] = ref[k];
	}
}

/* count triangles from first copied into blocks after the nodes so far;
 * returns the first block's node index, or -1. */
static int leaf_blocks(widener *x, int first, int count)
{
	int at = x->w->n_nodes, n = (count + 3) / 4;
	for (int k = 0; k < n * BVH_TRI4_SLOTS; k++)
		if (alloc_node(x) < 0)
			return -1;
	x->w->n_blocks += n;
	for (int b = 0; b < n; b++) {
		bvh_tri4 q;
		memset(&q, 0, sizeof q);
		float4 *axis[9] = { &q.ax, &q.ay, &q.az, &q.bx, &q.by, &q.bz, &q.cx, &q.cy, &q.cz };
		for (int lane = 0; lane < 4; lane++) {
			int k = 4 * b + lane;
			q.prim[lane] = k < count ? first + k : -1;
			if (k >= count)
				continue;
			const dev_prim *p = &x->tris[first + k];
			const float4 *v[3] = { &p->a, &p->b, &p->c };
			for (int c = 0; c < 3; c++) {
				float xyz[3] = { v[c]->x, v[c]->y, v[c]->z };
				for (int a = 0; a < 3; a++)
					((float *)axis[3 * c + a])[lane] = xyz[a];
			}
		}
		/* the node array's slots take the block's bytes */
		memcpy(&x->w->nodes[at + BVH_TRI4_SLOTS * b], &q, sizeof q);
	}
	return at;
}

/* The reference of a leaf over count primitives from first; *need is the
 * traversal stack it can take. */
static int leaf_ref(widener *x, const bvh_node *box, int first, int count, int *need)
{
	*need = 0;
	if (count <= BVH_WIDE_LEAF_MAX) {
		int at = x->tris ? leaf_blocks(x, first, count) : first;
		if (at < 0 || at >= 1 << BVH_WIDE_FIRST_BITS) {
			x->failed = 1;
			return 0;
		}
		return (int)(0x80000000u | (uint)count << BVH_WIDE_FIRST_BITS | (uint)at);
	}
	int w = alloc_node(x);
	if (w < 0)
		return 0;
	int ref[4], part = (count + 3) / 4, n = 0;
	bvh_node boxes[4];
	for (int at = first; at < first + count; at += part, n++) {
		int c = first + count - at < part ? first + count - at : part, sub;
		ref[n] = leaf_ref(x, box, at, c, &sub);
		boxes[n] = *box;
		*need = sub + 3 > *need ? sub + 3 : *need;
	}
	fill_node(x, w, n, boxes, ref);
	return w;
}

/* Whether binary node i's subtree holds at most BVH_WIDE_BLOCK primitives, in one run
 * (*first, *count): a subtree the wide layout makes a leaf of blocks. */
static int small_subtree(const bvh_node *bin, int i, int *first, int *count)
{
	if (bin[i].count > 0) {
		*first = bin[i].left_first;
		*count = bin[i].count;
		return *count <= BVH_WIDE_BLOCK;
	}
	int f1, n1, f2, n2;
	return small_subtree(bin, bin[i].left_first, &f1, &n1) && small_subtree(bin, bin[i].left_first + 1, &f2, &n2) &&
	       n1 + n2 <= BVH_WIDE_BLOCK && f2 == f1 + n1 && (*first = f1, *count = n1 + n2, 1);
}

/* Whether binary node i is a leaf of the wide layout, and its run. */
static int wide_leaf(const widener *x, const bvh_node *bin, int i, int *first, int *count)
{
	if (bin[i].count > 0) {
		*first = bin[i].left_first;
		*count = bin[i].count;
		return 1;
	}
	return x->tris && small_subtree(bin, i, first, count);
}

/* The children of binary node i, widened to at most four. */
static int gather(const widener *x, const bvh_node *bin, int i, int kids[4])
{
	int first, count;
	if (wide_leaf(x, bin, i, &first, &count)) {
		kids[0] = i;
		return 1;
	}
	int n = 2;
	kids[0] = bin[i].left_first;
	kids[1] = kids[0] + 1;
	while (n < 4) {
		int best = -1;
		float best_area = -1.0f;
		for (int k = 0; k < n; k++)
			if (!wide_leaf(x, bin, kids[k], &first, &count) && node_area(&bin[kids[k]]) > best_area) {
				best = k;
				best_area = node_area(&bin[kids[k]]);
			}
		if (best < 0)
			break;
		int c = bin[kids[best]].left_first;
		kids[best] = c;
		kids[n++] = c + 1;
	}
	return n;
}

/* The wide node of binary node i (recursion depth: the binary tree's depth,
 * which the lowering bounds by BVH_STACK_SIZE). */
static int widen(widener *x, const bvh_node *bin, int i, int *need)
{
	int w = alloc_node(x), kids[4], ref[4], n = gather(x, bin, i, kids);
	bvh_node boxes[4];
	*need = 0;
	if (w < 0)
		return 0;
	for (int k = 0; k < n && !x->failed; k++) {
		const bvh_node *c = &bin[kids[k]];
		int sub, first, count;
		boxes[k] = *c;
		ref[k] = wide_leaf(x, bin, kids[k], &first, &count) ? leaf_ref(x, c, first, count, &sub)
		                                                    : widen(x, bin, kids[k], &sub);
		*need = sub + n - 1 > *need ? sub + n - 1 : *need;
	}
	if (!x->failed)
		fill_node(x, w, n, boxes, ref);
	return w;
}

int bvh_widen(const bvh_node *nodes, const int *roots, int n_roots, const dev_prim *tris, int first_mesh,
              bvh_wide *out)
{
	memset(out, 0, sizeof *out);
	widener x = { out, 0, 0, NULL };
	out->roots = malloc((size_t)(n_roots > 0 ? n_roots : 1) * sizeof *out->roots);
	if (!out->roots)
		x.failed = 1;
	for (int r = 0; r < n_roots && !x.failed; r++) {
		int need = 0;
		x.tris = tris && r >= first_mesh ? tris : NULL;
		out->roots[r] = roots[r] < 0 ? alloc_node(&x) : widen(&x, nodes, roots[r], &need);
		out->max_stack = need > out->max_stack ? need : out->max_stack;
	}
	if (x.failed) {
		bvh_wide_free(out);
		return -1;
	}
	return 0;
}

void bvh_wide_free(bvh_wide *w)
{
	free(w->nodes);
	free(w->roots);
	memset(w, 0, sizeof *w);
}
