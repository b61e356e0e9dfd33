/* bvh.c: binned SAH build of a binary BVH over primitive boxes.
 *
 * Top-down build with an explicit, growable work stack (no recursion, so
 * meshes of millions of primitives cannot overflow the C stack). At each node
 * the primitives' centroids are binned into 16 bins on each of the three axes
 * and the cheapest of the 3 * 15 candidate planes is taken: on the Stanford
 * meshes, trying all three axes gives trees 3-4% cheaper (SAH) than binning
 * only the axis of largest centroid extent, for 1.5 times the build time
 * (bunny, 69,451 triangles: 36 ms instead of 25 ms at -O2).
 *
 * The primitives are sorted in a scratch array of records (box, centroid),
 * with the permutation kept in t->prim_index alongside, so that every pass
 * over a node's range reads memory sequentially. Boxes and centroids have a
 * fourth, unused lane so that the per-lane loops compile to 4-wide SSE
 * min/max at -O2. A node's box and its centroid bounds come from its parent's
 * bins and partition pass, so no separate bounds pass is needed per node. */
#include "bvh.h"

#include <float.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#define BINS 16
#define STACK_INIT 64

/* An axis-aligned box; lane 3 is padding. */
typedef struct {
	float lo[4], hi[4];
} box4;

/* One primitive during the build. */
typedef struct {
	box4 box;
	float c[4];         /* centroid; lane 3 is padding */
} prim_rec;

/* One bin of one axis. */
typedef struct {
	box4 box;
	int count;
} bin;

/* A node still to be split: its index, its depth (root = 1) and the bounds of
 * its primitives' centroids. Its own box is already in the node array. */
typedef struct {
	int node;
	int depth;
	box4 cbounds;
} work;

/* The binning of one node's centroid bounds, shared by the binning and the
 * partition passes so that both put every primitive in the same bin. */
typedef struct {
	float origin[4];
	float scale[4];     /* bins per unit length; 0 marks an axis that cannot be split */
} binning;

/* The chosen plane: primitives in bins 0 .. bin go left. */
typedef struct {
	int axis;
	int bin;
	float cost;         /* sum of area * count of both sides, not normalised */
	int imbalance;      /* |left count - right count|, the tie-breaker */
} split;

/* How a node's range is split: left primitives first, and each side's box and
 * centroid bounds. */
typedef struct {
	int left;
	box4 box[2];
	box4 cbounds[2];
} children;

typedef struct {
	prim_rec *rec;
	int *index;         /* t->prim_index, permuted together with rec */
	bvh_node *nodes;
	int n_nodes;
	work *stack;
	int sp, cap;
	int depth;
} builder;

/* Written as x < y ? x : y, which compiles to minss/minps without branches
 * (fminf would be a library call without -ffast-math). */
static float min_f(float x, float y)
{
	return x < y ? x : y;
}

static float max_f(float x, float y)
{
	return x > y ? x : y;
}

/* An inverted box, so that the first grow sets it. Finite values rather than
 * infinities keep arithmetic on an empty box free of inf - inf. */
static box4 box_empty(void)
{
	box4 b;
	for (int a = 0; a < 4; a++) {
		b.lo[a] = FLT_MAX;
		b.hi[a] = -FLT_MAX;
	}
	return b;
}

static void box_grow(box4 *b, const box4 *o)
{
	for (int a = 0; a < 4; a++) {
		b->lo[a] = min_f(o->lo[a], b->lo[a]);
		b->hi[a] = max_f(o->hi[a], b->hi[a]);
	}
}

static void box_grow_point(box4 *b, const float p[4])
{
	for (int a = 0; a < 4; a++) {
		b->lo[a] = min_f(p[a], b->lo[a]);
		b->hi[a] = max_f(p[a], b->hi[a]);
	}
}

/* Surface area; 0 for an empty (inverted) box, whose extents clamp to 0
 * (without a branch: this runs in the SAH sweeps' inner loops). */
static inline float box_area(const box4 *b)
{
	float d[3];
	for (int a = 0; a < 3; a++)
		d[a] = max_f(b->hi[a] - b->lo[a], 0.0f);
	return 2.0f * (d[0] * d[1] + d[1] * d[2] + d[2] * d[0]);
}

static box4 node_box(const bvh_node *n)
{
	box4 b = { { n->min_x, n->min_y, n->min_z, 0.0f }, { n->max_x, n->max_y, n->max_z, 0.0f } };
	return b;
}

static void set_node_box(bvh_node *n, const box4 *b)
{
	n->min_x = b->lo[0];
	n->min_y = b->lo[1];
	n->min_z = b->lo[2];
	n->max_x = b->hi[0];
	n->max_y = b->hi[1];
	n->max_z = b->hi[2];
}

/* The bin of coordinate x. max_f(f, 0) also sends a NaN to bin 0, so no NaN
 * reaches the float-to-int conversion (undefined behaviour in C). */
static int bin_of(float x, float origin, float scale)
{
	float f = (x - origin) * scale;
	return (int)min_f(max_f(f, 0.0f), (float)(BINS - 1));
}

/* Box of the primitives and box of their centroids over one range. */
static void range_bounds(const prim_rec *r, int count, box4 *bounds, box4 *cbounds)
{
	*bounds = box_empty();
	*cbounds = box_empty();
	for (int i = 0; i < count; i++) {
		box_grow(bounds, &r[i].box);
		box_grow_point(cbounds, r[i].c);
	}
}

/* An axis whose centroid extent is zero, too small for a finite scale, or
 * overflowing, gets scale 0: all its centroids would share one bin anyway. */
static binning make_binning(const box4 *cbounds)
{
	binning g = { { 0.0f }, { 0.0f } };
	for (int a = 0; a < 3; a++) {
		float extent = cbounds->hi[a] - cbounds->lo[a];
		float scale = extent > 0.0f ? (float)BINS / extent : 0.0f;
		g.origin[a] = cbounds->lo[a];
		g.scale[a] = (scale > 0.0f && scale <= FLT_MAX) ? scale : 0.0f;
	}
	return g;
}

static void fill_bins(const prim_rec *r, int count, const binning *g, bin bins[3][BINS])
{
	for (int a = 0; a < 3; a++)
		for (int k = 0; k < BINS; k++) {
			bins[a][k].box = box_empty();
			bins[a][k].count = 0;
		}
	for (int i = 0; i < count; i++) {
		int k[4];
		for (int a = 0; a < 4; a++)
			k[a] = bin_of(r[i].c[a], g->origin[a], g->scale[a]);
		for (int a = 0; a < 3; a++) {
			if (g->scale[a] == 0.0f)
				continue;
			box_grow(&bins[a][k[a]].box, &r[i].box);
			bins[a][k[a]].count++;
		}
	}
}

/* Best plane on one axis, by a right-to-left sweep for the right sides and a
 * left-to-right sweep for the left sides. Only planes with primitives on both
 * sides count, so a chosen split always makes progress. Empty bins are
 * skipped: the plane after an empty bin splits like the plane before it, and
 * small nodes, the majority, leave most bins empty. Equal costs go to the
 * more even split: when every area is 0 (primitives on one line) all costs
 * tie, and taking the first plane would peel off one bin at a time and make
 * the tree needlessly deep. */
static void best_on_axis(const bin bins[BINS], int axis, split *best)
{
	float right_cost[BINS];     /* right_cost[k]: area * count of bins k+1 .. BINS-1 */
	int right_count[BINS];
	box4 acc = box_empty();
	int n = 0;
	float cost = 0.0f;
	for (int k = BINS - 1; k > 0; k--) {
		if (bins[k].count > 0) {
			box_grow(&acc, &bins[k].box);
			n += bins[k].count;
			cost = box_area(&acc) * (float)n;
		}
		right_cost[k - 1] = cost;
		right_count[k - 1] = n;
	}
	acc = box_empty();
	n = 0;
	for (int k = 0; k < BINS - 1; k++) {
		if (bins[k].count == 0)
			continue;
		box_grow(&acc, &bins[k].box);
		n += bins[k].count;
		if (right_count[k] == 0)
			break;
		float c = box_area(&acc) * (float)n + right_cost[k];
		int imbalance = abs(n - right_count[k]);
		if (c < best->cost || (c == best->cost && imbalance < best->imbalance)) {
			best->axis = axis;
			best->bin = k;
			best->cost = c;
			best->imbalance = imbalance;
		}
	}
}

/* axis -1 means no plane separates the centroids. (bins is not const: C11
 * does not convert bin (*)[BINS] to const bin (*)[BINS] implicitly.) */
static split find_split(bin bins[3][BINS], const binning *g)
{
	split best = { -1, 0, FLT_MAX, INT_MAX };
	for (int a = 0; a < 3; a++)
		if (g->scale[a] != 0.0f)
			best_on_axis(bins[a], a, &best);
	return best;
}

static void swap_prims(prim_rec *r, int *index, int i, int j)
{
	prim_rec t = r[i];
	int k = index[i];
	r[i] = r[j];
	r[j] = t;
	index[i] = index[j];
	index[j] = k;
}

/* Moves the primitives of bins 0 .. s->bin to the front, collecting both
 * sides' centroid bounds on the way; returns how many went left. */
static int partition(prim_rec *r, int *index, int count, const binning *g, const split *s, children *ch)
{
	int a = s->axis, i = 0, j = count - 1;
	ch->cbounds[0] = box_empty();
	ch->cbounds[1] = box_empty();
	while (i <= j) {
		if (bin_of(r[i].c[a], g->origin[a], g->scale[a]) <= s->bin) {
			box_grow_point(&ch->cbounds[0], r[i].c);
			i++;
		} else {
			box_grow_point(&ch->cbounds[1], r[i].c);
			swap_prims(r, index, i, j--);
		}
	}
	return i;
}

/* Each side's box is the union of its bins on the split axis. */
static void boxes_from_bins(const bin bins[BINS], int split_bin, children *ch)
{
	ch->box[0] = box_empty();
	ch->box[1] = box_empty();
	for (int k = 0; k < BINS; k++)
		box_grow(&ch->box[k <= split_bin ? 0 : 1], &bins[k].box);
}

/* The fallback when no plane separates the centroids: halve by index, which
 * still terminates, and measure both halves. */
static void split_middle(const prim_rec *r, int count, children *ch)
{
	ch->left = count / 2;
	range_bounds(r, ch->left, &ch->box[0], &ch->cbounds[0]);
	range_bounds(r + ch->left, count - ch->left, &ch->box[1], &ch->cbounds[1]);
}

/* Fills ch and returns 1 to split the range, or returns 0 to make a leaf.
 * The SAH compares C_trav * area(node) + sum area(child) * count(child) with
 * area(node) * count, unnormalised so that a flat or point-like node (area 0)
 * compares 0 with 0 instead of dividing by zero; ties make a leaf. Ranges of
 * more than BVH_MAX_LEAF primitives are always split. */
static int choose_split(builder *b, int first, int count, const box4 *bounds, const box4 *cbounds,
			children *ch)
{
	bin bins[3][BINS];
	if (count == 1)
		return 0;
	prim_rec *r = b->rec + first;
	binning g = make_binning(cbounds);
	fill_bins(r, count, &g, bins);
	split s = find_split(bins, &g);
	float area = box_area(bounds);
	if (count <= BVH_MAX_LEAF && (s.axis < 0 || area + s.cost >= area * (float)count))
		return 0;
	if (s.axis < 0) {
		split_middle(r, count, ch);
		return 1;
	}
	ch->left = partition(r, b->index + first, count, &g, &s, ch);
	/* Binning and partition share bin_of, so this only guards against a
	 * future change breaking that agreement. */
	if (ch->left == 0 || ch->left == count) {
		split_middle(r, count, ch);
		return 1;
	}
	boxes_from_bins(bins[s.axis], s.bin, ch);
	return 1;
}

/* Returns 0, or -1 when the stack cannot grow. */
static int push(builder *b, work w)
{
	if (b->sp == b->cap) {
		work *s = realloc(b->stack, (size_t)b->cap * 2 * sizeof *s);
		if (!s)
			return -1;
		b->stack = s;
		b->cap *= 2;
	}
	b->stack[b->sp++] = w;
	return 0;
}

/* Builds the subtree of one node, pushing each right child for later and
 * continuing with the left child in the same loop. Returns 0 or -1. */
static int build_subtree(builder *b, work w)
{
	for (;;) {
		bvh_node *node = &b->nodes[w.node];
		int first = node->left_first, count = node->count;
		box4 bounds = node_box(node);
		children ch;
		if (w.depth > b->depth)
			b->depth = w.depth;
		if (!choose_split(b, first, count, &bounds, &w.cbounds, &ch))
			return 0;
		int child = b->n_nodes;
		b->n_nodes += 2;
		for (int k = 0; k < 2; k++) {
			set_node_box(&b->nodes[child + k], &ch.box[k]);
			b->nodes[child + k].left_first = k == 0 ? first : first + ch.left;
			b->nodes[child + k].count = k == 0 ? ch.left : count - ch.left;
		}
		node->left_first = child;
		node->count = 0;
		if (push(b, (work){ child + 1, w.depth + 1, ch.cbounds[1] }) != 0)
			return -1;
		w = (work){ child, w.depth + 1, ch.cbounds[0] };
	}
}

/* Sum over interior nodes of area / root area, plus over leaves of
 * area / root area * count. A root of area 0 (all primitives on one line or
 * point) makes every ratio 1. */
double bvh_sah_cost(const bvh_node *nodes, int n_nodes)
{
	box4 root = node_box(&nodes[0]);
	double root_area = box_area(&root);
	double cost = 0.0;
	for (int i = 0; i < n_nodes; i++) {
		box4 b = node_box(&nodes[i]);
		double ratio = root_area > 0.0 ? (double)box_area(&b) / root_area : 1.0;
		cost += nodes[i].count > 0 ? ratio * nodes[i].count : ratio;
	}
	return cost;
}

static void init_records(prim_rec *rec, int *index, const bvh_box *boxes, int n)
{
	for (int i = 0; i < n; i++) {
		for (int a = 0; a < 3; a++) {
			rec[i].box.lo[a] = boxes[i].min[a];
			rec[i].box.hi[a] = boxes[i].max[a];
			/* Halved before adding, so that boxes near FLT_MAX do not overflow. */
			rec[i].c[a] = 0.5f * boxes[i].min[a] + 0.5f * boxes[i].max[a];
		}
		rec[i].box.lo[3] = rec[i].box.hi[3] = rec[i].c[3] = 0.0f;
		index[i] = i;
	}
}

/* The build proper, once all memory is there. Returns 0 or -1. */
static int build_tree(builder *b, int n)
{
	box4 bounds, cbounds;
	range_bounds(b->rec, n, &bounds, &cbounds);
	set_node_box(&b->nodes[0], &bounds);
	b->nodes[0].left_first = 0;
	b->nodes[0].count = n;
	b->n_nodes = 1;
	b->stack[b->sp++] = (work){ 0, 1, cbounds };
	while (b->sp > 0) {
		work w = b->stack[--b->sp];
		if (build_subtree(b, w) != 0)
			return -1;
	}
	return 0;
}

static void free_builder(builder *b)
{
	free(b->nodes);
	free(b->rec);
	free(b->stack);
}

static int build_empty(bvh_tree *t)
{
	t->nodes = calloc(1, sizeof *t->nodes);
	if (!t->nodes)
		return -1;
	t->n_nodes = 1;
	t->depth = 1;
	return 0;
}

/* Returns 0, or -1 (t zeroed) when n < 0, boxes is NULL with n > 0, n is too
 * large for int node indices, or memory runs out.
 *
 * The empty tree (n == 0): one node, all zero (box at the origin, left_first 0,
 * count 0), n_nodes 1, n_prims 0, prim_index NULL, depth 1, sah_cost 0. Under
 * the node encoding count 0 reads as an interior node whose children would be
 * nodes[0] and nodes[1], so it must never be traversed: callers check
 * n_prims == 0 first and treat every ray as a miss.
 *
 * Otherwise every leaf holds 1 .. BVH_MAX_LEAF primitives and the tree has at
 * most 2n - 1 nodes; node boxes are exact unions of the input boxes, so they
 * contain no NaN unless the input does. Thread-safe: no global state. */
int bvh_build(const bvh_box *boxes, int n, bvh_tree *t)
{
	memset(t, 0, sizeof *t);
	if (n < 0 || (n > 0 && !boxes) || n > INT_MAX / 2)
		return -1;
	if (n == 0)
		return build_empty(t);
	builder b = { 0 };
	b.nodes = calloc((size_t)2 * n - 1, sizeof *b.nodes);
	b.rec = malloc((size_t)n * sizeof *b.rec);
	b.stack = malloc(STACK_INIT * sizeof *b.stack);
	b.cap = STACK_INIT;
	b.index = t->prim_index = malloc((size_t)n * sizeof *t->prim_index);
	if (!b.nodes || !b.rec || !b.stack || !b.index) {
		free_builder(&b);
		bvh_free(t);
		return -1;
	}
	init_records(b.rec, b.index, boxes, n);
	if (build_tree(&b, n) != 0) {
		free_builder(&b);
		bvh_free(t);
		return -1;
	}
	t->n_nodes = b.n_nodes;
	t->n_prims = n;
	t->depth = b.depth;
	t->sah_cost = bvh_sah_cost(b.nodes, b.n_nodes);
	/* Give back the unused tail of the 2n - 1 nodes; keep the block if the
	 * shrink fails, it is still valid. */
	t->nodes = realloc(b.nodes, (size_t)b.n_nodes * sizeof *b.nodes);
	if (!t->nodes)
		t->nodes = b.nodes;
	b.nodes = NULL;
	free_builder(&b);
	return 0;
}

void bvh_free(bvh_tree *t)
{
	if (!t)
		return;
	free(t->nodes);
	free(t->prim_index);
	memset(t, 0, sizeof *t);
}
