/* csg.cl: CSG objects (POV-Ray's union, merge, intersection, difference and
 * inverse, to any depth). A CSG object is one primitive of the BVH; its leaves
 * are the shapes it is made of, in world space, and its program (shared.h,
 * CSG_) says how their insides combine. A ray meets the leaves' surfaces one
 * after another; a leaf's surface point is on the CSG's surface when the
 * program gives different answers with the point just inside the leaf and just
 * outside it, the other leaves answering their inside tests. A union keeps its
 * parts' inner surfaces (POV-Ray returns all of a union's hits): where the leaf
 * is under a union, the union answers as the leaf's own part does. */

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

/* Whether the ray meets box b between t0 and t1 (inv: 1 / its direction). A
 * NaN from a zero component on the box's face (0 * inf) leaves that slab
 * out, fmin and fmax taking the other operand: the answer errs toward yes. */
static inline bool csg_box_meets(global const dev_prim *b, float3 o, float3 inv, float t0, float t1)
{
	float3 l = (b->a.xyz - o) * inv, h = (b->b.xyz - o) * inv;
	float3 n = fmin(l, h), f = fmax(l, h);
	return fmax(fmax(n.x, n.y), fmax(n.z, t0)) <= fmin(fmin(f.x, f.y), fmin(f.z, t1));
}

/* Whether x is inside the leaf q, whose box record is b: never outside b
 * when the leaf's inside lies within it, which spares a CSG of many leaves
 * most of their inside tests. */
static inline bool csg_leaf_inside(const scene_data *sc, global const bvh_node *nodes, global const dev_prim *prims,
                                   global const dev_prim *q, global const dev_prim *b, float3 x, uint *counts,
                                   int kind)
{
	if (b->a.w != 0.0f && (any(x < b->a.xyz) || any(x > b->b.xyz)))
		return false;
	if (q->type == PRIM_CSG_MESH)
		return csg_mesh_inside(nodes, prims, q, x, counts, kind);
	return shape_inside(sc, prims, q, x);
}

/* Whether the point x of leaf k's surface is on the CSG's surface; *flip when
 * the CSG's inside is on the leaf's outside there. The stacks are bits, the
 * top in bit 0: v1 with the point inside leaf k, v0 with it outside, has for
 * the entries that hold leaf k. */
static inline bool csg_classify(const scene_data *sc, global const bvh_node *nodes, global const dev_prim *prims,
                                global const dev_prim *csg,
                                int k, float3 x, bool *flip, uint *counts, int kind)
{
	int first = as_int(csg->a.x), n = as_int(csg->a.y), n_ops = as_int(csg->a.w);
	global const dev_prim *prog = &prims[as_int(csg->a.z)];
	uint v1 = 0, v0 = 0, has = 0;
	for (int i = 0; i < n_ops; i++) {
		int code = ((global const int *)&prog[i / CSG_OPS_PER_RECORD])[i % CSG_OPS_PER_RECORD];
		int op = code >> CSG_OP_SHIFT, arg = code & ((1 << CSG_OP_SHIFT) - 1);
		if (op == CSG_LEAF) {
			uint in = arg == k ? 1u : 0u;
			if (arg != k && arg < n)
				in = (uint)csg_leaf_inside(sc, nodes, prims, &prims[first + arg], csg_box(prims, csg, arg), x, counts,
				                           kind);
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

/* The nearest point of the CSG's surface in (tmin, tmax), or tmax; *prim is the
 * leaf's primitive there, or a mesh leaf's triangle with *inst the leaf (else
 * -1), as traverse_hit has them. */
static inline float csg_intersect(const scene_data *sc, float3 o, float3 d, global const bvh_node *nodes,
                                  global const dev_prim *prims,
                                  global const dev_prim *csg, float tmin, float tmax, int *prim, int *inst, bool *flip,
                                  uint *counts, int kind)
{
	int first = as_int(csg->a.x), n = csg->link;   /* the leaves after these are clipped_by's */
	float3 inv = 1.0f / d;
	float t = tmin;
	for (int c = 0; c < CSG_CROSSINGS; c++) {
		float best = tmax;
		int which = -1, tri = -1;
		for (int k = 0; k < n; k++) {
			global const dev_prim *q = &prims[first + k];
			if (!csg_box_meets(csg_box(prims, csg, k), o, inv, t, best))
				continue;   /* its hits lie in its box */
			int tk_tri = -1;
			float tk = q->type == PRIM_CSG_MESH
			         ? csg_mesh_intersect(nodes, prims, q, o, d, tmin, t, best, &tk_tri, counts, kind)
			         : shape_intersect(sc, o, d, prims, q, t, best);
			if (tk < best) {
				best = tk;
				which = k;
				tri = tk_tri;
			}
		}
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
