/* traverse.cl: closest-hit and any-hit traversal of the BVH, in either layout
 * (eclat(1), --bvh-layout; the host compiles with -DBVH_WIDE=1 for the wide one):
 * binary: bvh_node (shared.h), a stack of node indices, the nearer child first;
 * wide: bvh_wnode, the hit children sorted by entry distance, the nearest taken
 * and the others stacked with their distances.
 * Both prune far nodes against the closest hit so far. The host guarantees that
 * no traversal needs more than BVH_STACK_SIZE entries, so the stack cannot
 * overflow. The node buffer is declared bvh_node everywhere; only this file
 * reads it as the wide layout. */
#ifndef BVH_WIDE
#define BVH_WIDE 0
#endif

/* Boxes are tested with a relative slack, so rays through box edges and corners
 * are not lost to rounding (tests/test_bvh.c shows they are without it). */
#define BVH_BOX_PAD (1.0f + 4.0f * FLT_EPSILON)

typedef struct {
	float3 o, inv_d;
	int3 neg;       /* sign bit of each direction component: which slab plane is entered */
} traverse_ray;

static inline traverse_ray traverse_setup(float3 o, float3 d)
{
	traverse_ray r;
	r.o = o;
	r.inv_d = 1.0f / d;   /* +-0 gives +-inf */
	r.neg = signbit(d);   /* -1 where the sign bit is set */
	return r;
}

/* The larger and the smaller of acc and x, where a NaN x leaves acc: written as
 * a compare and a select on purpose, since fmax and fmin must also handle a NaN
 * acc, which costs an unordered compare and a blend more each (acc never is
 * NaN here: it starts at 0 or tmax). */
#define TRAVERSE_MAX(ACC, X) ((X) > (ACC) ? (X) : (ACC))
#define TRAVERSE_MIN(ACC, X) ((X) < (ACC) ? (X) : (ACC))
#define TRAVERSE_MAX4(ACC, X) select((ACC), (X), (X) > (ACC))
#define TRAVERSE_MIN4(ACC, X) select((ACC), (X), (X) < (ACC))

/* Slab test against [0, tmax], with the entry plane chosen by the direction's sign
 * bit. A component of 0 * inf (a ray lying in a slab's plane) is NaN, which
 * TRAVERSE_MAX and TRAVERSE_MIN drop, so such a ray counts as inside that slab;
 * the usual fmin(t1, t2) form would turn it into +inf and miss a box the ray
 * touches. Returns the entry distance, or INFINITY when the box is missed. */
static inline float traverse_slab(float3 lo, float3 hi, const traverse_ray *r, float tmax)
{
	float3 tn = (select(lo, hi, r->neg) - r->o) * r->inv_d;
	float3 tf = (select(hi, lo, r->neg) - r->o) * r->inv_d;
	float enter = TRAVERSE_MAX(TRAVERSE_MAX(TRAVERSE_MAX(0.0f, tn.x), tn.y), tn.z);
	float leave = TRAVERSE_MIN(TRAVERSE_MIN(TRAVERSE_MIN(tmax, tf.x), tf.y), tf.z);
	return enter <= leave * BVH_BOX_PAD ? enter : INFINITY;
}

static inline float traverse_box(global const bvh_node *n, const traverse_ray *r, float tmax)
{
	return traverse_slab((float3)(n->min_x, n->min_y, n->min_z), (float3)(n->max_x, n->max_y, n->max_z), r, tmax);
}

typedef struct {
	float t;
	int prim;      /* -1: no hit */
	int inst;      /* the instance the primitive was found through, or -1 */
	bool flip;     /* a CSG leaf's surface, the CSG's inside on its outside (csg.cl) */
} traverse_hit;

/* The traversal loop of one BVH from root, written once and made into a function
 * for each level (OpenCL has no recursion, and the top level calls the mesh
 * level). SETUP runs once a ray, before the walk (what every LEAF_PRIM of the ray
 * shares). LEAF_PRIM tests primitive i against the ray (o, d), lowering hit.t and
 * setting hit.prim and hit.inst. With any, the first hit ends the walk. counts
 * adds up the node and primitive tests for the ray's kind (the heat map's measure). */
#if !BVH_WIDE
#define TRAVERSE_FUNCTION(NAME, SETUP, LEAF_PRIM, BLOCKS)                                              \
static inline traverse_hit NAME(const scene_data *sc, global const bvh_node *nodes,               \
                         global const dev_prim *prims, int root,                                 \
                         float3 o, float3 d, float tmin, float tmax, bool any, uint *counts,     \
                         int kind)                                                              \
{                                                                                               \
	traverse_hit hit = { tmax, -1, -1, false };                                                        \
	traverse_ray r = traverse_setup(o, d);                                                      \
	SETUP                                                                                       \
	int stack[BVH_STACK_SIZE], sp = 0, node = root;                                             \
	counts[COUNT_NODES + kind]++;                                                               \
	if (traverse_box(&nodes[root], &r, hit.t) == INFINITY)                                      \
		return hit;                                                                             \
	for (;;) {                                                                                  \
		global const bvh_node *n = &nodes[node];                                                \
		if (n->count > 0) {                                                                     \
			for (int i = n->left_first; i < n->left_first + n->count; i++) {                    \
				counts[COUNT_PRIMS + kind]++;                                                   \
				LEAF_PRIM                                                                       \
				if (any && hit.prim >= 0)                                                       \
					return hit;                                                                 \
			}                                                                                   \
		} else {                                                                                \
			int a = n->left_first, b = a + 1;                                                   \
			float ta = traverse_box(&nodes[a], &r, hit.t);                                      \
			float tb = traverse_box(&nodes[b], &r, hit.t);                                      \
			counts[COUNT_NODES + kind] += 2;                                                    \
			if (ta > tb) {                                                                      \
				float tt = ta; ta = tb; tb = tt;                                                \
				int ti = a; a = b; b = ti;                                                      \
			}                                                                                   \
			if (ta != INFINITY) {                                                               \
				if (tb != INFINITY)                                                             \
					stack[sp++] = b;                                                            \
				node = a;                                                                       \
				continue;                                                                       \
			}                                                                                   \
		}                                                                                       \
		/* pop the next node still nearer than the closest hit */                               \
		for (;;) {                                                                              \
			if (sp == 0)                                                                        \
				return hit;                                                                     \
			node = stack[--sp];                                                                 \
			if (traverse_box(&nodes[node], &r, hit.t) != INFINITY)                              \
				break;                                                                          \
		}                                                                                       \
	}                                                                                           \
}

#else

/* The four bytes of a quantized bound, children 0 to 3, as floats. */
static inline float4 traverse_qdecode(uint q)
{
	return convert_float4((uint4)(q) >> (uint4)(0u, 8u, 16u, 24u) & (uint4)(255u));
}

/* The entry distances of a wide node's children, INFINITY for one missed or
 * absent: the four boxes' slab tests side by side in float4s, which a CPU
 * device runs in its vector unit (one work item still traces one ray). On
 * each axis the direction's sign picks the byte words of the planes entered
 * and left. A plane at origin + q * 2^e is crossed at
 * q * (2^e / d) + (origin - o) / d: one fma a plane after two products an
 * axis (Ylitie, Karras and Laine 2017), 4-6% more rays a second than forming
 * the plane first (issue 18). The rounding is of the same size as the plane's
 * own (BVH_BOX_PAD covers both; tests/test_traverse.c's corners and edges
 * pass); a NaN (q = 0 on an axis the ray does not move along) is dropped as in
 * traverse_slab, which only keeps a box. */
static inline float4 traverse_children(global const bvh_wnode *n, const traverse_ray *r, float tmax)
{
	uint meta = n->meta;
	float sx = as_float((meta & 255u) << 23), sy = as_float(((meta >> 8) & 255u) << 23);
	float sz = as_float(((meta >> 16) & 255u) << 23);
	uint lx = n->qlo_x, hx = n->qhi_x, ly = n->qlo_y, hy = n->qhi_y, lz = n->qlo_z, hz = n->qhi_z;
	float ax = sx * r->inv_d.x, bx = (n->origin_x - r->o.x) * r->inv_d.x;
	float ay = sy * r->inv_d.y, by = (n->origin_y - r->o.y) * r->inv_d.y;
	float az = sz * r->inv_d.z, bz = (n->origin_z - r->o.z) * r->inv_d.z;
	float4 tnx = fma(traverse_qdecode(r->neg.x ? hx : lx), ax, bx);
	float4 tfx = fma(traverse_qdecode(r->neg.x ? lx : hx), ax, bx);
	float4 tny = fma(traverse_qdecode(r->neg.y ? hy : ly), ay, by);
	float4 tfy = fma(traverse_qdecode(r->neg.y ? ly : hy), ay, by);
	float4 tnz = fma(traverse_qdecode(r->neg.z ? hz : lz), az, bz);
	float4 tfz = fma(traverse_qdecode(r->neg.z ? lz : hz), az, bz);
	float4 enter = TRAVERSE_MAX4(TRAVERSE_MAX4(TRAVERSE_MAX4((float4)(0.0f), tnx), tny), tnz);
	float4 leave = TRAVERSE_MIN4(TRAVERSE_MIN4(TRAVERSE_MIN4((float4)(tmax), tfx), tfy), tfz);
	int4 hit = enter <= leave * BVH_BOX_PAD & (int4)(0, 1, 2, 3) < (int4)((int)(meta >> 24));
	return select((float4)(INFINITY), enter, hit);
}

/* One lane of traverse_blocks' answer: its triangle, when it hits nearer
 * than the hit so far (lanes in order and < as the triangles one by one). */
#define TRAVERSE_LANE(OK, T, PRIM)                                                              \
	if ((OK) && (T) < hit.t) {                                                                  \
		hit.t = (T);                                                                            \
		hit.prim = (PRIM);                                                                      \
	}

/* A mesh leaf's triangles, four at a time from their bvh_tri4 blocks: the
 * watertight test of triangle_intersect_ray in float4s, with the same
 * operations in the same order, so each lane's answer is the single test's
 * bit for bit. A block where a live lane has an edge function of exactly 0
 * (a ray through an edge or a corner) is tested one triangle at a time, by
 * triangle_intersect_ray itself, which decides such edges in double. */
static inline traverse_hit traverse_blocks(global const bvh_wnode *nodes, global const dev_prim *prims, int ref,
                                           float3 o, const triangle_ray *r, float tmin, traverse_hit hit, bool any_hit,
                                           uint *counts, int kind)
{
	int count = (ref >> BVH_WIDE_FIRST_BITS) & BVH_WIDE_LEAF_MAX;
	global const bvh_tri4 *blk = (global const bvh_tri4 *)&nodes[ref & ((1 << BVH_WIDE_FIRST_BITS) - 1)];
	float ox = intersect_axis(o, r->kx), oy = intersect_axis(o, r->ky), oz = intersect_axis(o, r->kz);
	float sx = r->sx, sy = r->sy, sz = r->sz;
	counts[COUNT_PRIMS + kind] += count;
	for (int left = count; left > 0; left -= 4, blk++) {
		global const float4 *q = &blk->ax;   /* corner c's axis k: q[3 c + k] */
		float4 az = q[r->kz] - oz, bz = q[3 + r->kz] - oz, cz = q[6 + r->kz] - oz;
		float4 ax = q[r->kx] - ox - sx * az, ay = q[r->ky] - oy - sy * az;
		float4 bx = q[3 + r->kx] - ox - sx * bz, by = q[3 + r->ky] - oy - sy * bz;
		float4 cx = q[6 + r->kx] - ox - sx * cz, cy = q[6 + r->ky] - oy - sy * cz;
		float4 u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
		int4 live = (int4)(0, 1, 2, 3) < (int4)(left);
		int4 id = vload4(0, blk->prim);
		if (any(live & (u == 0.0f | v == 0.0f | w == 0.0f))) {
			for (int k = 0; k < 4 && k < left; k++) {
				int i = blk->prim[k];
				float t = triangle_intersect_ray(o, r, &prims[i], tmin, hit.t);
				TRAVERSE_LANE(true, t, i)   /* a miss gives hit.t itself */
			}
		} else {
			int4 out = (u < 0.0f | v < 0.0f | w < 0.0f) & (u > 0.0f | v > 0.0f | w > 0.0f);
			float4 det = u + v + w;
			float4 t = (u * sz * az + v * sz * bz + w * sz * cz) / det;
			int4 ok = live & ~out & det != 0.0f & t > tmin;
			TRAVERSE_LANE(ok.x, t.x, id.x)
			TRAVERSE_LANE(ok.y, t.y, id.y)
			TRAVERSE_LANE(ok.z, t.z, id.z)
			TRAVERSE_LANE(ok.w, t.w, id.w)
		}
		if (any_hit && hit.prim >= 0)
			return hit;
	}
	return hit;
}

/* Orders two (distance, child) pairs, nearer first. */
#define TRAVERSE_ORDER(TA, CA, TB, CB)                                                          \
	if (TB < TA) {                                                                              \
		float tt_ = TA; TA = TB; TB = tt_;                                                      \
		int tc_ = CA; CA = CB; CB = tc_;                                                        \
	}

/* The wide layout's loop, with the same contract as the binary one. A reference
 * ref >= 0 is a wide node, < 0 a leaf (shared.h). The four children's entry
 * distances are sorted by a network of five exchanges (no private arrays, which
 * PoCL keeps in memory): the nearest is taken at once, the others hit are
 * stacked farthest first, the next nearest on top. An any-hit walk (shadow
 * rays) only brings the nearest forward, in three: 4-6% more shadow rays a
 * second in make bench's traversal-only measurement. */
#define TRAVERSE_FUNCTION(NAME, SETUP, LEAF_PRIM, BLOCKS)                                        \
static inline traverse_hit NAME(const scene_data *sc, global const bvh_node *nodes_,              \
                         global const dev_prim *prims, int root,                                 \
                         float3 o, float3 d, float tmin, float tmax, bool any, uint *counts,     \
                         int kind)                                                              \
{                                                                                               \
	global const bvh_wnode *nodes = (global const bvh_wnode *)nodes_;                           \
	traverse_hit hit = { tmax, -1, -1, false };                                                        \
	traverse_ray r = traverse_setup(o, d);                                                      \
	SETUP                                                                                       \
	int stack[BVH_STACK_SIZE], sp = 0, ref = root;                                              \
	float tstack[BVH_STACK_SIZE];                                                               \
	for (;;) {                                                                                  \
		if (ref < 0 && BLOCKS) {                                                                \
			hit = traverse_blocks(nodes, prims, ref, o, &tri, tmin, hit, any, counts, kind);    \
			if (any && hit.prim >= 0)                                                           \
				return hit;                                                                     \
		} else if (ref < 0) {                                                                   \
			int first = ref & ((1 << BVH_WIDE_FIRST_BITS) - 1);                                 \
			int end = first + ((ref >> BVH_WIDE_FIRST_BITS) & BVH_WIDE_LEAF_MAX);               \
			for (int i = first; i < end; i++) {                                                 \
				counts[COUNT_PRIMS + kind]++;                                                   \
				LEAF_PRIM                                                                       \
				if (any && hit.prim >= 0)                                                       \
					return hit;                                                                 \
			}                                                                                   \
		} else {                                                                                \
			global const bvh_wnode *n = &nodes[ref];                                            \
			counts[COUNT_NODES + kind] += (int)(n->meta >> 24);                                 \
			float4 t = traverse_children(n, &r, hit.t);                                         \
			float t0 = t.x, t1 = t.y, t2 = t.z, t3 = t.w;                                       \
			int c0 = n->child[0], c1 = n->child[1], c2 = n->child[2], c3 = n->child[3];         \
			if (!any) {                                                                         \
				TRAVERSE_ORDER(t0, c0, t1, c1);                                                 \
				TRAVERSE_ORDER(t2, c2, t3, c3);                                                 \
				TRAVERSE_ORDER(t0, c0, t2, c2);                                                 \
				TRAVERSE_ORDER(t1, c1, t3, c3);                                                 \
				TRAVERSE_ORDER(t1, c1, t2, c2);                                                 \
			} else {   /* any hit ends the walk: only the nearest need go first */                 \
				TRAVERSE_ORDER(t0, c0, t1, c1);                                                 \
				TRAVERSE_ORDER(t0, c0, t2, c2);                                                 \
				TRAVERSE_ORDER(t0, c0, t3, c3);                                                 \
			}                                                                                   \
			if (t0 != INFINITY) {                                                               \
				if (t3 != INFINITY) {                                                           \
					stack[sp] = c3;                                                             \
					tstack[sp++] = t3;                                                          \
				}                                                                               \
				if (t2 != INFINITY) {                                                           \
					stack[sp] = c2;                                                             \
					tstack[sp++] = t2;                                                          \
				}                                                                               \
				if (t1 != INFINITY) {                                                           \
					stack[sp] = c1;                                                             \
					tstack[sp++] = t1;                                                          \
				}                                                                               \
				ref = c0;                                                                       \
				continue;                                                                       \
			}                                                                                   \
		}                                                                                       \
		/* pop the next child still nearer than the closest hit */                              \
		for (;;) {                                                                              \
			if (sp == 0)                                                                        \
				return hit;                                                                     \
			sp--;                                                                               \
			if (tstack[sp] <= hit.t * BVH_BOX_PAD) {                                            \
				ref = stack[sp];                                                                \
				break;                                                                          \
			}                                                                                   \
		}                                                                                       \
	}                                                                                           \
}

#endif

/* A mesh's BVH, in the mesh's space: its primitives are triangles. */
TRAVERSE_FUNCTION(traverse_mesh, triangle_ray tri = triangle_setup(d);, {
	float t = triangle_intersect_ray(o, &tri, &prims[i], tmin, hit.t);
	if (t < hit.t) {
		hit.t = t;
		hit.prim = i;
	}
}, BVH_WIDE)

/* Instance i (a placed mesh) against the ray, lowering hit: the ray is taken
 * into its mesh's space, where the direction is not unit length, so t means
 * the same distance in both spaces. */
static inline traverse_hit traverse_instance(const scene_data *sc, global const bvh_node *nodes,
                                             global const dev_prim *prims, int i, float3 o, float3 d, float tmin,
                                             traverse_hit hit, bool any, uint *counts, int kind)
{
	global const dev_prim *q = &prims[i];
	float3 mo = intersect_to_local(q, o);
	float3 md = (float3)(dot(q->a.xyz, d), dot(q->b.xyz, d), dot(q->c.xyz, d));
	traverse_hit h = traverse_mesh(sc, nodes, prims, q->link, mo, md, tmin, hit.t, any, counts, kind);
	if (h.prim >= 0) {
		hit.t = h.t;
		hit.prim = h.prim;
		hit.inst = i;
		hit.flip = false;
	}
	return hit;
}

/* The top level: the scene's primitives in world space and its instances. */
TRAVERSE_FUNCTION(traverse_top, triangle_ray tri = triangle_setup(d);, {
	global const dev_prim *q = &prims[i];
	if (q->type == PRIM_INSTANCE) {
		/* the node buffer's declared type again (the wide layout's loop reads it as bvh_wnode) */
		hit = traverse_instance(sc, (global const bvh_node *)nodes, prims, i, o, d, tmin, hit, any, counts, kind);
	} else if (q->type == PRIM_CSG) {
		int leaf;   /* one name a line: commas would split the macro's argument */
		int leaf_inst;
		bool flip;
		float t = csg_intersect(sc, o, d, (global const bvh_node *)nodes, prims, q, tmin, hit.t, &leaf, &leaf_inst,
		                        &flip, counts, kind);
		if (t < hit.t) {
			hit.t = t;
			hit.prim = leaf;
			hit.inst = leaf_inst;
			hit.flip = flip;
		}
	} else {
		/* triangles, the most common, without the shapes' dispatch and with the
		 * ray's part of their test made once */
		float t = q->type == PRIM_TRIANGLE || q->type == PRIM_SMOOTH_TRIANGLE
		        ? triangle_intersect_ray(o, &tri, q, tmin, hit.t)
		        : shape_intersect(sc, o, d, prims, q, tmin, hit.t);
		if (t < hit.t) {
			hit.t = t;
			hit.prim = i;
			hit.inst = -1;
			hit.flip = false;
		}
	}
}, 0)

/* The unbounded primitives (planes, quadrics, and CSG objects with no bounds) after the
 * top level's n_prims: every ray tests them. */
static inline traverse_hit traverse_planes(const scene_data *sc, global const bvh_node *nodes,
                                           global const dev_prim *prims, int n_prims, int n_planes, float3 o, float3 d, float tmin, traverse_hit hit,
                                           uint *counts, int kind)
{
	for (int i = n_prims; i < n_prims + n_planes; i++) {
		counts[COUNT_PRIMS + kind]++;
		if (prims[i].type == PRIM_CSG) {
			int leaf, leaf_inst;
			bool flip;
			float t = csg_intersect(sc, o, d, nodes, prims, &prims[i], tmin, hit.t, &leaf, &leaf_inst, &flip, counts,
			                        kind);
			if (t < hit.t) {
				hit.t = t;
				hit.prim = leaf;
				hit.inst = leaf_inst;
				hit.flip = flip;
			}
			continue;
		}
		float t = shape_intersect(sc, o, d, prims, &prims[i], tmin, hit.t);
		if (t < hit.t) {
			hit.t = t;
			hit.prim = i;
			hit.inst = -1;
			hit.flip = false;
		}
	}
	return hit;
}

/* The top level's n_prims primitives against the ray, in (tmin, tmax); with
 * any, the first hit ends the walk. A top level of one mesh alone is not
 * walked: the ray goes to the instance at once. */
static inline traverse_hit traverse_objects(const scene_data *sc, global const bvh_node *nodes,
                                            global const dev_prim *prims, int n_prims, float3 o, float3 d,
                                            float tmin, float tmax, bool any, uint *counts, int kind)
{
	traverse_hit none = { tmax, -1, -1, false };
	if (n_prims == 1 && prims[0].type == PRIM_INSTANCE)
		return traverse_instance(sc, nodes, prims, 0, o, d, tmin, none, any, counts, kind);
	return n_prims > 0 ? traverse_top(sc, nodes, prims, 0, o, d, tmin, tmax, any, counts, kind) : none;
}

/* Closest hit in (tmin, tmax). sc: the scene's buffers, which an isosurface's
 * function may read, or 0 (raycast.cl's test kernels). */
static inline traverse_hit traverse_closest(const scene_data *sc, global const bvh_node *nodes,
                                            global const dev_prim *prims,
                                     int n_prims, int n_planes, float3 o, float3 d, float tmin,
                                     float tmax, uint *counts, int kind)
{
	traverse_hit hit = traverse_objects(sc, nodes, prims, n_prims, o, d, tmin, tmax, false, counts, kind);
	return traverse_planes(sc, nodes, prims, n_prims, n_planes, o, d, tmin, hit, counts, kind);
}

/* Any hit in (tmin, tmax): shadow rays stop at the first occluder. */
static inline bool traverse_any(const scene_data *sc, global const bvh_node *nodes, global const dev_prim *prims,
                                int n_prims,
                         int n_planes, float3 o, float3 d, float tmin, float tmax, uint *counts)
{
	traverse_hit none = { tmax, -1, -1, false };
	if (traverse_planes(sc, nodes, prims, n_prims, n_planes, o, d, tmin, none, counts, RAY_SHADOW).prim >= 0)
		return true;
	return traverse_objects(sc, nodes, prims, n_prims, o, d, tmin, tmax, true, counts, RAY_SHADOW).prim >= 0;
}
