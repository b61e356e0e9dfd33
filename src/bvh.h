/* bvh.h: bounding volume hierarchy over primitive boxes, built on the host.
 *
 *   bvh_box boxes[n] = ...;            one box per primitive
 *   bvh_tree t;
 *   if (bvh_build(boxes, n, &t) != 0) ...   out of memory
 *   t.nodes[0] is the root; a leaf covers t.prim_index[left_first .. +count-1],
 *   which are indices into boxes[]. The caller reorders its primitives by
 *   prim_index so that a leaf's primitives are contiguous on the device.
 *   bvh_free(&t);
 *
 * The tree is binary with node layout bvh_node (kernels/shared.h), children
 * adjacent, so it can be converted to wider layouts later. */
#ifndef ECLAT_BVH_H
#define ECLAT_BVH_H

#include <stddef.h>

#include "../kernels/shared.h"

typedef struct {
	float min[3], max[3];
} bvh_box;

typedef struct {
	bvh_node *nodes;
	int n_nodes;
	int *prim_index;
	int n_prims;
	int depth;          /* longest root-to-leaf path, root = 1 */
	double sah_cost;    /* SAH cost with C_node = 1, C_prim = 1, relative to the root area */
} bvh_tree;

/* Binned SAH build (16 bins per axis, 8 under 64 primitives, exact SAH for
 * small nodes, leaves of at most BVH_MAX_LEAF primitives).
 * n may be 0 (one empty leaf). Boxes may be flat (zero extent on an axis).
 * Returns 0, or -1 when memory runs out (t is then left empty). */
#define BVH_MAX_LEAF 4
int bvh_build(const bvh_box *boxes, int n, bvh_tree *t);
/* The same on at most threads threads (0: one per online processor). The tree
 * does not depend on threads. */
int bvh_build_threads(const bvh_box *boxes, int n, int threads, bvh_tree *t);
/* The same, with primitive i's box from box_of(ctx, i, &box), called once for
 * each i, from two threads at once for large n (so it must not change shared
 * state): the builder writes the boxes straight into its own records, and the
 * caller needs no array of them (fresh memory costs a page fault every 4 KiB,
 * which is not cheap on a virtual machine). */
typedef void bvh_box_fn(const void *ctx, int i, bvh_box *out);
int bvh_build_fn(bvh_box_fn *box_of, const void *ctx, int n, bvh_tree *t);
/* The same, with every range of at most leaf_whole (1 .. BVH_MAX_LEAF)
 * primitives made a leaf without trying a split. The wide layout makes any
 * mesh subtree of at most BVH_WIDE_BLOCK triangles one block (bvh_tri4), so
 * for its meshes the splits below that would only order a block's triangles,
 * at a sixth of the build's time (dragon, one thread: 27.8 -> 23.2 ms).
 * Returns -1 (t empty) for leaf_whole out of range too. */
int bvh_build_leaves(bvh_box_fn *box_of, const void *ctx, int n, int leaf_whole, bvh_tree *t);

/* The reference paper's builder, for comparison (--bvh median): a node's box is
 * cut in two at the middle of its longest side, the primitives going to the side
 * of their centroid, down to max_depth (root = 1) or until a node holds at most
 * two primitives or cannot be cut. Leaves may hold many primitives. */
int bvh_build_median(const bvh_box *boxes, int n, int max_depth, bvh_tree *t);

/* The triangles of one bvh_tri4 block (kernels/shared.h): bvh_widen makes
 * each mesh subtree of at most this many one block, which is why the
 * lowering builds meshes for the wide layout with bvh_build_leaves to it. */
#define BVH_WIDE_BLOCK 4
_Static_assert(BVH_WIDE_BLOCK <= BVH_MAX_LEAF, "a block is built as one leaf");

/* The 4-wide layout (bvh_wnode, kernels/shared.h), converted from binary
 * trees in one node array (src/bvh_wide.c). roots: binary node indices of the
 * trees' roots, each converted with everything below it; a root of -1 gives
 * an empty node (no children), for an empty tree. With tris, the primitives,
 * the roots from first_mesh on are meshes' trees, all triangles, whose leaves
 * become bvh_tri4 blocks (kernels/shared.h); with NULL no tree's do.
 * Returns 0, or -1 when memory runs out, a box is not finite or a primitive
 * index needs more than BVH_WIDE_FIRST_BITS bits (out is then left empty). */
typedef struct {
	bvh_wnode *nodes;
	int n_nodes;        /* node slots, the blocks' included */
	int n_blocks;       /* bvh_tri4 blocks among them, BVH_TRI4_SLOTS slots each */
	int *roots;         /* the wide node of each root given */
	int max_stack;      /* the most stack entries a traversal of any of the trees can need */
} bvh_wide;

int bvh_widen(const bvh_node *nodes, const int *roots, int n_roots, const dev_prim *tris, int first_mesh,
              bvh_wide *out);
void bvh_wide_free(bvh_wide *w);

/* A new array of n elements of size bytes, out[i] = elems[index[i]] (a tree's
 * prim_index puts primitives in leaf order), copied on up to two threads.
 * Returns it (free() it), or NULL when memory runs out. */
void *bvh_gather(const void *elems, size_t size, const int *index, int n);

/* The SAH cost of a tree, as in bvh_tree.sah_cost. */
double bvh_sah_cost(const bvh_node *nodes, int n_nodes);
void bvh_free(bvh_tree *t);

#endif
