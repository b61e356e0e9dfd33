/* csg.cl: CSG objects (POV-Ray's union, merge, intersection, difference and
 * inverse, to any depth). A CSG object is one primitive of the BVH; its leaves
 * are the shapes it is made of, in world space, and its program (shared.h,
 * CSG_) says how their insides combine. A ray meets the leaves' surfaces one
 * after another; a leaf's surface point is on the CSG's surface when the
 * program gives different answers with the point just inside the leaf and just
 * outside it, the other leaves answering their inside tests. A union keeps its
 * parts' inner surfaces (POV-Ray returns all of a union's hits): where the leaf
 * is under a union, the union answers as the leaf's own part does. A tree
 * over the leaves' boxes (src/lower_csg_tree.c) gives each crossing the
 * leaves whose boxes the ray meets, and each classification those whose
 * boxes hold the point, so that neither touches every leaf. */

#define CSG_CROSSINGS 256   /* leaf surfaces a ray may cross in one CSG object, at most */

/* A mesh leaf's (PRIM_CSG_MESH), in kernels/csg_mesh.cl after the traversal it
 * uses: its hit past t (with no inside, only its nearest past start), the
 * triangle in *tri; and whether x is inside it. */
static float csg_mesh_intersect(global const bvh_node *nodes, global const dev_prim *prims,
                                global const dev_prim *leaf, float3 o, float3 d, float start, float t, float tmax,
                                int *tri, uint *counts, int kind);
static bool csg_mesh_inside(global const bvh_node *nodes, global const dev_prim *prims, global const dev_prim *leaf,
                            float3 x, uint *counts, int kind);

/* Leaf k's box record (lowering's csg_leaf_box): a.xyz and b.xyz its corners,
 * a.w 1 when the leaf's inside lies within it. Its hits always do. */
static inline global const dev_prim *csg_box(global const dev_prim *prims, global const dev_prim *csg, int k)
{
	return &prims[as_int(csg->b.x) + k];
}

/* The box of a reference in the CSG's leaf tree (shared.h): a node's record,
 * or leaf ~ref's box record. */
static inline global const dev_prim *csg_tree_box(global const dev_prim *prims, global const dev_prim *csg, int ref)
{
	return ref >= 0 ? &prims[as_int(csg->b.y) + ref] : csg_box(prims, csg, ~ref);
}

/* Entry i of the tree's list of leaves, which its runs index. */
static inline int csg_tree_leaf(global const dev_prim *prims, global const dev_prim *csg, int i)
{
	return ((global const int *)&prims[as_int(csg->b.w) + i / CSG_OPS_PER_RECORD])[i % CSG_OPS_PER_RECORD];
}

/* Where the ray enters box b between t0 and t1 (inv: 1 / its direction), or
 * INFINITY when it misses it. A NaN from a zero component on the box's face
 * (0 * inf) leaves that slab out, fmin and fmax taking the other operand. A
 * node's box holds its children's, and the same sums with the larger box
 * cannot give a later entry or an earlier exit: a ray that meets a leaf's box
 * meets every box above it. */
static inline float csg_box_entry(global const dev_prim *b, float3 o, float3 inv, float t0, float t1)
{
	float3 l = (b->a.xyz - o) * inv, h = (b->b.xyz - o) * inv;
	float3 n = fmin(l, h), f = fmax(l, h);
	float enter = fmax(fmax(n.x, n.y), fmax(n.z, t0));
	return enter <= fmin(fmin(f.x, f.y), fmin(f.z, t1)) ? enter : INFINITY;
}

static inline bool csg_box_holds(global const dev_prim *b, float3 x)
{
	return !(any(x < b->a.xyz) || any(x > b->b.xyz));
}

/* Whether x is inside the leaf q, whose box record is b: never outside b
 * when the leaf's inside lies within it. */
static inline bool csg_leaf_inside(const scene_data *sc, global const bvh_node *nodes, global const dev_prim *prims,
                                   global const dev_prim *q, global const dev_prim *b, float3 x, uint *counts,
                                   int kind)
{
	if (b->a.w != 0.0f && !csg_box_holds(b, x))
		return false;
	if (q->type == PRIM_CSG_MESH)
		return csg_mesh_inside(nodes, prims, q, x, counts, kind);
	return shape_inside(sc, prims, q, x);
}

/* The leaves rays may meet whose boxes may hold x, through the leaf tree:
 * bit k % 64 for leaf k, set for each leaf whose box holds x and for every
 * leaf of a run whose box does (which answers its own box test again in
 * csg_leaf_inside), so that a leaf whose bit is clear is outside its box. */
static inline ulong csg_near(global const dev_prim *prims, global const dev_prim *csg, float3 x)
{
	int stack[CSG_TREE_STACK], sp = 0;
	ulong near = 0;
	stack[sp++] = as_int(csg->b.z);
	while (sp > 0) {
		int ref = stack[--sp];
		if (!csg_box_holds(csg_tree_box(prims, csg, ref), x))
			continue;
		if (ref < 0) {
			near |= 1ul << (~ref & 63);
			continue;
		}
		global const dev_prim *node = &prims[as_int(csg->b.y) + ref];
		int from = as_int(node->c.z), count = as_int(node->c.w);
		for (int i = from; i < from + count; i++)
			near |= 1ul << (csg_tree_leaf(prims, csg, i) & 63);
		if (count == 0) {
			stack[sp++] = as_int(node->c.y);
			stack[sp++] = as_int(node->c.x);
		}
	}
	return near;
}

/* Whether x is inside leaf arg of the CSG's program (not leaf k), near from
 * csg_near. A leaf rays may meet whose inside lies within its box (boxed)
 * and whose bit is clear is outside, and neither its box record nor its shape
 * is read. */
static inline bool csg_op_inside(const scene_data *sc, global const bvh_node *nodes, global const dev_prim *prims,
                                 global const dev_prim *csg, int arg, bool boxed, ulong near, float3 x, uint *counts,
                                 int kind)
{
	if (arg >= as_int(csg->a.y))   /* CSG_NO_LEAF */
		return false;
	if (boxed && arg < csg->link && ((near >> (arg & 63)) & 1ul) == 0)
		return false;
	return csg_leaf_inside(sc, nodes, prims, &prims[as_int(csg->a.x) + arg], csg_box(prims, csg, arg), x, counts,
	                       kind);
}

/* The program's int i. */
static inline int csg_program_int(global const dev_prim *prog, int i)
{
	return ((global const int *)&prog[i / CSG_OPS_PER_RECORD])[i % CSG_OPS_PER_RECORD];
}

/* Whether the point x of leaf k's surface is on the CSG's surface; *flip when
 * the CSG's inside is on the leaf's outside there. The stacks are bits, the
 * top in bit 0: v1 with the point inside leaf k, v0 with it outside, has for
 * the entries that hold leaf k. The leaves whose boxes hold x come from the
 * leaf tree, and only they (and those whose inside their box does not bound,
 * and clipped_by's) are asked; a part of the program that holds none of them
 * nor leaf k is skipped where lowering put a CSG_SKIP before it. */
static inline bool csg_classify(const scene_data *sc, global const bvh_node *nodes, global const dev_prim *prims,
                                global const dev_prim *csg,
                                int k, float3 x, bool *flip, uint *counts, int kind)
{
	int n_ops = as_int(csg->a.w);
	ulong near = as_int(csg->b.z) == CSG_NO_TREE ? ~0ul : csg_near(prims, csg, x);
	global const dev_prim *prog = &prims[as_int(csg->a.z)];
	uint v1 = 0, v0 = 0, has = 0;
	for (int i = 0; i < n_ops; i++) {
		int code = csg_program_int(prog, i);
		int op = code >> CSG_OP_SHIFT, arg = code & ((1 << CSG_OP_SHIFT) - 1);
		if (op == CSG_LEAF || op == CSG_LEAF_BOXED) {
			uint in = arg == k ? 1u : 0u;
			if (arg != k)
				in = (uint)csg_op_inside(sc, nodes, prims, csg, arg, op == CSG_LEAF_BOXED, near, x, counts, kind);
			v1 = v1 << 1 | in;
			v0 = v0 << 1 | (arg == k ? 0u : in);
			has = has << 1 | (arg == k ? 1u : 0u);
			continue;
		}
		if (op == CSG_NOT) {
			v1 ^= 1u;
			v0 ^= 1u;
			continue;
		}
		if (op == CSG_SKIP) {   /* its mask in the next two ints */
			uint lo = (uint)csg_program_int(prog, i + 1), hi = (uint)csg_program_int(prog, i + 2);
			i += 2;
			if (((near | 1ul << (k & 63)) & ((ulong)hi << 32 | lo)) != 0ul)
				continue;   /* the part may hold leaf k or one whose box holds x: read it */
			i += arg >> 1;
			v1 = v1 << 1 | (uint)(arg & 1);
			v0 = v0 << 1 | (uint)(arg & 1);
			has <<= 1;
			continue;
		}
		uint mask = (1u << arg) - 1u;   /* the top arg entries (arg < 32, lowering says) */
		uint a1 = v1 & mask, a0 = v0 & mask, h = has & mask, r1, r0;
		if (op == CSG_AND) {
			r1 = a1 == mask;
			r0 = a0 == mask;
		} else if (op == CSG_UNION && h) {
			r1 = (a1 & h) != 0u;
			r0 = (a0 & h) != 0u;
		} else {
			r1 = a1 != 0u;
			r0 = a0 != 0u;
		}
		v1 = (v1 >> arg) << 1 | r1;
		v0 = (v0 >> arg) << 1 | r0;
		has = (has >> arg) << 1 | (h != 0u);
	}
	*flip = (v1 & 1u) == 0u;
	return ((v1 ^ v0) & 1u) != 0u;
}

/* Leaf k's hit past t, when it is nearer than *best (of hits at the same t,
 * the first leaf's is kept, as a loop over the leaves in order would keep it:
 * a leaf before *which is asked for hits up to the float after *best, which
 * is positive and finite then, so that the float after it is its bits plus
 * one). */
static inline void csg_leaf_hit(const scene_data *sc, float3 o, float3 d, global const bvh_node *nodes,
                                global const dev_prim *prims, global const dev_prim *csg, int k, float tmin, float t,
                                float *best, int *which, int *tri, uint *counts, int kind)
{
	global const dev_prim *q = &prims[as_int(csg->a.x) + k];
	float hi = k < *which ? as_float(as_int(*best) + 1) : *best;
	int tk_tri = -1;
	float tk = q->type == PRIM_CSG_MESH ? csg_mesh_intersect(nodes, prims, q, o, d, tmin, t, hi, &tk_tri, counts, kind)
	                                   : shape_intersect(sc, o, d, prims, q, t, hi);
	if (tk < hi) {
		*best = tk;
		*which = k;
		*tri = tk_tri;
	}
}

/* The nearest hit past t of the leaves rays may meet, through the leaf tree:
 * only the leaves whose boxes the ray meets before the nearest hit so far are
 * tested, the nearer child first. Returns the leaf, or -1 (then *best is
 * still tmax), its hit in *best and a mesh leaf's triangle in *tri. */
static inline int csg_nearest(const scene_data *sc, float3 o, float3 d, float3 inv, global const bvh_node *nodes,
                              global const dev_prim *prims, global const dev_prim *csg, float tmin, float t,
                              float *best, int *tri, uint *counts, int kind)
{
	int which = -1, stack[CSG_TREE_STACK], sp = 0;
	float enter[CSG_TREE_STACK];
	int root = as_int(csg->b.z);
	if (root == CSG_NO_TREE) {   /* few leaves, or overlapping ones: each in turn */
		for (int k = 0; k < csg->link; k++)
			if (csg_box_entry(csg_box(prims, csg, k), o, inv, t, *best) < INFINITY)
				csg_leaf_hit(sc, o, d, nodes, prims, csg, k, tmin, t, best, &which, tri, counts, kind);
		return which;
	}
	float e = csg_box_entry(csg_tree_box(prims, csg, root), o, inv, t, *best);
	if (e < INFINITY) {
		stack[0] = root;
		enter[0] = e;
		sp = 1;
	}
	while (sp > 0) {
		sp--;
		int ref = stack[sp];
		if (enter[sp] > *best)
			continue;   /* it lies past the nearest hit found since it was stacked */
		if (ref < 0) {
			csg_leaf_hit(sc, o, d, nodes, prims, csg, ~ref, tmin, t, best, &which, tri, counts, kind);
			continue;
		}
		global const dev_prim *node = &prims[as_int(csg->b.y) + ref];
		int from = as_int(node->c.z), count = as_int(node->c.w);
		for (int i = from; i < from + count; i++) {
			int k = csg_tree_leaf(prims, csg, i);
			if (csg_box_entry(csg_box(prims, csg, k), o, inv, t, *best) < INFINITY)
				csg_leaf_hit(sc, o, d, nodes, prims, csg, k, tmin, t, best, &which, tri, counts, kind);
		}
		if (count != 0)
			continue;
		int a = as_int(node->c.x), b = as_int(node->c.y);
		float ea = csg_box_entry(csg_tree_box(prims, csg, a), o, inv, t, *best);
		float eb = csg_box_entry(csg_tree_box(prims, csg, b), o, inv, t, *best);
		if (ea < eb) {   /* the farther first, so that the nearer is taken next */
			int r = a;
			float er = ea;
			a = b, ea = eb;
			b = r, eb = er;
		}
		if (ea < INFINITY) {
			stack[sp] = a;
			enter[sp++] = ea;
		}
		if (eb < INFINITY) {
			stack[sp] = b;
			enter[sp++] = eb;
		}
	}
	return which;
}

/* The nearest point of the CSG's surface in (tmin, tmax), or tmax; *prim is the
 * leaf's primitive there, or a mesh leaf's triangle with *inst the leaf (else
 * -1), as traverse_hit has them. A ray meets the leaves' surfaces one after
 * another, each found through the leaf tree, until the program keeps one. */
static inline float csg_intersect(const scene_data *sc, float3 o, float3 d, global const bvh_node *nodes,
                                  global const dev_prim *prims,
                                  global const dev_prim *csg, float tmin, float tmax, int *prim, int *inst, bool *flip,
                                  uint *counts, int kind)
{
	int first = as_int(csg->a.x);
	if (csg->link == 0)
		return tmax;   /* only clipped_by's leaves, which rays never meet */
	float3 inv = 1.0f / d;
	float t = tmin;
	for (int c = 0; c < CSG_CROSSINGS; c++) {
		float best = tmax;
		int tri = -1;
		int which = csg_nearest(sc, o, d, inv, nodes, prims, csg, tmin, t, &best, &tri, counts, kind);
		if (which < 0)
			return tmax;
		if (csg_classify(sc, nodes, prims, csg, which, o + best * d, flip, counts, kind)) {
			*prim = tri >= 0 ? tri : first + which;
			*inst = tri >= 0 ? first + which : -1;
			return best;
		}
		t = best;
	}
	return tmax;
}
