/* bvh_median.c: the reference paper's BVH builder (section III), kept to compare
 * with the SAH builder on the same scene: split at the spatial middle of the
 * longest side of the node's box, to a maximum depth. */
#include <stdlib.h>
#include <string.h>

#include "bvh.h"

struct task {
	int node, first, count, depth;
};

static void range_box(const bvh_box *boxes, const int *index, int first, int count, bvh_node *n)
{
	float lo[3] = { 1e30f, 1e30f, 1e30f }, hi[3] = { -1e30f, -1e30f, -1e30f };
	for (int i = first; i < first + count; i++)
		for (int k = 0; k < 3; k++) {
			const bvh_box *b = &boxes[index[i]];
			lo[k] = b->min[k] < lo[k] ? b->min[k] : lo[k];
			hi[k] = b->max[k] > hi[k] ? b->max[k] : hi[k];
		}
	n->min_x = lo[0], n->min_y = lo[1], n->min_z = lo[2];
	n->max_x = hi[0], n->max_y = hi[1], n->max_z = hi[2];
}

/* Moves the primitives whose centroid lies below the middle of the longest side
 * to the front of the range; returns how many there are. */
static int split_middle(const bvh_box *boxes, int *index, int first, int count, const bvh_node *n)
{
	float size[3] = { n->max_x - n->min_x, n->max_y - n->min_y, n->max_z - n->min_z };
	float lo[3] = { n->min_x, n->min_y, n->min_z };
	int axis = size[1] > size[0] ? 1 : 0;
	axis = size[2] > size[axis] ? 2 : axis;
	float mid2 = 2 * lo[axis] + size[axis];   /* twice the middle, against centroid sums */
	int i = first, j = first + count - 1;
	while (i <= j) {
		const bvh_box *b = &boxes[index[i]];
		if (b->min[axis] + b->max[axis] < mid2) {
			i++;
		} else {
			int t = index[i];
			index[i] = index[j];
			index[j--] = t;
		}
	}
	return i - first;
}

int bvh_build_median(const bvh_box *boxes, int n, int max_depth, bvh_tree *t)
{
	memset(t, 0, sizeof *t);
	int cap = n > 0 ? 2 * n - 1 : 1;
	t->nodes = calloc(cap, sizeof *t->nodes);
	t->prim_index = malloc((n > 0 ? n : 1) * sizeof *t->prim_index);
	struct task *stack = malloc((max_depth + 2) * sizeof *stack);
	if (!t->nodes || !t->prim_index || !stack) {
		free(stack);
		bvh_free(t);
		return -1;
	}
	for (int i = 0; i < n; i++)
		t->prim_index[i] = i;
	t->n_prims = n;
	t->n_nodes = 1;
	int sp = 0;
	stack[sp++] = (struct task){ 0, 0, n, 1 };
	while (sp > 0) {
		struct task k = stack[--sp];
		bvh_node *node = &t->nodes[k.node];
		range_box(boxes, t->prim_index, k.first, k.count, node);
		t->depth = k.depth > t->depth ? k.depth : t->depth;
		int left = k.count > 2 && k.depth < max_depth
		         ? split_middle(boxes, t->prim_index, k.first, k.count, node) : 0;
		if (left == 0 || left == k.count) {   /* a leaf: deep enough, small, or not cut */
			node->left_first = k.first;
			node->count = k.count;
			continue;
		}
		node->left_first = t->n_nodes;
		node->count = 0;
		t->n_nodes += 2;
		stack[sp++] = (struct task){ node->left_first + 1, k.first + left, k.count - left, k.depth + 1 };
		stack[sp++] = (struct task){ node->left_first, k.first, left, k.depth + 1 };
	}
	free(stack);
	t->sah_cost = n > 0 ? bvh_sah_cost(t->nodes, t->n_nodes) : 0;
	return 0;
}
