/* traverse.cl: closest-hit and any-hit traversal of the binary BVH (bvh_node,
 * shared.h): a stack of node indices, the nearer child first, far nodes pruned
 * against the closest hit so far. The host guarantees the tree is no deeper than
 * BVH_STACK_SIZE, so the stack cannot overflow. */

/* Boxes are tested with a relative slack, so rays through box edges and corners
 * are not lost to rounding (tests/test_bvh.c shows they are without it). */
#define BVH_BOX_PAD (1.0f + 4.0f * FLT_EPSILON)

typedef struct {
	float3 o, inv_d;
	int3 neg;       /* sign bit of each direction component: which slab plane is entered */
} traverse_ray;

inline traverse_ray traverse_setup(float3 o, float3 d)
{
	traverse_ray r;
	r.o = o;
	r.inv_d = 1.0f / d;   /* +-0 gives +-inf */
	r.neg = signbit(d);   /* -1 where the sign bit is set */
	return r;
}

/* Slab test against [0, tmax], with the entry plane chosen by the direction's sign
 * bit. A component of 0 * inf (a ray lying in a slab's plane) is NaN, which fmin
 * and fmax drop, so such a ray counts as inside that slab; the usual
 * fmin(t1, t2) form would turn it into +inf and miss a box the ray touches.
 * Returns the entry distance, or INFINITY when the box is missed. */
inline float traverse_box(global const bvh_node *n, const traverse_ray *r, float tmax)
{
	float3 lo = (float3)(n->min_x, n->min_y, n->min_z), hi = (float3)(n->max_x, n->max_y, n->max_z);
	float3 tn = (select(lo, hi, r->neg) - r->o) * r->inv_d;
	float3 tf = (select(hi, lo, r->neg) - r->o) * r->inv_d;
	float enter = fmax(fmax(fmax(0.0f, tn.x), tn.y), tn.z);
	float leave = fmin(fmin(fmin(tmax, tf.x), tf.y), tf.z);
	return enter <= leave * BVH_BOX_PAD ? enter : INFINITY;
}

typedef struct {
	float t;
	int prim;      /* -1: no hit */
} traverse_hit;

/* The unbounded primitives (planes) after the BVH's n_prims: every ray tests them. */
inline traverse_hit traverse_planes(global const dev_prim *prims, int n_prims, int n_planes,
                                    float3 o, float3 d, float tmin, traverse_hit hit, uint *counts)
{
	for (int i = n_prims; i < n_prims + n_planes; i++) {
		float t = intersect_plane(o, d, &prims[i], tmin, hit.t);
		counts[COUNT_TESTS]++;
		if (t < hit.t) {
			hit.t = t;
			hit.prim = i;
		}
	}
	return hit;
}

/* Closest hit in (tmin, tmax). counts[COUNT_TESTS] adds up box and primitive
 * tests (the heat map's measure). */
inline traverse_hit traverse_closest(global const bvh_node *nodes, global const dev_prim *prims,
                                     int n_prims, int n_planes, float3 o, float3 d, float tmin,
                                     float tmax, uint *counts)
{
	traverse_hit hit = { tmax, -1 };
	hit = traverse_planes(prims, n_prims, n_planes, o, d, tmin, hit, counts);
	if (n_prims == 0)
		return hit;
	traverse_ray r = traverse_setup(o, d);
	int stack[BVH_STACK_SIZE], sp = 0, node = 0;
	uint *tests = &counts[COUNT_TESTS];
	*tests += 1;
	if (traverse_box(&nodes[0], &r, hit.t) == INFINITY)
		return hit;
	for (;;) {
		global const bvh_node *n = &nodes[node];
		if (n->count > 0) {
			for (int i = n->left_first; i < n->left_first + n->count; i++) {
				float t = intersect_prim(o, d, &prims[i], tmin, hit.t);
				*tests += 1;
				if (t < hit.t) {
					hit.t = t;
					hit.prim = i;
				}
			}
		} else {
			int a = n->left_first, b = a + 1;
			float ta = traverse_box(&nodes[a], &r, hit.t);
			float tb = traverse_box(&nodes[b], &r, hit.t);
			*tests += 2;
			if (ta > tb) {
				float tt = ta; ta = tb; tb = tt;
				int ti = a; a = b; b = ti;
			}
			if (ta != INFINITY) {
				if (tb != INFINITY)
					stack[sp++] = b;
				node = a;
				continue;
			}
		}
		/* pop the next node still nearer than the closest hit */
		for (;;) {
			if (sp == 0)
				return hit;
			node = stack[--sp];
			if (traverse_box(&nodes[node], &r, hit.t) != INFINITY)
				break;
		}
	}
}

/* Any hit in (tmin, tmax): shadow rays stop at the first occluder. */
inline bool traverse_any(global const bvh_node *nodes, global const dev_prim *prims, int n_prims,
                         int n_planes, float3 o, float3 d, float tmin, float tmax, uint *counts)
{
	traverse_hit planes = { tmax, -1 };
	if (traverse_planes(prims, n_prims, n_planes, o, d, tmin, planes, counts).prim >= 0)
		return true;
	if (n_prims == 0)
		return false;
	uint *tests = &counts[COUNT_TESTS];
	traverse_ray r = traverse_setup(o, d);
	int stack[BVH_STACK_SIZE], sp = 0;
	stack[sp++] = 0;
	while (sp > 0) {
		global const bvh_node *n = &nodes[stack[--sp]];
		*tests += 1;
		if (traverse_box(n, &r, tmax) == INFINITY)
			continue;
		if (n->count > 0) {
			for (int i = n->left_first; i < n->left_first + n->count; i++) {
				*tests += 1;
				if (intersect_prim(o, d, &prims[i], tmin, tmax) < tmax)
					return true;
			}
		} else {
			stack[sp++] = n->left_first + 1;
			stack[sp++] = n->left_first;
		}
	}
	return false;
}
